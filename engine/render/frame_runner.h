#pragma once
// FrameRunner: runs built frames on the device. Applies the pass toggles, compiles the frame's
// graph, records it into the next frame slot (with that slot's transient memory and host uploads),
// submits it — waiting on and signalling a presentable image's semaphores when given — and keeps
// it as the last frame. When a frame is known complete it takes its per-pass GPU times.

#include "executor/transient_pool.h"
#include "render/frame.h"
#include "vk/frame.h"
#include "vk/host_upload_ring.h"

#include <chrono>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

class FrameRunner {
public:
    // Precondition: `context` outlives the runner.
    FrameRunner(vk::Context& context, uint32_t framesInFlight);
    ~FrameRunner();  // waits for the frames in flight

    struct SubmitOptions {
        std::span<const std::string> disabledPasses;  // pass names switched off in this frame (read during submit)
        // false: a disabled pass the frame does not declare, or one that cannot be switched off
        // (PassDecl::cannotBeDisabled), is ignored (the viewer keeps toggles across scene and
        // environment changes); true: it is a UserError (the command line).
        bool unknownPassIsError = true;
        bool emitBarriers = true;  // testing hook: false records no barriers (sync validation must object)
        const PresentTarget* present = nullptr;
        bool serialPasses = false;  // RenderSettings::serialPasses; not with `present`
    };
    // Submits `frame` as above; it becomes the last frame. Returns when it was submitted. Throws
    // UserError for an unknown disabled pass (when that is an error).
    std::chrono::steady_clock::time_point submit(Frame frame, const SubmitOptions& options);
    // Waits for the last submitted frame (its timings are then the completed ones).
    void waitCurrent() {
        ++mCompletionWaits;
        mFrames.waitCurrent();
    }
    // How many times waitCurrent() was called: the CPU stopped until the frame it had just
    // submitted completed (captures, precompute frames), instead of running ahead.
    uint64_t completionWaits() const { return mCompletionWaits; }
    // Submits, overlapping submits and blocking fence waits so far (vk::FrameRingStats).
    const vk::FrameRingStats& ringStats() const { return mFrames.stats(); }
    // Waits for every frame in flight.
    void waitIdle() { mFrames.waitIdle(); }

    // The last frame submitted (its graph, declaration and compiled result).
    const Frame& last() const { return mLast; }
    // Per-pass GPU times of the latest frame known to be complete: in execution order, and by
    // declared pass.
    const std::vector<PassTime>& completedPassTimes() const { return mCompletedTimes; }
    const graph::GraphTimings& completedTimings() const { return mCompletedTimings; }
    // The GPU time of the pass named `pass` in that frame; negative if it did not run there.
    double completedPassMs(std::string_view pass) const;
    // The GPU time of the last completed frame's IBL precompute passes (negative before any).
    double lastPrecomputeGpuMs() const { return mLastPrecomputeGpuMs; }
    // Transient-pool rebuilds so far (tests: stays constant while the graph is unchanged).
    uint32_t transientRebuilds() const;
    // The transient pool of the last submitted frame's slot: the images behind its graph's transients.
    const graph::TransientPool& lastTransients() const { return *mTransients[mFrames.currentSlot()]; }

private:
    // Copies the frame's host uploads into the current slot's buffers and binds them.
    void writeHostUploads(Frame& frame);

    vk::Context& mContext;
    vk::FrameRing mFrames;
    std::vector<std::unique_ptr<graph::TransientPool>> mTransients;  // one per frame slot
    vk::HostUploadRing mHostUploads;
    std::vector<PassTime> mCompletedTimes;
    graph::GraphTimings mCompletedTimings;  // of the latest completed frame, by declared pass
    double mLastPrecomputeGpuMs = -1.0;
    uint64_t mCompletionWaits = 0;
    Frame mLast;
};

}  // namespace candela
