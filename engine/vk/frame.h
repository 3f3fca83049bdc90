#pragma once
// FrameRing: frames in flight. Each slot owns a command buffer, a fence, a descriptor allocator and
// a timestamp pool. begin() waits until the slot's previous frame has completed, runs the deferred
// destructions that are now safe and recycles the slot's pools; submit() sends the frame.

#include "vk/descriptors.h"
#include "vk/handle.h"
#include "vk/timestamps.h"

#include <functional>
#include <memory>
#include <vector>

namespace candela::vk {

struct FrameSlot {
    CommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    Fence fence;
    std::unique_ptr<DescriptorAllocator> descriptors;
    std::unique_ptr<TimestampPool> timestamps;
    uint64_t frame = 0;        // number of the frame last recorded in this slot
    bool submitted = false;
    // Runs once when the slot's submitted frame is known to be complete (its fence was waited for
    // by begin(), waitCurrent() or waitIdle()), after its timestamps were fetched. Cleared after.
    std::function<void(FrameSlot&)> completed;
};

// How far the CPU ran ahead of the GPU, counted since the ring was made (the viewer's summary,
// tests). A frame overlaps when it is submitted while an earlier one is still executing: its
// recording ran alongside the GPU's work.
struct FrameRingStats {
    uint64_t submits = 0;
    uint64_t overlappedSubmits = 0;  // submits made while an earlier submitted frame was still running
    uint64_t blockingWaits = 0;      // fence waits (begin, waitCurrent, waitIdle) that found the frame running
    double blockedMs = 0.0;          // CPU wall time spent in those waits
};

class FrameRing {
public:
    FrameRing(Context& context, uint32_t framesInFlight = 2, uint32_t timestampCapacity = 256);
    ~FrameRing();
    FrameRing(const FrameRing&) = delete;
    FrameRing& operator=(const FrameRing&) = delete;

    // Starts recording the next frame; returns its slot (command buffer already begun).
    FrameSlot& begin();
    // Ends and submits the current frame to the graphics queue, with optional semaphores (swapchain).
    void submit(const std::vector<VkSemaphoreSubmitInfo>& waits = {},
                const std::vector<VkSemaphoreSubmitInfo>& signals = {});
    // Serialized timing: ends the current frame's command buffer, submits what it holds so far,
    // waits for it and begins the same command buffer again, so that recording continues where it
    // stopped. Returns the wall milliseconds from submit to completion. Precondition: begin() was
    // called and submit() not yet; the frame waits on no semaphore (its first part would run
    // before the wait).
    double flushAndResume();
    // Waits for the current slot's frame (after submit), e.g. to read back results.
    void waitCurrent();
    // Waits for every submitted frame and runs all deferred destructions.
    void waitIdle();

    uint32_t slotCount() const { return static_cast<uint32_t>(mSlots.size()); }
    uint32_t currentSlot() const { return mCurrent; }
    const FrameRingStats& stats() const { return mStats; }

private:
    void collectCompleted();
    // Waits for the slot's submitted frame (if any) and fetches its timestamps.
    void waitSlot(FrameSlot& slot);
    Context* mContext;
    std::vector<FrameSlot> mSlots;
    uint32_t mCurrent = 0;
    FrameRingStats mStats;
};

}  // namespace candela::vk
