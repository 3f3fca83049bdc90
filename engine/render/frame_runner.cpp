#include "render/frame_runner.h"

#include "core/errors.h"

#include <algorithm>

namespace candela {

using namespace graph;

FrameRunner::FrameRunner(vk::Context& context, uint32_t framesInFlight)
    : mContext(context), mFrames(context, framesInFlight), mHostUploads(context, mFrames.slotCount()) {
    for (uint32_t i = 0; i < mFrames.slotCount(); ++i) mTransients.push_back(std::make_unique<TransientPool>(context));
}

FrameRunner::~FrameRunner() { mFrames.waitIdle(); }

uint32_t FrameRunner::transientRebuilds() const {
    uint32_t total = 0;
    for (const auto& pool : mTransients) total += pool->rebuilds();
    return total;
}

double FrameRunner::completedPassMs(std::string_view pass) const {
    for (const PassTime& t : mCompletedTimes)
        if (t.name == pass) return t.gpuMs;
    return -1.0;
}

std::chrono::steady_clock::time_point FrameRunner::submit(Frame frame, const SubmitOptions& options) {
    RenderGraph& graph = *frame.graph;
    for (const std::string& name : options.disabledPasses) {
        const std::optional<uint32_t> pass = graph.findPass(name);
        if (!pass) {
            if (!options.unknownPassIsError) continue;
            std::string names;
            for (const PassDecl& p : graph.declaration().passes) names += (names.empty() ? "" : ", ") + p.name;
            throw UserError("cannot disable pass '" + name + "': no such pass (passes: " + names + ")");
        }
        if (const std::string& why = graph.declaration().passes[*pass].cannotBeDisabled; !why.empty()) {
            if (!options.unknownPassIsError) continue;  // the viewer: its panel shows the box greyed out
            throw UserError("cannot disable pass '" + name + "': " + why);
        }
        graph.setPassEnabled(name, false);
    }
    graph.compile({.memoryRequirements = deviceMemoryRequirements(mContext, graph.declaration())});
    vk::FrameSlot& slot = mFrames.begin();
    writeHostUploads(frame);
    TransientPool& transients = *mTransients[mFrames.currentSlot()];
    transients.realize(graph.declaration(), graph.compiled());
    if (options.serialPasses && options.present) throw UserError("serialized pass timing renders headless frames only");
    std::vector<double> serialMs;
    if (options.serialPasses) serialMs.assign(graph.declaration().passes.size(), -1.0);
    ExecutionRecord record = executeGraph({.context = mContext,
                                           .graph = graph,
                                           .imports = frame.imports,
                                           .transients = transients,
                                           .cmd = slot.cmd,
                                           .descriptors = *slot.descriptors,
                                           .timestamps = slot.timestamps.get(),
                                           .afterPass = options.serialPasses
                                                            ? std::function<void(uint32_t)>([&](uint32_t pass) {
                                                                  serialMs[pass] = mFrames.flushAndResume();
                                                              })
                                                            : nullptr,
                                           .emitBarriers = options.emitBarriers});
    std::vector<std::string> names;
    for (uint32_t pass : graph.compiled().order) names.push_back(graph.declaration().passes[pass].name);
    slot.completed = [this, record = std::move(record), order = graph.compiled().order, names = std::move(names),
                      serialMs = std::move(serialMs), precompute = std::make_pair(frame.precomputeBegin, frame.precomputeEnd)](vk::FrameSlot& done) {
        mCompletedTimings = record.timings(*done.timestamps);
        mCompletedTimings.serialMs = serialMs;
        mCompletedTimes.clear();
        for (size_t i = 0; i < order.size(); ++i)
            mCompletedTimes.push_back({names[i], order[i] < mCompletedTimings.gpuMs.size() ? mCompletedTimings.gpuMs[order[i]] : -1.0});
        if (precompute.first == precompute.second) return;
        mLastPrecomputeGpuMs = 0.0;
        for (uint32_t pass = precompute.first; pass < precompute.second; ++pass)
            mLastPrecomputeGpuMs += std::max(mCompletedTimings.gpuMs[pass], 0.0);
    };
    const auto submitted = std::chrono::steady_clock::now();
    std::vector<VkSemaphoreSubmitInfo> waits, signals;
    if (const PresentTarget* present = options.present; present && present->acquired)
        waits.push_back({.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                         .semaphore = present->acquired,
                         .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT});
    // Signalled when all the frame's work, the transition to PRESENT_SRC included, has completed
    // (at the end of the batch, so it stalls nothing).
    if (const PresentTarget* present = options.present; present && present->rendered)
        signals.push_back({.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                           .semaphore = present->rendered,
                           .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT});
    mFrames.submit(waits, signals);
    mLast = std::move(frame);
    return submitted;
}

void FrameRunner::writeHostUploads(Frame& frame) {
    // The slot's previous frame has completed (FrameRing::begin waited for it): its buffers are free.
    for (size_t i = 0; i < frame.hostUploads.size(); ++i) {
        const Frame::HostUpload& upload = frame.hostUploads[i];
        const ResourceDecl& resource = frame.graph->declaration().resources[upload.buffer.index];
        frame.imports.bind(upload.buffer, mHostUploads.write(mFrames.currentSlot(), i, upload.bytes, resource.buffer.size,
                                                             resource.name.c_str()));
    }
}

}  // namespace candela
