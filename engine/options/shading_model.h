#pragma once
// The shading models (both paths) and their names, the one table that the shading variants'
// names, the command line (--shading) and the tests read. Names only: no Vulkan.

#include "core/name_table.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

namespace candela::options {

enum class ShadingModel : uint32_t { Pbr = 0, PbrSchlickGgx = 1, BlinnPhong = 2 };

inline constexpr std::pair<ShadingModel, const char*> kShadingModelNames[] = {
    {ShadingModel::Pbr, "pbr"}, {ShadingModel::PbrSchlickGgx, "pbr-schlick-ggx"}, {ShadingModel::BlinnPhong, "blinn-phong"}};

// The model named `name` in kShadingModelNames; nullopt for anything else.
constexpr std::optional<ShadingModel> parseShadingModel(std::string_view name) {
    return valueNamed(kShadingModelNames, name);
}

constexpr const char* shadingModelName(ShadingModel model) { return nameOf(kShadingModelNames, model); }

}  // namespace candela::options
