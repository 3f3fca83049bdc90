#pragma once
// The tone mapping operators of the tonemap pass (passes/post/tonemap_pass.h) and their names, the one
// table that the pass, the command line (--tonemap) and the tests read. Names only: no Vulkan.

#include "core/name_table.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

namespace candela::options {

enum class Tonemap : uint32_t { PbrNeutral = 0, Aces = 1, Agx = 2, Reinhard = 3, Linear = 4 };

inline constexpr std::pair<Tonemap, const char*> kTonemapNames[] = {{Tonemap::PbrNeutral, "pbr-neutral"},
                                                                     {Tonemap::Aces, "aces"},
                                                                     {Tonemap::Agx, "agx"},
                                                                     {Tonemap::Reinhard, "reinhard"},
                                                                     {Tonemap::Linear, "linear"}};

// The operator named `name` in kTonemapNames; nullopt for anything else.
constexpr std::optional<Tonemap> parseTonemap(std::string_view name) { return valueNamed(kTonemapNames, name); }

constexpr const char* tonemapName(Tonemap op) { return nameOf(kTonemapNames, op); }

}  // namespace candela::options
