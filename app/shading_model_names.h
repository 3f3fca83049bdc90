#pragma once
// The names of the forward pass's shading models (--shading). The enum is defined with the forward
// pass (passes/forward_pass.h), which needs Vulkan; the command-line parser sees only this
// declaration, so the values below are written as numbers. main.cpp, which sees the definition,
// checks at compile time that each name gives the model it stands for.

#include "core/name_table.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

namespace candela::passes {
enum class ShadingModel : uint32_t;  // Pbr = 0, PbrSchlickGgx = 1, BlinnPhong = 2
}

namespace candela::app {

inline constexpr std::pair<passes::ShadingModel, const char*> kShadingModelNames[] = {
    {passes::ShadingModel{0}, "pbr"}, {passes::ShadingModel{1}, "pbr-schlick-ggx"}, {passes::ShadingModel{2}, "blinn-phong"}};

// The model named `name` in kShadingModelNames; nullopt for anything else.
constexpr std::optional<passes::ShadingModel> parseShadingModel(std::string_view name) {
    return valueNamed(kShadingModelNames, name);
}

}  // namespace candela::app
