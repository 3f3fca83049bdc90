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
#include "ibl/sheen_lut.h"
#include "ibl/ibl_settings.h"
#include "passes/calibration_pass.h"
#include "passes/encode_pass.h"
#include "passes/forward_pass.h"
#include "passes/pattern_pass.h"
#include "passes/skin_morph_pass.h"
#include "passes/skybox_pass.h"
#include "passes/tonemap_pass.h"
#include "passes/transmission_background_pass.h"
#include "scene/camera.h"
#include "scene/gpu_scene.h"
#include "scene/scene_pose.h"
#include "shader/parameter_registry.h"
#include "vk/buffer.h"
#include "vk/frame.h"
#include "vk/msaa.h"

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// Which camera looks at the scene: a glTF camera, or the orbit camera (framing the scene bounds
// unless the distance or target is given).
struct CameraSettings {
    std::optional<uint32_t> gltfCamera;     // --camera INDEX
    std::optional<glm::vec3> orbit;         // --camera-orbit θ°,φ°,r (r ≤ 0: frame the bounds)
    std::optional<glm::vec3> target;        // --target X,Y,Z
    float fovYDegrees = 45.0f;              // --fov
    // An interactive camera (the viewer's), used as is; overrides the three above.
    std::optional<scene::OrbitCamera> orbitCamera;
    // Moves the image centre right by this many NDC units (off-axis projection): the viewer
    // centres the scene in the part of the window its side panel leaves free.
    float lensShiftX = 0.0f;
};

struct RenderSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    bool floatOutput = false;  // capture linear HDR (EXR/PFM) instead of 8-bit sRGB (PNG)
    // The scene to draw; null renders the foundation's procedural test pattern instead.
    const scene::Scene* scene = nullptr;
    // The scene as its animations pose it this frame (a pose of `scene`, owned by the caller);
    // null, or a pose that animates nothing, draws the loaded rest pose with the static draw data.
    const scene::ScenePose* pose = nullptr;
    CameraSettings camera;
    passes::ShadingModel shading = passes::ShadingModel::Pbr;
    // A debug view of the forward pass instead of the shaded image (a variant of the frame graph:
    // no skybox; data views are tonemapped linearly at exposure 0, see passes::DebugView).
    passes::DebugView debugView = passes::DebugView::None;
    // A scene without punctual lights gets a default key and fill light (directional), so that
    // it is visible before image-based lighting exists; false leaves it unlit.
    bool defaultLights = true;
    // The scene's own punctual lights (KHR_lights_punctual); false leaves them out, for comparisons
    // under image-based lighting alone — the scene then counts as one without lights.
    bool sceneLights = true;
    passes::TonemapSettings tonemap;
    // Frustum culling and the level-of-detail error (--lod-error, --cull).
    passes::DrawSelection drawSelection;
    // Specular anti-aliasing (--specular-aa).
    passes::ShadingOptions shadingOptions;
    // MSAA sample count of the draw targets (--msaa: 1, 2, 4 or 8); nullopt: the device default
    // (vk::chooseMsaa). Clamped to what the device supports, with a warning.
    std::optional<uint32_t> msaa;
    // Image-based lighting: the environment (null: none; read during the call only, hashed when the
    // pointer or the quality changes), what to precompute and how to look it up.
    const scene::Environment* environment = nullptr;
    ibl::IblQuality iblQuality;
    ibl::IblLook ibl;
    std::filesystem::path iblCacheDir;  // empty: no on-disk cache
    float patternExposure = 1.0f;  // test pattern only
    std::vector<std::string> disabledPasses;  // runtime toggles by pass name
    // false: a disabled pass this frame does not declare is ignored (the viewer keeps toggles
    // across scene and environment changes); true: it is a UserError (the command line).
    bool unknownPassIsError = true;
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

