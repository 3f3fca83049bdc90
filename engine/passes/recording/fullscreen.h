#pragma once
// The draw shared by full-screen passes (fullscreen.vert.glsl + a fragment shader): begin
// rendering on the pass's declared attachments, bind the pipeline and descriptor set 0, push
// constants if any, draw one triangle covering the viewport, end rendering.

#include "executor/graph_executor.h"
#include "vk/descriptors.h"
#include "vk/pipeline.h"

#include <string_view>

namespace candela::passes {

// Within rendering begun by the pass: binds `pipeline` and `set` (set 0), pushes the constants if
// any and draws the triangle.
inline void recordFullscreenTriangle(const graph::PassContext& ctx, const vk::Pipeline& pipeline, VkDescriptorSet set,
                                     const void* pushConstants = nullptr, uint32_t pushSize = 0) {
    pipeline.bind(ctx.cmd());
    vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 0, 1, &set, 0, nullptr);
    if (pushConstants) pipeline.pushConstants(ctx.cmd(), pushConstants, pushSize);
    vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
}

inline void drawFullscreenTriangle(const graph::PassContext& ctx, const vk::Pipeline& pipeline, VkDescriptorSet set,
                                   const void* pushConstants = nullptr, uint32_t pushSize = 0) {
    ctx.beginRendering();
    recordFullscreenTriangle(ctx, pipeline, set, pushConstants, pushSize);
    ctx.endRendering();
}

// The common full-screen pass whose set 0 holds one texture of the graph, read through `sampler`:
// writes the set (binding `binding`, the texture's view and layout in this pass) and draws.
inline void drawFullscreenSampling(const graph::PassContext& ctx, const vk::Pipeline& pipeline, std::string_view binding,
                                   graph::TextureId texture, VkSampler sampler, const void* pushConstants = nullptr,
                                   uint32_t pushSize = 0) {
    const VkDescriptorSet set = vk::DescriptorWriter(pipeline.program(), 0)
                                    .image(binding, ctx.view(texture), ctx.layout(texture), sampler)
                                    .commit(ctx.context(), ctx.descriptors());
    drawFullscreenTriangle(ctx, pipeline, set, pushConstants, pushSize);
}

}  // namespace candela::passes
