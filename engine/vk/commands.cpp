#include "vk/commands.h"

#include "vk/check.h"

#include <algorithm>
#include <initializer_list>

namespace candela::vk {

Fence createFence(Context& context, bool signaled) {
    const VkFenceCreateInfo info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO,
                                 .flags = signaled ? VkFenceCreateFlags(VK_FENCE_CREATE_SIGNALED_BIT) : 0u};
    VkFence fence = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFence(context.device(), &info, nullptr, &fence));
    return Fence(context, fence);
}

Semaphore createSemaphore(Context& context) {
    const VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(context.device(), &info, nullptr, &semaphore));
    return Semaphore(context, semaphore);
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

namespace {
VkImageMemoryBarrier2 rangeBarrier(VkImage image, VkImageSubresourceRange range, VkPipelineStageFlags2 srcStages,
                                   VkAccessFlags2 srcAccess, VkImageLayout oldLayout, VkPipelineStageFlags2 dstStages,
                                   VkAccessFlags2 dstAccess, VkImageLayout newLayout) {
    return {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = srcStages,
            .srcAccessMask = srcAccess,
            .dstStageMask = dstStages,
            .dstAccessMask = dstAccess,
            .oldLayout = oldLayout,
            .newLayout = newLayout,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = image,
            .subresourceRange = range};
}

VkImageMemoryBarrier2 mipBarrier(VkImage image, VkImageAspectFlags aspect, uint32_t mip, uint32_t mipCount,
                                 uint32_t layer, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                                 VkImageLayout oldLayout, VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess,
                                 VkImageLayout newLayout) {
    return rangeBarrier(image, {aspect, mip, mipCount, layer, 1}, srcStages, srcAccess, oldLayout, dstStages, dstAccess,
                        newLayout);
}

void barriers(VkCommandBuffer cmd, std::initializer_list<VkImageMemoryBarrier2> list) {
    const VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                      .imageMemoryBarrierCount = static_cast<uint32_t>(list.size()),
                                      .pImageMemoryBarriers = list.begin()};
    vkCmdPipelineBarrier2(cmd, &dependency);
}
}  // namespace

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStages,
                  VkAccessFlags2 srcAccess, VkImageLayout oldLayout, VkPipelineStageFlags2 dstStages,
                  VkAccessFlags2 dstAccess, VkImageLayout newLayout) {
    barriers(cmd, {rangeBarrier(image, {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS}, srcStages,
                                srcAccess, oldLayout, dstStages, dstAccess, newLayout)});
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
    const VkMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                   .srcStageMask = srcStages,
                                   .srcAccessMask = srcAccess,
                                   .dstStageMask = dstStages,
                                   .dstAccessMask = dstAccess};
    const VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .memoryBarrierCount = 1,
                                      .pMemoryBarriers = &barrier};
    vkCmdPipelineBarrier2(cmd, &dependency);
}

namespace {
constexpr VkPipelineStageFlags2 kShaderStages =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
}  // namespace

ReadScope imageReaders(VkImageUsageFlags usage, VkImageLayout layout) {
    ReadScope scope;
    switch (layout) {
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
            if (usage & VK_IMAGE_USAGE_SAMPLED_BIT) scope = {kShaderStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
            break;
        case VK_IMAGE_LAYOUT_GENERAL:
            if (usage & VK_IMAGE_USAGE_SAMPLED_BIT) scope = {kShaderStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
            if (usage & VK_IMAGE_USAGE_STORAGE_BIT)
                scope = {kShaderStages, scope.access | VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
            break;
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
            if (usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT)
                scope = {VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
            break;
        default: break;
    }
    if (scope.stages == VK_PIPELINE_STAGE_2_NONE)
        throw InternalError("no reads of an image with usage " + std::to_string(usage) + " in layout " +
                            std::to_string(layout) + " to make an upload visible to");
    return scope;
}

ReadScope bufferReaders(VkBufferUsageFlags usage) {
    ReadScope scope;
    const auto add = [&](VkBufferUsageFlags bit, VkPipelineStageFlags2 stages, VkAccessFlags2 access) {
        if (!(usage & bit)) return;
        scope.stages |= stages;
        scope.access |= access;
    };
    add(VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
        VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
    add(VK_BUFFER_USAGE_INDEX_BUFFER_BIT, VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT, VK_ACCESS_2_INDEX_READ_BIT);
    add(VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
    add(VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, kShaderStages, VK_ACCESS_2_UNIFORM_READ_BIT);
    add(VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, kShaderStages, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    add(VK_BUFFER_USAGE_TRANSFER_SRC_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    return scope;
}

void recordMipChain(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkExtent3D baseExtent,
                    uint32_t baseMip, uint32_t mipLevels, uint32_t layer, VkImageLayout finalLayout,
                    const ReadScope& readers) {
    const auto corner = [&](uint32_t level) {
        return VkOffset3D{static_cast<int32_t>(std::max(1u, baseExtent.width >> level)),
                          static_cast<int32_t>(std::max(1u, baseExtent.height >> level)),
                          static_cast<int32_t>(std::max(1u, baseExtent.depth >> level))};
    };
    for (uint32_t level = baseMip + 1; level < mipLevels; ++level) {
        barriers(cmd, {mipBarrier(image, aspect, level - 1, 1, layer, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                  VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                  VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL)});
        const VkImageBlit blit{.srcSubresource = {aspect, level - 1, layer, 1},
                               .srcOffsets = {{0, 0, 0}, corner(level - 1)},
                               .dstSubresource = {aspect, level, layer, 1},
                               .dstOffsets = {{0, 0, 0}, corner(level)}};
        vkCmdBlitImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                       &blit, VK_FILTER_LINEAR);
    }
    // Every mip but the last was a blit source; the last one is still a transfer destination.
    barriers(cmd, {mipBarrier(image, aspect, baseMip, mipLevels - 1 - baseMip, layer, VK_PIPELINE_STAGE_2_BLIT_BIT,
                              VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readers.stages, readers.access,
                              finalLayout),
                   mipBarrier(image, aspect, mipLevels - 1, 1, layer, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                              VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, readers.stages,
                              readers.access, finalLayout)});
}

void setViewportAndScissor(VkCommandBuffer cmd, VkExtent2D extent) {
    const VkViewport viewport{0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace candela::vk