// A presentable image to render into (a vk::Swapchain image): the tonemap writes it, the overlay
// draws over it, and it ends in PRESENT_SRC_KHR. The frame waits on `acquired` before writing it
// and signals `rendered` when done.
struct PresentTarget {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkSemaphore acquired = VK_NULL_HANDLE;
    VkSemaphore rendered = VK_NULL_HANDLE;
};

// Adds passes that draw over the finished 8-bit frame (the UI); returns the target's new version.
using OverlayFn = std::function<graph::TextureId(graph::RenderGraph& graph, graph::TextureId target)>;

// GPU time of one pass of a completed frame.
struct PassTime {
    std::string name;
    double gpuMs = -1.0;  // negative: the pass did not run or was not measured
};

struct FrameTiming {
    double cpuMs = 0.0;           // CPU wall time to build, compile and record the frame and submit it
    double submitWaitMs = 0.0;    // CPU wall time from submit to the fence
    graph::GraphTimings timings;  // per declared pass of that frame's graph
};

// The last IBL precompute: the frame that ran it, from the start of its building to its fence, and
// the GPU time of its precompute passes. Negative before any.
struct PrecomputeTime {
    double frameMs = -1.0;
    double gpuMs = -1.0;
};

// One frame as built: its graph with the Vulkan objects bound to the imported resources, the
// handles of its results and what it scheduled. The scene and pattern entry points build one with
// Renderer's beginFrame (precomputeIbl and renderCalibration declare their few passes into a fresh
// one), add their ending (readback, overlay, export) and submit it; the renderer then keeps it as
// the last frame, for export, --explain and finishing the IBL precompute.
struct Frame {
    std::unique_ptr<graph::RenderGraph> graph = std::make_unique<graph::RenderGraph>();
    graph::ImportBindings imports;
    graph::TextureId hdr;  // linear HDR (RGBA16F): the scene after forward and skybox, or the test pattern
    graph::TextureId ldr;  // the 8-bit image: tonemapped scene, or encoded pattern
    bool ibl = false;      // image-based lighting: the maps are imported
    bool sheenLut = false; // the sheen LUT is imported (a material has a sheen)
    bool transmission = false;  // transmissive draws: transmission_background and forward_transmission
    bool skybox = false;
    passes::DebugView debugView = passes::DebugView::None;
    // The IBL precompute passes added: declared pass indices [precomputeBegin, precomputeEnd).
    uint32_t precomputeBegin = 0, precomputeEnd = 0;
    // What --explain says of the scene (variants, lights, IBL, what was left out), besides culled passes.
    std::vector<std::string> notes;
    // Data the CPU makes for this frame alone (the posed draws of an animated scene): each is
    // copied, once the frame slot is free, into that slot's own host-visible buffer, which is
    // then bound to the imported handle. The submit makes the host writes visible to the device.
    struct HostUpload {
        graph::BufferId buffer;
        std::vector<std::byte> bytes;
    };
    std::vector<HostUpload> hostUploads;
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
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
    // Renders one frame of the scene into `target` (settings.width × height must be its size) and
    // submits it; the caller presents. Without an environment it does not wait for the GPU (up to
    // framesInFlight frames are in flight); a frame with image-based lighting is waited for, so the
    // maps learn of a completed precompute. With `screenshot`, the finished image (overlay
    // included) is also read back into it as sRGB RGBA8 (this waits for the frame). Throws
    // UserError as capture() does.
    void renderToTarget(const RenderSettings& settings, const PresentTarget& target, const OverlayFn& overlay,
                        CapturedFrame* screenshot = nullptr);
    // Per-pass GPU times of the latest frame known to be complete, in execution order.
    const std::vector<PassTime>& completedPassTimes() const { return mCompletedTimes; }
    // What the forward passes of the last frame drew (scene vs submitted draws and triangles,
    // state changes; the latter once the frame is recorded).
    const passes::DrawStats& drawStats() const { return mForward.drawStats(); }
    // The sample count `requested` (RenderSettings::msaa) gives on this device, and why.
    vk::MsaaChoice msaa(std::optional<uint32_t> requested) const;
    // The last IBL precompute that completed.
    const PrecomputeTime& lastPrecompute() const { return mLastPrecompute; }
    // The GPU time of the pass named `pass` in that frame; negative if it did not run there.
    double completedPassMs(std::string_view pass) const;
    // Waits for every frame in flight.
    void waitIdle() { mFrames.waitIdle(); }
    // The Scene object last drawn was replaced in place (same address, new contents): the next
    // frame uploads it anew. Waits for the frames in flight.
    void sceneReplaced();
    // After shaders were replaced (hot reload): the frame passes rebuild their pipelines at their
    // next use by themselves; a replaced IBL shader also discards the maps, so that the next frame
    // runs the precompute with it.
    void shadersReplaced(const std::vector<std::string>& names);
    // Runs the IBL precompute again in the next frame (not from the cache), for the environment and
    // quality of the last frame.
    void recomputeIbl();

