#pragma once
// Lookups in a names table: an array of {value, name} pairs that is the one place where the
// names of an enum's values are written (the command line, the viewer and reports read it).

#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace candela {

// The value named `name` in `table`; nullopt for any other name.
template <class E, size_t N>
constexpr std::optional<E> valueNamed(const std::pair<E, const char*> (&table)[N], std::string_view name) {
    for (const auto& [value, text] : table)
        if (name == text) return value;
    return std::nullopt;
}

// The name of `value` in `table`; "?" for a value the table does not hold.
template <class E, size_t N>
constexpr const char* nameOf(const std::pair<E, const char*> (&table)[N], E value) {
    for (const auto& [v, text] : table)
        if (v == value) return text;
    return "?";
}

}  // namespace candela
