#pragma once
// Parsers of flag values. Each takes the flag's name for its message: anything malformed is a
// candela::UserError of one line, "--flag: expected …, got '…'". Pure, unit-tested.

#include "core/errors.h"
#include "core/name_table.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace candela::app {

// Parses a decimal integer in [0, 2^32): "--width" and "abc" → UserError naming the flag.
uint32_t parseDimension(const std::string& flag, const std::string& value);
// A whole number of at least 1.
uint32_t parseCount(const std::string& flag, const std::string& value);
// Parses a finite decimal number; anything else → UserError naming the flag.
float parseNumber(const std::string& flag, const std::string& value);
// Pixels of level-of-detail error: ≥ 0, or > 0 when `zeroAllowed` is false.
float parsePixels(const std::string& flag, const std::string& value, bool zeroAllowed);
// Parses a finite number of seconds >= 0, in double precision.
double parseSeconds(const std::string& flag, const std::string& value);
// Parses "A,B,C" (three finite numbers).
std::array<float, 3> parseTriple(const std::string& flag, const std::string& value);
// Parses "#rrggbb" into sRGB-encoded components in [0,1].
std::array<float, 3> parseHexColor(const std::string& flag, const std::string& value);
// A file or folder name: anything but "".
std::string parsePath(const std::string& flag, const std::string& value);
// The comma-separated items of `value`, empty ones included ("" gives one empty item).
std::vector<std::string> commaSeparated(const std::string& value);

// The file name of frame `index` of an image sequence: `pattern` with its one %d or %0Nd replaced.
// Throws UserError when the pattern does not hold exactly one such field (% written as %%).
std::string sequenceFileName(const std::string& pattern, uint32_t index);

// A default the engine owns, written as a flag would take it ("0.5", "256").
std::string valueText(float value);
std::string valueText(uint32_t value);

// "a, b and c" with conjunction "and".
std::string joinWords(const std::vector<std::string>& words, const std::string& conjunction);
// "a, b or c" ("a, b, c or FORM" with another form): the list that help and errors show.
std::string joinChoices(const std::vector<std::string>& names, const std::string& otherForm = "");

// The names of an enum's table ({value, name} pairs), in its order.
template <class E, size_t N>
std::vector<std::string> namesOf(const std::pair<E, const char*> (&table)[N]) {
    std::vector<std::string> names;
    for (const auto& [value, name] : table) names.emplace_back(name);
    return names;
}

// The value named `text` in `table`; otherwise a UserError listing every name (and `otherForm`,
// a form of value the flag accepts besides them, such as "#rrggbb").
template <class E, size_t N>
E parseChoice(const std::string& flag, const std::pair<E, const char*> (&table)[N], const std::string& text,
              const std::string& otherForm = "") {
    if (const std::optional<E> value = valueNamed(table, text)) return *value;
    throw UserError(flag + ": expected " + joinChoices(namesOf(table), otherForm) + ", got '" + text + "'");
}

}  // namespace candela::app
