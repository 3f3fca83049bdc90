#pragma once
// GPU timestamps for one frame: a query pool reset at the start of the frame, pairs written around
// passes, results read after the frame's fence. Absent (enabled() false) when the queue has no
// timestamp support.

#include "vk/handle.h"

#include <optional>
#include <vector>

namespace candela::vk {

// Whether timestamps written around a pass's commands measure what the pass costs on a device of
// driver `driver`. Not on lavapipe (llvmpipe): it rasterizes a render pass's draws when the render
// pass ends and runs other work after the timestamp that follows it, so a pass's time is mostly the
// recording of its commands (graph::GraphTimings::gpuMsUnreliable). SwiftShader, the other CPU
// driver, waits for its renderer before it writes a timestamp (bench: each pass's GPU time within
// 8% of the pass submitted alone, docs/devices.md); GPUs write them when the work before is done.
bool timestampsMeasurePasses(VkDriverId driver);
// One line for `candela info`: what the device's per-pass timestamps measure.
const char* timestampBehaviour(VkDriverId driver);

class TimestampPool {
public:
    TimestampPool(Context& context, uint32_t capacity);
    bool enabled() const { return static_cast<bool>(mPool); }
    // timestampsMeasurePasses for the pool's device.
    bool measuresPasses() const { return mMeasuresPasses; }

    // Records the reset of all queries; must precede any write in the frame.
    void reset(VkCommandBuffer cmd);
    // Writes a timestamp after `stage` and returns its index, or nullopt when disabled or full.
    std::optional<uint32_t> write(VkCommandBuffer cmd, VkPipelineStageFlags2 stage);
    // Milliseconds between two written queries. Precondition: the frame's work has completed.
    // Returns a negative value if the results are not available.
    double elapsedMs(uint32_t begin, uint32_t end);
    // Fetches all results written this frame. Call once after the fence wait.
    void fetch();

private:
    Context* mContext;
    QueryPool mPool;
    uint32_t mCapacity;
    uint32_t mUsed = 0;
    double mPeriodNs = 0.0;
    bool mMeasuresPasses = true;
    uint64_t mMask = ~0ull;
    std::vector<uint64_t> mResults;  // value, availability pairs
};

}  // namespace candela::vk
