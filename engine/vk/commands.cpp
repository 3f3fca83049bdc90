#include "vk/commands.h"

#include "core/check.h"

namespace candela::vk {

Fence createFence(Context& context, bool signaled) {
    const VkFenceCreateInfo info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO,
                                 .flags = signaled ? VkFenceCreateFlags(VK_FENCE_CREATE_SIGNALED_BIT) : 0u};
    VkFence fence = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFence(context.device(), &info, nullptr, &fence));
    return Fence(context, fence);
}

CommandPool createCommandPool(Context& context, uint32_t family, VkCommandPoolCreateFlags flags) {
    const VkCommandPoolCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, .flags = flags, .queueFamilyIndex = family};
    VkCommandPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateCommandPool(context.device(), &info, nullptr, &pool));
    return CommandPool(context, pool);
}

OneShotCommands::OneShotCommands(Context& context)
    : mContext(&context),
      mPool(createCommandPool(context, context.graphicsQueue().family, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT)),
      mFence(createFence(context, false)) {
    const VkCommandBufferAllocateInfo info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                           .commandPool = mPool.get(),
                                           .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                           .commandBufferCount = 1};
    VK_CHECK(vkAllocateCommandBuffers(context.device(), &info, &mCmd));
}

VkCommandBuffer OneShotCommands::begin() {
    VK_CHECK(vkResetCommandPool(mContext->device(), mPool.get(), 0));
    const VkCommandBufferBeginInfo info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(mCmd, &info));
    return mCmd;
}

void OneShotCommands::submitAndWait() {
    VK_CHECK(vkEndCommandBuffer(mCmd));
    const VkCommandBufferSubmitInfo cmdInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO, .commandBuffer = mCmd};
    const VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2, .commandBufferInfoCount = 1,
                               .pCommandBufferInfos = &cmdInfo};
    VkFence fence = mFence.get();
    VK_CHECK(vkQueueSubmit2(mContext->graphicsQueue().queue, 1, &submit, fence));
    VK_CHECK(vkWaitForFences(mContext->device(), 1, &fence, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(mContext->device(), 1, &fence));
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStages,
                  VkAccessFlags2 srcAccess, VkImageLayout oldLayout, VkPipelineStageFlags2 dstStages,
                  VkAccessFlags2 dstAccess, VkImageLayout newLayout) {
    const VkImageMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
                                        .srcStageMask = srcStages,
                                        .srcAccessMask = srcAccess,
                                        .dstStageMask = dstStages,
                                        .dstAccessMask = dstAccess,
                                        .oldLayout = oldLayout,
                                        .newLayout = newLayout,
                                        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                        .image = image,
                                        .subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0,
                                                             VK_REMAINING_ARRAY_LAYERS}};
    const VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                      .imageMemoryBarrierCount = 1,
                                      .pImageMemoryBarriers = &barrier};
    vkCmdPipelineBarrier2(cmd, &dependency);
}

void setViewportAndScissor(VkCommandBuffer cmd, VkExtent2D extent) {
    const VkViewport viewport{0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace candela::vk
