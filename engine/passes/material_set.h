#pragma once
// Descriptor set 1 of the programs that shade materials — the forward programs and the visibility
// path's compute shading: a material's core textures and, for a layered program, the layer
// parameters' buffer and the layer textures. Shared so that both paths bind a material alike.

#include "gpu_scene/gpu_scene.h"
#include "vk/descriptors.h"
#include "vk/pipeline.h"

namespace candela::passes {

// Writes set 1 of `program` for material `material` of `scene`: its core textures and, with
// `layers` (the layer parameters' buffer; VK_NULL_HANDLE for a core program), the layer textures
// the program declares (a program specialized to the material's layers declares only theirs).
// The set comes from `allocator` and lives as long as it does.
VkDescriptorSet writeMaterialSet(vk::Context& context, vk::DescriptorAllocator& allocator, const vk::Program& program,
                                 const scene::GpuScene& scene, uint32_t material, VkBuffer layers);

}  // namespace candela::passes
