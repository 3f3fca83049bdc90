#pragma once
// The material texture sets of the visibility path (docs/shading-paths.md): materials that bind
// the same image and sampler in every core and layer texture slot share one set. A compute
// dispatch shades pixels of many materials at once but binds one descriptor set 1, so it shades
// one texture set: Vulkan devices need not index sampler arrays at all (lavapipe cannot,
// shaderSampledImageArrayDynamicIndexing is off), so the textures are bound, not indexed. Scenes
// without textures, and materials that differ only in their factors, share a single set.
// Plain data and a pure function.

#include "gpu_scene/gpu_scene.h"

#include <cstdint>
#include <vector>

namespace candela::passes {

struct TextureSets {
    std::vector<uint32_t> ofMaterial;      // per scene material: its texture set
    std::vector<uint32_t> firstMaterial;   // per texture set: the first material that has it
    // Per texture set, the slots that hold a texture of the scene (bit per CANDELA_TEX_* and
    // CANDELA_LAYER_TEX_* slot); the others hold the 1×1 white default, which the shading reads as
    // the constant it is. Normal-map slots always count (their default is a flat normal, read only
    // when the material has the map).
    std::vector<uint32_t> coreSlots, layerSlots;
};

// The texture sets of `scene`'s materials, numbered in material order.
TextureSets textureSetsOf(const gpu_scene::GpuScene& scene);

}  // namespace candela::passes
