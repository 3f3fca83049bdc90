#include "scene/material_variants.h"

#include "core/errors.h"

namespace candela::scene {

void selectVariant(Scene& scene, std::optional<uint32_t> variant) {
    for (const DrawVariants& d : scene.drawVariants) {
        uint32_t material = d.defaultMaterial;
        if (variant)
            for (const auto& [v, m] : d.materials)
                if (v == *variant) material = m;
        scene.draws.at(d.draw).material = material;
    }
}

uint32_t variantIndex(const Scene& scene, const std::string& name) {
    for (uint32_t i = 0; i < scene.variants.size(); ++i)
        if (scene.variants[i] == name) return i;
    if (scene.variants.empty())
        throw UserError("--variant " + name + ": " + scene.source + " has no material variants (KHR_materials_variants)");
    std::string known;
    for (const std::string& v : scene.variants) known += (known.empty() ? "" : ", ") + v;
    throw UserError("--variant: " + scene.source + " has no variant '" + name + "' (its variants: " + known + ")");
}

}  // namespace candela::scene
