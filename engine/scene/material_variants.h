#pragma once
// KHR_materials_variants: choosing which of a file's material variants the scene's draws use
// (`--variant NAME`, the viewer's variant list). The loader records the variants
// (Scene::variants, Scene::drawVariants); these functions pick one. Plain data, no Vulkan.

#include "scene/scene.h"

#include <optional>
#include <string>

namespace candela::scene {

// Gives every draw that a variant maps the material of `variant` (a Scene::variants index), or its
// default material with nullopt; draws the variant does not map get their default.
// Precondition: variant < scene.variants.size().
void selectVariant(Scene& scene, std::optional<uint32_t> variant);

// The index of the variant named `name`. Throws UserError naming the file's variants when there is
// no such variant (or the file has none).
uint32_t variantIndex(const Scene& scene, const std::string& name);

}  // namespace candela::scene
