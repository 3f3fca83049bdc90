#pragma once
// Renderer: builds the frame's render graph from the scene and the settings, compiles and executes
// it on the device, and reads the result back (headless capture). Owns the passes' pipelines, the
// uploaded scene, the frames in flight with their transient pools, and the readback buffer.
//
// Scene frame graph:  [ibl precompute, only when the environment or its quality changed] →
//                     forward (HDR + depth) → [skybox] → tonemap (8-bit) → readback.
// Test-pattern graph: pattern (compute, HDR) → encode (graphics, 8-bit sRGB) → readback.
// For a float capture the readback reads the HDR image directly, so tonemap/encode are culled.

#include "graph/graph_executor.h"
#include "graph/render_graph.h"
#include "ibl/ibl_maps.h"
#include "ibl/ibl_settings.h"
#include "passes/calibration_pass.h"
#include "passes/encode_pass.h"
#include "passes/forward_pass.h"
#include "passes/pattern_pass.h"
#include "passes/skybox_pass.h"
#include "passes/tonemap_pass.h"
#include "scene/camera.h"
#include "scene/gpu_scene.h"
#include "vk/buffer.h"
#include "vk/frame.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

// Which camera looks at the scene: a glTF camera, or the orbit camera (framing the scene bounds
// unless the distance or target is given).
struct CameraSettings {
    std::optional<uint32_t> gltfCamera;     // --camera INDEX
    std::optional<glm::vec3> orbit;         // --camera-orbit θ°,φ°,r (r ≤ 0: frame the bounds)
    std::optional<glm::vec3> target;        // --target X,Y,Z
    float fovYDegrees = 45.0f;              // --fov
};

struct RenderSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    bool floatOutput = false;  // capture linear HDR (EXR/PFM) instead of 8-bit sRGB (PNG)
    // The scene to draw; null renders the foundation's procedural test pattern instead.
    const scene::Scene* scene = nullptr;
    CameraSettings camera;
    passes::ShadingModel shading = passes::ShadingModel::Pbr;
    // A scene without punctual lights gets a default key and fill light (directional), so that
    // it is visible before image-based lighting exists; false leaves it unlit.
    bool defaultLights = true;
    passes::TonemapSettings tonemap;
    // Image-based lighting: the environment (null: none; read during the call only, hashed when the
    // pointer or the quality changes), what to precompute and how to look it up.
    const scene::Environment* environment = nullptr;
    ibl::IblQuality iblQuality;
    ibl::IblLook ibl;
    std::filesystem::path iblCacheDir;  // empty: no on-disk cache
    float patternExposure = 1.0f;  // test pattern only
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

struct FrameTiming {
    double submitWaitMs = 0.0;    // CPU wall time from submit to the fence
    graph::GraphTimings timings;  // per declared pass of that frame's graph
};

class Renderer {
public:
    // Precondition: `context` outlives the renderer.
    explicit Renderer(vk::Context& context, uint32_t framesInFlight = 2);
    ~Renderer();

    // Throws UserError if the size is 0 or beyond the device's maxImageDimension2D.
    void validateSettings(const RenderSettings& settings) const;

    // Renders one frame and reads it back (waits for the GPU). A scene is uploaded on first use
    // and again whenever a different Scene object is passed. Throws UserError for a bad camera
    // choice or an unknown pass name.
    CapturedFrame capture(const RenderSettings& settings);

    // Renders one frame without reading it back (benchmarks): the 8-bit result is an exported
    // output of the graph, as a swapchain image would be. Waits for the GPU.
    FrameTiming renderFrame(const RenderSettings& settings);
    // Runs the IBL precompute passes alone for `environment` at `quality` — always, even when the
    // maps are current; no cache — and waits. The maps then serve the following frames (read them
    // back through iblMaps()). Throws UserError for an invalid quality.
    FrameTiming precomputeIbl(const scene::Environment& environment, const ibl::IblQuality& quality);
    // Gives the ground truth (RenderSettings::ibl.referenceSamples > 0) its environment; see
    // ibl::IblMaps::setReferenceEnvironment. Waits for the GPU.
    void setReferenceEnvironment(const scene::Environment& environment);
    // Runs the calibration pass alone at width × height (see passes/calibration_pass.h).
    FrameTiming renderCalibration(uint32_t width, uint32_t height);

    // The view the settings select for `scene` at `aspect` (width / height).
    static scene::ViewSetup resolveView(const scene::Scene& scene, const CameraSettings& camera, float aspect);

    // The graph of the last frame (declaration and compiled result), for export and inspection.
    const graph::RenderGraph& lastGraph() const { return *mGraph; }
    // The key and fill lights added to scenes without lights (see RenderSettings::defaultLights).
    static std::vector<scene::Light> defaultLights();
    // Which passes and variants the last frame left out and why (`--explain`).
    std::vector<std::string> explain() const;
    // Transient-pool rebuilds so far (tests: stays constant while the graph is unchanged).
    uint32_t transientRebuilds() const;
    // The image-based-lighting maps (tests and reports read them back).
    ibl::IblMaps& iblMaps() { return mIbl; }

private:
    // Declare the frame's passes; return the 8-bit result and set mHdr to the HDR image.
    graph::TextureId buildSceneGraph(graph::RenderGraph& graph, const RenderSettings& settings,
                                     graph::ImportBindings& imports);
    graph::TextureId buildPatternGraph(graph::RenderGraph& graph, const RenderSettings& settings);
    void prepareScene(const RenderSettings& settings);
    void prepareEnvironment(const RenderSettings& settings);
    // Waits for the GPU and gives the maps this environment and quality (see IblMaps::setEnvironment).
    void useEnvironment(const scene::Environment* environment, const ibl::IblQuality& quality,
                        const std::filesystem::path& cacheDir, bool force);
    static void applyToggles(graph::RenderGraph& graph, const std::vector<std::string>& disabledPasses);
    FrameTiming execute(graph::RenderGraph& graph, const graph::ImportBindings& imports, bool emitBarriers);

    vk::Context& mContext;
    vk::FrameRing mFrames;
    std::vector<std::unique_ptr<graph::TransientPool>> mTransients;  // one per frame slot
    passes::PatternPass mPattern;
    passes::EncodePass mEncode;
    passes::ForwardPass mForward;
    passes::TonemapPass mTonemap;
    ibl::IblMaps mIbl;
    std::unique_ptr<passes::SkyboxPass> mSkybox;  // created with the first environment
    std::unique_ptr<passes::CalibrationPass> mCalibration;  // created by the first renderCalibration
    graph::TextureId mHdr;  // HDR image of the graph being built
    const scene::Scene* mUploaded = nullptr;
    bool mUploadedDefaultLights = false;
    std::unique_ptr<scene::GpuScene> mGpuScene;
    // What mIbl was last set up with (the environment is re-hashed only when these change).
    const scene::Environment* mEnvironment = nullptr;
    ibl::IblQuality mIblQuality;
    std::filesystem::path mIblCacheDir;
    bool mIblInGraph = false;   // the last scene graph used image-based lighting
    bool mSkyboxInGraph = false;
    vk::Buffer mReadback;
    std::unique_ptr<graph::RenderGraph> mGraph;
};

}  // namespace candela
