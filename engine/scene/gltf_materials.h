#pragma once
// Internal to the glTF loader: samplers and metallic-roughness materials (all five textures,
// factors, alpha modes, KHR_materials_emissive_strength, KHR_materials_unlit, KHR_texture_transform).

#include "scene/gltf_context.h"
#include "scene/gltf_images.h"
#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace candela::scene::gltf {

// Appends one Scene::Sampler per glTF sampler, same order (TextureRef::sampler indexes them).
void loadSamplers(const LoadContext& ctx, const tinygltf::Model& model, Scene& scene);

// Appends one Scene::Material per glTF material, same order, resolving textures through `images`
// (base colour and emissive as sRGB, the rest linear). Every index is range-checked.
void loadMaterials(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images, Scene& scene);

}  // namespace candela::scene::gltf
