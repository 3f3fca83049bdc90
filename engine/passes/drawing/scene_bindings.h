#pragma once
// The scene's descriptor sets, as every program that draws or shades it binds them (the forward
// programs, the visibility raster and the visibility shading):
//   set 0: the scene's storage blocks (Lights, Draws, Materials: scene_blocks.h), each the scene's
//          own buffer or, in a frame of an animated pose, that frame's posed buffer;
//   set 1: a material's core textures and, for a layered program, the layer parameters' buffer (the
//          scene's or the frame's posed one) and the layer textures.
// The scene's own sets are written once per scene (the passes' setScene); a frame with posed
// buffers writes its own in the pass's execute callback (frameSceneSet, PosedMaterialSets).

#include "executor/graph_executor.h"
#include "gpu_scene/gpu_scene.h"
#include "passes/drawing/frame_inputs.h"
#include "vk/descriptors.h"
#include "vk/pipeline.h"

#include <vector>

namespace candela::passes {

// The buffers set 0 names.
struct SceneBuffers {
    VkBuffer lights = VK_NULL_HANDLE;
    VkBuffer draws = VK_NULL_HANDLE;
    VkBuffer materials = VK_NULL_HANDLE;
};
// The scene's own buffers.
SceneBuffers sceneBuffersOf(const gpu_scene::GpuScene& scene);

// Writes set 0 of `program`: each scene block the program declares, naming `buffers`' one. The set
// comes from `allocator` and lives as long as it does.
VkDescriptorSet writeSceneSet(vk::Context& context, vk::DescriptorAllocator& allocator, const vk::Program& program,
                              const SceneBuffers& buffers);

// Set 0 of `program` in a pass's execute callback: `sceneSet` (written for the scene's own buffers)
// unless the frame has a posed buffer among those `declared` (declareFrameReads) that the program
// reads; then a set naming it, from the frame's descriptor pool.
VkDescriptorSet frameSceneSet(const graph::PassContext& ctx, const vk::Program& program, const gpu_scene::GpuScene& scene,
                              const PosedBuffers& declared, VkDescriptorSet sceneSet);

// The frame's deformed vertices as `declared` (declareFrameReads) resolve them in a pass's execute
// callback; VK_NULL_HANDLE when the frame has none.
inline VkBuffer deformedBuffer(const graph::PassContext& ctx, const DeclaredFrameBuffers& declared) {
    return declared.deformed.valid() ? ctx.buffer(declared.deformed) : VK_NULL_HANDLE;
}

// Writes set 1 of `program` for material `material` of `scene`: its core textures and, with
// `layers` (the layer parameters' buffer; VK_NULL_HANDLE for a core program), the layer textures
// the program declares (a program specialized to the material's layers declares only theirs).
// The set comes from `allocator` and lives as long as it does.
VkDescriptorSet writeMaterialSet(vk::Context& context, vk::DescriptorAllocator& allocator, const vk::Program& program,
                                 const gpu_scene::GpuScene& scene, uint32_t material, VkBuffer layers);

// Within one pass's execute callback: the layered materials' sets 1 naming the frame's posed layer
// parameters, written at first use, one per slot (a material, or a texture set). Without posed
// layer data every call returns the scene's set.
class PosedMaterialSets {
public:
    // `declaredLayers`: the posed material layers as the pass declared them (invalid: none);
    // `slots`: how many sets the pass indexes. Preconditions: the arguments outlive this object.
    PosedMaterialSets(const graph::PassContext& ctx, const gpu_scene::GpuScene& scene, graph::BufferId declaredLayers, size_t slots);
    // `sceneSet` unless `layered` and the frame has posed layer data; then set 1 of `program` for
    // `material`, naming the frame's buffer, written once for `slot`.
    VkDescriptorSet get(size_t slot, bool layered, const vk::Program& program, uint32_t material, VkDescriptorSet sceneSet);

private:
    const graph::PassContext& mCtx;
    const gpu_scene::GpuScene& mScene;
    graph::BufferId mLayers;
    std::vector<VkDescriptorSet> mSets;
};

}  // namespace candela::passes
