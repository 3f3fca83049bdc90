#include "frame_measurement.h"

#include "vk/image.h"

#include <algorithm>
#include "stopwatch.h"

namespace candela::app {

FrameMeasurement measureFrames(Renderer& renderer, const RenderSettings& settings, uint32_t frames,
                               const std::function<void(uint32_t)>& beforeFrame, uint32_t serialFrames) {
    FrameMeasurement out;
    for (int i = 0; i < 2; ++i) {
        const auto start = Clock::now();
        renderer.renderFrame(settings);
        if (i == 0) out.firstFrameMs = msSince(start);
        renderer.renderCalibration(settings.width, settings.height);
    }
    for (uint32_t i = 0; i < frames; ++i) {
        if (beforeFrame) beforeFrame(i);
        const FrameTiming frame = renderer.renderFrame(settings);
        out.frameMs.push_back(frame.submitWaitMs);
        out.cpuMs.push_back(frame.cpuMs);
        out.drawStats = renderer.drawStats();
        if (i + 1 == frames) out.explain = renderer.explain();
        const graph::GraphDecl& decl = renderer.lastGraph().declaration();
        for (uint32_t pass : renderer.lastGraph().compiled().order) {
            const std::string& name = decl.passes[pass].name;
            // Passes can come and go between frames (skin_morph with the pose): list every one seen.
            if (std::find(out.passOrder.begin(), out.passOrder.end(), name) == out.passOrder.end()) out.passOrder.push_back(name);
            if (frame.timings.gpuMs[pass] >= 0.0) out.passGpuMs[name].push_back(frame.timings.gpuMs[pass]);
        }
        const FrameTiming calibration = renderer.renderCalibration(settings.width, settings.height);
        out.calibrationMs.push_back(calibration.submitWaitMs);
        const uint32_t calibrationPass = *renderer.lastGraph().findPass("calibration");
        if (calibration.timings.gpuMs[calibrationPass] >= 0.0) out.calibrationGpuMs.push_back(calibration.timings.gpuMs[calibrationPass]);
    }
    RenderSettings serial = settings;
    serial.serialPasses = true;
    for (uint32_t i = 0; i < serialFrames; ++i) {
        const FrameTiming frame = renderer.renderFrame(serial);
        const graph::GraphDecl& decl = renderer.lastGraph().declaration();
        for (uint32_t pass : renderer.lastGraph().compiled().order)
            if (frame.timings.serialMs[pass] >= 0.0) out.passSerialMs[decl.passes[pass].name].push_back(frame.timings.serialMs[pass]);
    }
    return out;
}

InFlightMeasurement measureFramesInFlight(Renderer& renderer, vk::Context& context, const RenderSettings& settings,
                                          uint32_t frames) {
    constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_UNORM;
    const vk::Image image(context, {.width = settings.width,
                                    .height = settings.height,
                                    .format = kFormat,
                                    .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                    .name = "offscreen target"});
    // No presentation engine: no semaphores; the image rests as the frame's last write left it.
    const PresentTarget target{.image = image.handle(),
                               .view = image.view(),
                               .format = kFormat,
                               .finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    for (int i = 0; i < 2; ++i) renderer.renderToTarget(settings, target, {});
    renderer.waitIdle();
    const vk::FrameRingStats ring = renderer.frameRingStats();
    const uint64_t completionWaits = renderer.completionWaits();
    InFlightMeasurement out;
    const auto start = Clock::now();
    auto previous = start;
    for (uint32_t i = 0; i < frames; ++i) {
        renderer.renderToTarget(settings, target, {});
        const auto now = Clock::now();
        out.frameMs.push_back(std::chrono::duration<double, std::milli>(now - previous).count());
        previous = now;
    }
    out.ring = renderer.frameRingStats();
    renderer.waitIdle();
    out.wallMsPerFrame = msSince(start) / frames;
    out.ring.submits -= ring.submits;
    out.ring.overlappedSubmits -= ring.overlappedSubmits;
    out.ring.blockingWaits -= ring.blockingWaits;
    out.ring.blockedMs -= ring.blockedMs;
    out.completionWaits = renderer.completionWaits() - completionWaits;
    return out;
}

}  // namespace candela::app
