#pragma once
// How a frame shades its opaque and alpha-masked surfaces (--shading-path; docs/shading-paths.md),
// and the names of the choices, the one table the command line and the docs read. Names only.

#include "core/name_table.h"

#include <cstdint>
#include <utility>

namespace candela::options {

enum class ShadingPath : uint8_t {
    Auto,        // the device's default (vk::DeviceChoices::shadingPath, chosen by measurement)
    Forward,     // the forward pass: each draw's fragments shaded as they are rasterized
    Visibility,  // a visibility buffer, classified per tile and shaded in compute, each covered pixel once
};

inline constexpr std::pair<ShadingPath, const char*> kShadingPathNames[] = {
    {ShadingPath::Auto, "auto"}, {ShadingPath::Forward, "forward"}, {ShadingPath::Visibility, "visibility"}};

constexpr const char* shadingPathName(ShadingPath value) { return nameOf(kShadingPathNames, value); }

}  // namespace candela::options
