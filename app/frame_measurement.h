#pragma once
// Measuring frames against the calibration pass (passes/calibration_pass.h), shared by `bench` and
// `scale-report`: frames and calibration runs interleaved, so that the machine's drift affects both
// alike; figures as medians and ratios to the calibration of the same run.

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
    std::vector<std::string> passOrder;    // every pass seen, in the order first met
    passes::DrawStats drawStats;           // of the last frame
    std::vector<std::string> explain;      // Renderer::explain() of the last frame (not of a calibration run)
};

// Two warm-up frames (pipelines, transient pools, the scene's upload), then `frames` frames each
// followed by a calibration pass at the same size; `beforeFrame(i)` runs before frame i (e.g. to
// pose an animation). Precondition: frames ≥ 1.
FrameMeasurement measureFrames(Renderer& renderer, const RenderSettings& settings, uint32_t frames,
                               const std::function<void(uint32_t)>& beforeFrame = {});

}  // namespace candela::app
