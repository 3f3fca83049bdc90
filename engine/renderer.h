#pragma once
// Renderer: builds the frame's render graph from the settings, compiles and executes it on the
// device, and reads the result back (headless capture). Owns the passes' pipelines, the frames in
// flight with their transient pools, and the readback buffer.
//
// The foundation's frame graph:  pattern (compute, HDR) → encode (graphics, 8-bit sRGB) → readback.
// For a float capture the readback reads the HDR image directly, so encode is culled.

#include "graph/graph_executor.h"
#include "graph/render_graph.h"
#include "passes/encode_pass.h"
#include "passes/pattern_pass.h"
#include "vk/buffer.h"
#include "vk/frame.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

struct RenderSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    bool floatOutput = false;  // capture linear HDR (EXR/PFM) instead of 8-bit sRGB (PNG)
    float exposure = 1.0f;
    std::vector<std::string> disabledPasses;  // runtime toggles by pass name
    bool emitBarriers = true;  // testing hook: false records no barriers (sync validation must object)
};

struct CapturedFrame {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;   // !floatOutput: sRGB-encoded RGBA, top row first
    std::vector<float> rgba32f;   // floatOutput: linear RGBA, top row first
    graph::GraphTimings timings;  // per declared pass; negative where not run/measured
    double submitWaitMs = 0.0;    // CPU wall time from submit to the fence
    double readbackMs = 0.0;      // CPU time to copy (and convert) the pixels out of the buffer
};

class Renderer {
public:
    // Precondition: `context` outlives the renderer.
    explicit Renderer(vk::Context& context, uint32_t framesInFlight = 2);
    ~Renderer();

    // Throws UserError if the size is 0 or beyond the device's maxImageDimension2D.
    void validateSettings(const RenderSettings& settings) const;

    // Renders one frame and reads it back (waits for the GPU).
    CapturedFrame capture(const RenderSettings& settings);

    // The graph of the last frame (declaration and compiled result), for export and inspection.
    const graph::RenderGraph& lastGraph() const { return *mGraph; }
    // Transient-pool rebuilds so far (tests: stays constant while the graph is unchanged).
    uint32_t transientRebuilds() const;

private:
    vk::Context& mContext;
    vk::FrameRing mFrames;
    std::vector<std::unique_ptr<graph::TransientPool>> mTransients;  // one per frame slot
    passes::PatternPass mPattern;
    passes::EncodePass mEncode;
    vk::Buffer mReadback;
    std::unique_ptr<graph::RenderGraph> mGraph;
};

}  // namespace candela