    // Runs the IBL precompute passes alone for `environment` at `quality` — always, even when the
    // maps are current; no cache — and waits. The maps then serve the following frames (read them
    // back through iblMaps()). Throws UserError for an invalid quality.
    FrameTiming precomputeIbl(const scene::Environment& environment, const ibl::IblQuality& quality);
    // Gives the ground truth (RenderSettings::ibl.referenceSamples > 0) its environment; see
    // ibl::IblMaps::setReferenceEnvironment. Waits for the GPU.
    void setReferenceEnvironment(const scene::Environment& environment);
    // Runs the calibration pass alone at width × height (see passes/calibration_pass.h).
    FrameTiming renderCalibration(uint32_t width, uint32_t height);

    // The view the settings select for `scene` at `aspect` (width / height). With an animated
    // `pose`, glTF cameras are where the pose puts them and framing contains the whole animation.
    static scene::ViewSetup resolveView(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                        const scene::ScenePose* pose = nullptr);

    // The graph of the last frame (declaration and compiled result), for export and inspection.
    const graph::RenderGraph& lastGraph() const { return *mLast.graph; }
    // The key and fill lights added to scenes without lights (see RenderSettings::defaultLights).
    static std::vector<scene::Light> defaultLights();
    // Which passes and variants the last frame left out and why (`--explain`).
    std::vector<std::string> explain() const;
    // Transient-pool rebuilds so far (tests: stays constant while the graph is unchanged).
    uint32_t transientRebuilds() const;
    // The reflected shader parameters of the recent frames and the user's values for them: the
    // forward, skybox and tonemap push constants, and each light and material ("forward",
    // "Lights[i]" / "Materials[i]"). Values set here apply from the next frame.
    shader::ParameterRegistry& parameters() { return mParameters; }
    // The image-based-lighting maps (tests and reports read them back).
    ibl::IblMaps& iblMaps() { return *mIbl; }

private:
    // The start every entry point shares: checks the settings, uploads a changed scene or
    // environment and declares the frame's passes (the scene, or the test pattern without one) in a
    // new graph. With `present`, the tonemap writes the imported presentable image; otherwise a
    // new transient. Throws UserError as capture() does.
    Frame beginFrame(const RenderSettings& settings, const PresentTarget* present = nullptr);
    void buildSceneGraph(Frame& frame, const RenderSettings& settings, std::optional<graph::TextureId> target);
    void buildPatternGraph(Frame& frame, const RenderSettings& settings);
    void prepareScene(const RenderSettings& settings);
    void prepareEnvironment(const RenderSettings& settings);
    // Runs the scene's lights and materials through the parameter registry; rewrites their buffers
    // (after waiting for the GPU) when the user changed one.
    void applySceneParameters();
    // Waits for the GPU and gives the maps this environment and quality (see IblMaps::setEnvironment).
    void useEnvironment(const scene::Environment* environment, const ibl::IblQuality& quality,
                        const std::filesystem::path& cacheDir, bool force);
    // Applies the settings' pass toggles, compiles the frame's graph, records it into the next frame
    // slot and submits it (waiting on and signalling the present target's semaphores if given); it
    // becomes the last frame. Returns when it was submitted.
    std::chrono::steady_clock::time_point submit(Frame frame, const RenderSettings& settings,
                                                 const PresentTarget* present = nullptr);
    // submit(), then waits for the frame and finishes it.
    FrameTiming execute(Frame frame, const RenderSettings& settings);
    // After the last frame completed: the IBL maps take over what its precompute computed, and its
    // time is recorded.
    void finishFrame();
    // Imports the IBL maps into `frame`, with the precompute passes when they are pending (and the
    // ground truth's inputs with `reference`); marks the frame as lit by them and records which
    // declared passes the precompute added. Precondition: the maps have an environment.
    passes::IblHandles addIblMaps(Frame& frame, bool reference);
    // Imports the readback buffer, (re)created for `bytes`, into `frame` (final state: host read).
    graph::BufferId importReadback(Frame& frame, VkDeviceSize bytes);
    // Adds the skin_morph pass for the pose's deformed draws (with this frame's joint matrices and
    // non-zero morph weights as host uploads); nullopt, and an --explain note, when none is deformed.
    std::optional<passes::ForwardPass::DeformedVertices> addSkinMorph(Frame& frame, const scene::ScenePose& pose);
    // Declares `bytes` as a storage buffer the CPU writes for this frame (Frame::hostUploads).
    graph::BufferId addHostUpload(Frame& frame, std::string name, std::vector<std::byte> bytes);
    // Copies the frame's host uploads into the current slot's buffers and binds them.
    void writeHostUploads(Frame& frame);
    // New, empty IBL maps (after waiting for the frames in flight).
    void resetIblMaps();

