#pragma once
// Measuring frames against the calibration pass (passes/diagnostics/calibration_pass.h), shared by
// `bench` and `scale-report`: frames and calibration runs interleaved, so that the machine's drift
// affects both alike; figures as medians and ratios to the calibration of the same run.

#include "render/renderer.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace candela::app {

struct FrameMeasurement {
    double firstFrameMs = 0.0;             // the first warm-up frame, wall time of the call (upload, pipelines, IBL...)
    std::vector<double> frameMs;           // submit to fence, per frame
    std::vector<double> cpuMs;             // building, compiling and recording, per frame
    std::vector<double> calibrationMs, calibrationGpuMs;
    std::map<std::string, std::vector<double>> passGpuMs;
    // Per pass, from a few more frames run with RenderSettings::serialPasses: wall time of the
    // pass submitted and waited for alone (what a CPU device's timestamps cannot show).
    std::map<std::string, std::vector<double>> passSerialMs;
    std::vector<std::string> passOrder;    // every pass seen, in the order first met
    passes::DrawStats drawStats;           // of the last frame
    std::vector<std::string> explain;      // Renderer::explain() of the last frame (not of a calibration run)
};

// Two warm-up frames (pipelines, transient pools, the scene's upload), then `frames` frames each
// followed by a calibration pass at the same size, then `serialFrames` frames with serialized
// passes (passSerialMs); `beforeFrame(i)` runs before frame i (e.g. to pose an animation; not
// before the serialized ones). Precondition: frames ≥ 1.
FrameMeasurement measureFrames(Renderer& renderer, const RenderSettings& settings, uint32_t frames,
                               const std::function<void(uint32_t)>& beforeFrame = {}, uint32_t serialFrames = 0);

// Frames run as the viewer runs them (Renderer::renderToTarget, up to the renderer's frames in
// flight), presented into an offscreen image instead of a window: how often a frame ends and how
// far the CPU's building and recording overlapped the GPU's work.
struct InFlightMeasurement {
    std::vector<double> frameMs;   // from the return of one renderToTarget to the next (the viewer's frame time)
    double wallMsPerFrame = 0.0;   // all frames, until the GPU finished the last, divided by their number
    vk::FrameRingStats ring;       // over the measured frames (submits, overlapping submits, blocking waits)
    uint64_t completionWaits = 0;  // waits for the frame just submitted, over the measured frames
};

// Two warm-up frames (the IBL precompute among them), then `frames` frames into an offscreen RGBA8
// image of the settings' size. Precondition: frames ≥ 1.
InFlightMeasurement measureFramesInFlight(Renderer& renderer, vk::Context& context, const RenderSettings& settings,
                                          uint32_t frames);

}  // namespace candela::app
