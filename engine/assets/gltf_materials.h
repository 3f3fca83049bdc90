#pragma once
// Internal to the glTF loader: samplers and metallic-roughness materials (all five textures,
// factors, alpha modes, KHR_materials_emissive_strength, KHR_materials_unlit, KHR_texture_transform).

#include "assets/gltf_context.h"
#include "assets/gltf_images.h"
#include "scene/scene.h"

namespace tinygltf {
class Model;
struct Primitive;
}

namespace candela::assets::gltf {

// Appends one Scene::Sampler per glTF sampler, same order (TextureRef::sampler indexes them).
void loadSamplers(const LoadContext& ctx, const tinygltf::Model& model, scene::Scene& scene);

// Appends one Scene::Material per glTF material, same order, resolving textures through `images`
// (base colour and emissive as sRGB, the rest linear). Every index is range-checked.
void loadMaterials(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images, scene::Scene& scene);

// KHR_materials_variants: the root extension's variant names into scene.variants. Call before
// loadNodes.
void loadVariantNames(const LoadContext& ctx, const tinygltf::Model& model, scene::Scene& scene);

// The (variant, material) pairs of a mesh primitive's KHR_materials_variants mappings, in file
// order (a later mapping of the same variant wins); empty without the extension. Fails on a
// variant or material index out of range. `what` names the primitive in messages.
std::vector<std::pair<uint32_t, uint32_t>> primitiveVariants(const LoadContext& ctx, const tinygltf::Primitive& primitive,
                                                             const scene::Scene& scene, const std::string& what);

}  // namespace candela::assets::gltf