    vk::Context& mContext;
    vk::FrameRing mFrames;
    std::vector<std::unique_ptr<graph::TransientPool>> mTransients;  // one per frame slot
    std::vector<std::vector<vk::Buffer>> mHostBuffers;                // per frame slot, per host upload
    passes::PatternPass mPattern;
    passes::EncodePass mEncode;
    passes::ForwardPass mForward;
    passes::TonemapPass mTonemap;
    std::unique_ptr<ibl::IblMaps> mIbl;
    std::unique_ptr<ibl::SheenLut> mSheenLut;  // created with the first scene that has a sheen
    std::unique_ptr<passes::SkyboxPass> mSkybox;  // created with the first environment
    std::unique_ptr<passes::TransmissionBackgroundPass> mTransmissionBackground;  // created with the first transmissive draw
    std::unique_ptr<passes::CalibrationPass> mCalibration;  // created by the first renderCalibration
    const scene::Scene* mUploaded = nullptr;
    bool mUploadedDefaultLights = false;
    bool mUploadedSceneLights = true;
    std::unique_ptr<scene::GpuScene> mGpuScene;
    // The rest pose of an uploaded scene with skins or morph targets, drawn when a frame brings no
    // pose of its own (skinned meshes are placed by their joints even at rest).
    std::unique_ptr<scene::ScenePose> mRestPose;
    std::unique_ptr<passes::SkinMorphPass> mSkinMorph;  // created with the first deformed frame
    // What mIbl was last set up with (the environment is re-hashed only when these change).
    const scene::Environment* mEnvironment = nullptr;
    ibl::IblQuality mIblQuality;
    std::filesystem::path mIblCacheDir;
    shader::ParameterRegistry mParameters;
    vk::Buffer mReadback;
    std::vector<PassTime> mCompletedTimes;
    graph::GraphTimings mCompletedTimings;  // of the latest completed frame, by declared pass
    PrecomputeTime mLastPrecompute;
    Frame mLast;  // the last frame submitted
    std::optional<uint32_t> mMsaaWarnedFor;  // the clamped request last warned of (once per request)
};

}  // namespace candela
