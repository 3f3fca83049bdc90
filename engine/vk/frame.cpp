#include "vk/frame.h"

#include "vk/check.h"
#include "vk/commands.h"

#include <algorithm>
#include <chrono>
#include <utility>

namespace candela::vk {
namespace {

// Resets the slot's pool (its one command buffer) and begins recording the command buffer again.
void restartCommands(Context& context, FrameSlot& slot) {
    VK_CHECK(vkResetCommandPool(context.device(), slot.pool.get(), 0));
    const VkCommandBufferBeginInfo info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(slot.cmd, &info));
}

// Ends the slot's command buffer and submits it to the graphics queue, signalling the slot's fence.
void submitCommands(Context& context, FrameSlot& slot, const std::vector<VkSemaphoreSubmitInfo>& waits = {},
                    const std::vector<VkSemaphoreSubmitInfo>& signals = {}) {
    VK_CHECK(vkEndCommandBuffer(slot.cmd));
    const VkCommandBufferSubmitInfo cmdInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO, .commandBuffer = slot.cmd};
    const VkSubmitInfo2 submitInfo{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                                   .waitSemaphoreInfoCount = static_cast<uint32_t>(waits.size()),
                                   .pWaitSemaphoreInfos = waits.data(),
                                   .commandBufferInfoCount = 1,
                                   .pCommandBufferInfos = &cmdInfo,
                                   .signalSemaphoreInfoCount = static_cast<uint32_t>(signals.size()),
                                   .pSignalSemaphoreInfos = signals.data()};
    VK_CHECK(vkQueueSubmit2(context.graphicsQueue().queue, 1, &submitInfo, slot.fence.get()));
}

}  // namespace

FrameRing::FrameRing(Context& context, uint32_t framesInFlight, uint32_t timestampCapacity) : mContext(&context) {
    mSlots.resize(std::max(1u, framesInFlight));
    for (FrameSlot& slot : mSlots) {
        slot.pool = createCommandPool(context, context.graphicsQueue().family, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
        const VkCommandBufferAllocateInfo info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                               .commandPool = slot.pool.get(),
                                               .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                               .commandBufferCount = 1};
        VK_CHECK(vkAllocateCommandBuffers(context.device(), &info, &slot.cmd));
        slot.fence = createFence(context, false);
        slot.descriptors = std::make_unique<DescriptorAllocator>(context);
        slot.timestamps = std::make_unique<TimestampPool>(context, timestampCapacity);
    }
    mCurrent = static_cast<uint32_t>(mSlots.size()) - 1;
}

FrameRing::~FrameRing() {
    try {
        waitIdle();
    } catch (...) {
        // Device loss while shutting down: nothing more can be done; the context reports it.
    }
}

void FrameRing::collectCompleted() {
    // Every submitted frame is done except those whose slot fence is still unsignalled; only
    // frames older than the oldest unfinished one are certainly complete.
    int64_t completed = static_cast<int64_t>(mContext->currentFrame()) - 1;
    for (FrameSlot& slot : mSlots)
        if (slot.submitted && vkGetFenceStatus(mContext->device(), slot.fence.get()) != VK_SUCCESS)
            completed = std::min(completed, static_cast<int64_t>(slot.frame) - 1);
    if (completed >= 0) mContext->collect(static_cast<uint64_t>(completed));
}

void FrameRing::waitSlot(FrameSlot& slot) {
    if (!slot.submitted) return;
    VkFence fence = slot.fence.get();
    if (vkGetFenceStatus(mContext->device(), fence) != VK_SUCCESS) {
        const auto start = std::chrono::steady_clock::now();
        VK_CHECK(vkWaitForFences(mContext->device(), 1, &fence, VK_TRUE, UINT64_MAX));
        ++mStats.blockingWaits;
        mStats.blockedMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    VK_CHECK(vkResetFences(mContext->device(), 1, &fence));
    slot.submitted = false;
    slot.timestamps->fetch();
    if (slot.completed) std::exchange(slot.completed, nullptr)(slot);
}

FrameSlot& FrameRing::begin() {
    mCurrent = (mCurrent + 1) % mSlots.size();
    FrameSlot& slot = mSlots[mCurrent];
    waitSlot(slot);
    collectCompleted();
    slot.descriptors->reset();
    restartCommands(*mContext, slot);
    slot.frame = mContext->currentFrame();
    slot.timestamps->reset(slot.cmd);
    return slot;
}

void FrameRing::submit(const std::vector<VkSemaphoreSubmitInfo>& waits, const std::vector<VkSemaphoreSubmitInfo>& signals) {
    FrameSlot& slot = mSlots[mCurrent];
    ++mStats.submits;
    if (std::any_of(mSlots.begin(), mSlots.end(), [&](const FrameSlot& other) {
            return other.submitted && vkGetFenceStatus(mContext->device(), other.fence.get()) != VK_SUCCESS;
        }))
        ++mStats.overlappedSubmits;
    submitCommands(*mContext, slot, waits, signals);
    slot.submitted = true;
    mContext->advanceFrame();
}

double FrameRing::flushAndResume() {
    FrameSlot& slot = mSlots[mCurrent];
    VkFence fence = slot.fence.get();
    const auto start = std::chrono::steady_clock::now();
    submitCommands(*mContext, slot);
    VK_CHECK(vkWaitForFences(mContext->device(), 1, &fence, VK_TRUE, UINT64_MAX));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    VK_CHECK(vkResetFences(mContext->device(), 1, &fence));
    // Unlike begin(), this keeps the slot's descriptors and timestamps, which the rest of the
    // frame goes on using.
    restartCommands(*mContext, slot);
    return ms;
}

void FrameRing::waitCurrent() {
    waitSlot(mSlots[mCurrent]);
    collectCompleted();
}

void FrameRing::waitIdle() {
    for (FrameSlot& slot : mSlots) waitSlot(slot);
    mContext->waitIdleAndCollect();
}

}  // namespace candela::vk
