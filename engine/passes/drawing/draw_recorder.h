#pragma once
// The draw recorder: records a range of a frame's draw list into a graphics pass, with the state
// set only where it changes — the pipeline, set 1 (the material's), the cull mode and front face,
// the vertex buffer (the scene's or the frame's deformed vertices) — and the draw's index pushed
// in the frame's push constants. Every pass that rasterizes the scene's draws records through it
// (the forward draws, the visibility raster); what differs between them is which pipeline a draw
// uses and which sets they bind, which the pass gives as two hooks.

#include "executor/graph_executor.h"
#include "gpu_scene/gpu_scene.h"
#include "passes/drawing/draw_list.h"
#include "passes/drawing/frame_inputs.h"
#include "vk/pipeline.h"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace candela::passes {

// One draw as a pass records it, with what its hooks need, fixed when the pass is declared.
struct DrawCall {
    const vk::Pipeline* pipeline = nullptr;
    DrawListItem item;
    int32_t vertexOffset = kRestVertices;  // into the deformed vertices; kRestVertices: the scene's own
    VkDescriptorSet materialSet = VK_NULL_HANDLE;  // the scene's set 1 of the draw (VK_NULL_HANDLE: none)
    bool layered = false;  // drawn by a layered program (set 3; set 1 names the posed layer data)
};

// Records `draws` in order between ctx.beginRendering() and ctx.endRendering(). `pipelineBound(p,
// draw, stats)` binds the sets of pipeline `p` other than set 1 after it is bound (every set is rebound
// after a switch: programs may differ from set 1 on); `materialSet(draw)` is the set 1 of a draw
// (VK_NULL_HANDLE: the pipeline has none), bound when it differs from the one bound. `deformed`:
// the frame's deformed vertices. State changes are counted in `recorded` (if given).
// Preconditions: in a graphics pass's execute callback; each pipeline is non-null, has dynamic
// cull mode and front face and a push-constant block of sizeof(FramePush); `deformed` is valid if
// any draw's vertexOffset is not kRestVertices; the hooks record no rendering begin or end.
template <class PipelineBound, class MaterialSet>
void recordDraws(const graph::PassContext& ctx, std::span<const DrawCall> draws, const gpu_scene::GpuScene& scene, VkBuffer deformed,
                 shading::FramePush push, DrawStats* recorded, PipelineBound&& pipelineBound, MaterialSet&& materialSet) {
    DrawStats unused;
    DrawStats& stats = recorded ? *recorded : unused;
    VkCommandBuffer cmd = ctx.cmd();
    ctx.beginRendering();
    if (draws.empty()) {  // e.g. only transmissive draws: the pass just clears
        ctx.endRendering();
        return;
    }
    const VkDeviceSize offset = 0;
    const VkBuffer rest = scene.vertexBuffer();
    VkBuffer boundVertices = rest;
    vkCmdBindVertexBuffers(cmd, 0, 1, &rest, &offset);
    vkCmdBindIndexBuffer(cmd, scene.indexBuffer(), 0, VK_INDEX_TYPE_UINT32);
    stats.bufferBinds += 2;
    // The draws come sorted by pipeline and material: few of these change.
    const vk::Pipeline* bound = nullptr;
    VkDescriptorSet boundMaterial = VK_NULL_HANDLE;
    std::optional<VkCullModeFlags> cullMode;
    std::optional<VkFrontFace> frontFace;
    for (const DrawCall& draw : draws) {
        const DrawListItem& item = draw.item;
        if (draw.pipeline != bound) {
            bound = draw.pipeline;
            bound->bind(cmd);
            ++stats.pipelineBinds;
            pipelineBound(*bound, draw, stats);
            boundMaterial = VK_NULL_HANDLE;
        }
        if (const VkDescriptorSet set = materialSet(draw); set != VK_NULL_HANDLE && set != boundMaterial) {
            boundMaterial = set;
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound->layout(), 1, 1, &set, 0, nullptr);
            ++stats.descriptorBinds;
        }
        if (const VkCullModeFlags wanted = item.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT; cullMode != wanted) {
            cullMode = wanted;
            vkCmdSetCullMode(cmd, wanted);
            ++stats.dynamicStates;
        }
        // glTF fronts are counter-clockwise; a mirroring transform turns them clockwise.
        if (const VkFrontFace wanted = item.flipWinding ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
            frontFace != wanted) {
            frontFace = wanted;
            vkCmdSetFrontFace(cmd, wanted);
            ++stats.dynamicStates;
        }
        push.counts.y = item.drawData;
        bound->pushConstants(cmd, &push, sizeof(push));
        const bool restVertices = draw.vertexOffset == kRestVertices;
        if (const VkBuffer wanted = restVertices ? rest : deformed; wanted != boundVertices) {
            boundVertices = wanted;
            vkCmdBindVertexBuffers(cmd, 0, 1, &boundVertices, &offset);
            ++stats.bufferBinds;
        }
        vkCmdDrawIndexed(cmd, item.indexCount, item.instances, item.firstIndex, restVertices ? 0 : draw.vertexOffset, 0);
    }
    ctx.endRendering();
}

// The vertex input of a program that reads the scene's vertices whole, as recordDraws binds them
// (scene::Vertex at binding 0): position, normal, tangent, texture coordinates 0 and 1 and COLOR_0
// at locations 0–5 (forward.vert.glsl).
inline std::vector<VkVertexInputBindingDescription> sceneVertexBindings() {
    return {{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
}
inline std::vector<VkVertexInputAttributeDescription> sceneVertexAttributes() {
    return {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)},
            {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, tangent)},
            {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv0)},
            {4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv1)},
            {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, color)}};
}

// The primitive topology of a pipeline drawing the scene's draws of `topology`.
inline VkPrimitiveTopology primitiveTopology(scene::Topology topology) {
    return topology == scene::Topology::Triangles ? VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST
           : topology == scene::Topology::Lines   ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST
                                                  : VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
}

// Binds `set` at index `index` of `pipeline`'s layout (graphics), counting it in `stats` (a hook's).
inline void bindGraphicsSet(VkCommandBuffer cmd, const vk::Pipeline& pipeline, uint32_t index, VkDescriptorSet set, DrawStats& stats) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), index, 1, &set, 0, nullptr);
    ++stats.descriptorBinds;
}

}  // namespace candela::passes
