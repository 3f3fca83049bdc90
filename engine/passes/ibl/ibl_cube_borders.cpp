#include "passes/ibl/ibl_cube_borders.h"

#include "vk/commands.h"
#include "vk/descriptors.h"

namespace candela::passes {

CubeBorderDraw::CubeBorderDraw(vk::Context& context) {
    if (!context.choices().cubeBordersNeedADraw) return;
    mPipeline = vk::Pipeline::graphics(context, "ibl_cube_borders.vert", "",
                                       {.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST, .rasterizerDiscard = true});
    mSampler = vk::createSampler(context, {});
}

void CubeBorderDraw::record(const graph::PassContext& ctx, VkImageView view, VkImageLayout layout) const {
    if (!mPipeline.handle()) return;
    VkCommandBuffer cmd = ctx.cmd();
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    const VkDescriptorSet set = vk::DescriptorWriter(mPipeline.program(), 0)
                                    .image("cube", view, layout, mSampler.get())
                                    .commit(ctx.context(), ctx.descriptors());
    const VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO, .renderArea = {{0, 0}, {1, 1}}, .layerCount = 1};
    vkCmdBeginRendering(cmd, &rendering);
    const VkViewport viewport{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {1, 1}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.layout(), 0, 1, &set, 0, nullptr);
    vkCmdDraw(cmd, 1, 1, 0, 0);
    vkCmdEndRendering(cmd);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_NONE);
}

}  // namespace candela::passes
