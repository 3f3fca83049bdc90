#pragma once
// Renderer: the facade the commands, the viewer and the tests use. It runs one frame per call:
// prepares the scene state (uploads, environment: SceneState), has the FrameBuilder declare the
// frame's passes, adds the ending the call needs (readback, overlay, export), and has the
// FrameRunner compile, record and submit it; a capture reads the result back (Readback).
//
// What a scene frame declares is FrameBuilder's (frame_builder.h: facts → plan → passes); the test
// pattern is pattern → encode. A capture ends in a readback, which for a float capture reads the
// HDR image directly, so tonemap/encode are culled.

#include "render/frame.h"
#include "render/frame_builder.h"
#include "render/frame_runner.h"
#include "render/readback.h"
#include "render/render_settings.h"
#include "render/scene_state.h"
#include "shader/parameter_registry.h"
#include "vk/msaa.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

struct CapturedFrame {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;   // !floatOutput: sRGB-encoded RGBA, top row first
    std::vector<float> rgba32f;   // floatOutput: linear RGBA, top row first
    // RenderSettings::outputs besides colour (in options::PixelOutput order); rgba8 and rgba32f
    // are empty when colour was not asked for.
    std::vector<CapturedOutput> outputs;
    graph::GraphTimings timings;  // per declared pass; negative where not run/measured
    double submitWaitMs = 0.0;    // CPU wall time from submit to the fence
    double readbackMs = 0.0;      // CPU time to copy (and convert) the pixels out of the buffer
};

// Adds passes that draw over the finished 8-bit frame (the UI); returns the target's new version.
using OverlayFn = std::function<graph::TextureId(graph::RenderGraph& graph, graph::TextureId target)>;

// How the renderer runs frames, whatever they show.
struct RendererOptions {
    uint32_t framesInFlight = 2;
    // false: a disabled pass (RenderSettings::disabledPasses) that a frame does not declare, or
    // that cannot be switched off, is ignored (the viewer keeps toggles across scene and
    // environment changes); true: UserError.
    bool unknownPassIsError = true;
    bool emitBarriers = true;  // testing hook: false records no barriers (sync validation must object)
};

class Renderer {
public:
    // Precondition: `context` outlives the renderer.
    explicit Renderer(vk::Context& context, RendererOptions options = {});
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
    // submits it; the caller presents. It does not wait for the GPU (up to framesInFlight frames
    // are in flight, with an environment or without) unless the frame computed persistent maps
    // (Frame::computesMaps: the IBL precompute after an environment change, the sheen LUT once),
    // which is waited for so that the maps are current for the next frame. With `screenshot`, the
    // finished image (overlay included) is also read back into it as sRGB RGBA8 (this waits for
    // the frame). Throws UserError as capture() does.
    void renderToTarget(const RenderSettings& settings, const PresentTarget& target, const OverlayFn& overlay,
                        CapturedFrame* screenshot = nullptr);
    // Per-pass GPU times of the latest frame known to be complete, in execution order.
    const std::vector<PassTime>& completedPassTimes() const { return mRunner.completedPassTimes(); }
    // What the forward passes of the last frame drew (scene vs submitted draws and triangles,
    // state changes; the latter once the frame is recorded).
    const passes::DrawStats& drawStats() const { return mBuilder.drawStats(); }
    // The sample count `requested` (RenderSettings::msaa) gives on this device, and why.
    vk::MsaaChoice msaa(std::optional<uint32_t> requested) const;
    // Device memory of the textures of the scene last drawn (GpuScene::textureBytes); 0 before a frame.
    VkDeviceSize sceneTextureBytes() const;
    // The last IBL precompute that completed.
    const PrecomputeTime& lastPrecompute() const { return mLastPrecompute; }
    // How many IBL precomputes have completed.
    uint32_t precomputeCount() const { return mPrecomputes; }
    // Waits for the pipelines queued ahead of use (RenderSettings::precompile) to be built
    // (benchmarks: so that a measurement leaves them out).
    void finishPipelineBuilds() { mBuilder.finishPipelineBuilds(); }
    // RendererOptions::unknownPassIsError from the next frame on (bench's debug-view switch: its
    // frame need not declare every pass the measured frames had switched off).
    void setUnknownPassIsError(bool error) { mOptions.unknownPassIsError = error; }
    // The GPU time of the pass named `pass` in that frame; negative if it did not run there.
    double completedPassMs(std::string_view pass) const { return mRunner.completedPassMs(pass); }
    // Waits for every frame in flight.
    void waitIdle() { mRunner.waitIdle(); }
    // How often the renderer waited for the frame it had just submitted (FrameRunner::completionWaits),
    // and how far the CPU ran ahead of the GPU (submits while an earlier frame ran, blocking waits).
    uint64_t completionWaits() const { return mRunner.completionWaits(); }
    const vk::FrameRingStats& frameRingStats() const { return mRunner.ringStats(); }
    // The Scene object last drawn was replaced in place (same address, new contents): the next
    // frame uploads it anew. Waits for the frames in flight.
    void sceneReplaced();
    // The same for the Environment object last used (its maps made anew by the next frame).
    void environmentReplaced();
    // Does now what the next frame with `settings` would do first: uploads its scene unless it is
    // uploaded (waiting for the copies) and gives the maps its environment (their precompute runs
    // in that frame). Lets a caller time the upload apart from the frame. Throws UserError as
    // capture() does. Precondition: settings.scene is set.
    void upload(const RenderSettings& settings);
    // Gives the maps `environment` for frames of `quality` with its IBL cache in `cacheDir`, as
    // upload() would after its scene: read from the cache, or their precompute set up for the next
    // frame. Lets a caller do it before it has the scene (while the scene loads); a scene with a
    // sheen asks for the maps again with the sheen's. Null `environment`: none.
    void prepareEnvironment(const assets::Environment* environment, const ibl::IblQuality& quality,
                            const std::filesystem::path& cacheDir);
    // Queues on the workers the builds of the pipelines a first frame of `settings` will take
    // whatever its scene (the tonemap's, for a scene without transmissive or blended draws:
    // FrameBuilder::prepareTonemapAhead), so that they compile while the scene loads. settings.scene
    // may be null. Nothing with --precompile off.
    void prepareFirstFrame(const RenderSettings& settings) { mBuilder.prepareTonemapAhead(settings, nullptr); }
    // Frees the device memory of the scene last drawn (after waiting for the frames in flight),
    // so that a run over many scenes holds one at a time; the next frame uploads its scene,
    // whatever its address. The environment's maps, the pipelines and the caches stay.
    void releaseScene();
    // What the device holds of the scene last uploaded; null before one or after releaseScene().
    const gpu_scene::GpuScene* uploadedScene() const { return mScene.hasGpuScene() ? &mScene.gpuScene() : nullptr; }
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
    FrameTiming precomputeIbl(const assets::Environment& environment, const ibl::IblQuality& quality);
    // Gives the ground truth (RenderSettings::ibl.referenceSamples > 0) its environment; see
    // ibl_maps::IblMaps::setReferenceEnvironment. Waits for the GPU.
    void setReferenceEnvironment(const assets::Environment& environment);
    // Runs the calibration pass alone at width × height (see passes/diagnostics/calibration_pass.h).
    FrameTiming renderCalibration(uint32_t width, uint32_t height);

    // The view the settings select for `scene` at `aspect` (width / height). With an animated
    // `pose`, glTF cameras are where the pose puts them and framing fits the pose as it stands.
    static scene::ViewSetup resolveView(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                        const pose::ScenePose* pose = nullptr) {
        return FrameBuilder::resolveView(scene, camera, aspect, pose);
    }
    // The orbit camera and the flags that reproduce the view (FrameBuilder::orbitCamera, cameraFlags).
    static scene::OrbitCamera orbitCamera(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                          const pose::ScenePose* pose = nullptr) {
        return FrameBuilder::orbitCamera(scene, camera, aspect, pose);
    }
    static std::string cameraFlags(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                   const pose::ScenePose* pose = nullptr) {
        return FrameBuilder::cameraFlags(scene, camera, aspect, pose);
    }

    // The graph of the last frame (declaration and compiled result), for export and inspection.
    const graph::RenderGraph& lastGraph() const { return *mRunner.last().graph; }
    // The key and fill lights added to scenes without lights (see RenderSettings::defaultLights).
    static std::vector<scene::Light> defaultLights() { return SceneState::defaultLights(); }
    // Which passes and variants the last frame left out and why (`--explain`).
    std::vector<std::string> explain() const;
    // The plan of the last frame (what it draws where, what it leaves out and why); null when the
    // last frame was no scene frame.
    const FramePlan* lastPlan() const { return mRunner.last().plan ? &*mRunner.last().plan : nullptr; }
    // What the last frame's draws asked of the shading programs; null when it was no scene frame.
    const passes::ShadingSummary* lastShading() const {
        return mRunner.last().shading ? &*mRunner.last().shading : nullptr;
    }
    // What the last frame's visibility path did (image, tiles, shading lists); null when the last
    // frame took the forward path or was no scene frame.
    const VisibilitySummary* lastVisibility() const {
        return mRunner.last().visibility ? &*mRunner.last().visibility : nullptr;
    }
    // What the last frame's pose animated besides its nodes (KHR_animation_pointer); empty when
    // nothing was, or the last frame was no scene frame.
    const PosedSummary& lastPosed() const { return mRunner.last().posed; }
    // What the last frame drew behind the scene: the sky (a skybox pass that ran, or composited by
    // the tonemap), the tonemap's solid background colour, or nothing (alpha = coverage).
    enum class Backdrop { Sky, Color, Transparent };
    Backdrop lastBackdrop() const;
    // Transient-pool rebuilds so far (tests: stays constant while the graph is unchanged).
    uint32_t transientRebuilds() const { return mRunner.transientRebuilds(); }
    // The Vulkan images behind the last frame's transients (tests read their usage).
    const graph::TransientPool& lastTransients() const { return mRunner.lastTransients(); }
    // The reflected shader parameters of the recent frames and the user's values for them: the
    // forward, skybox and tonemap push constants, and each light and material ("forward",
    // "Lights[i]" / "Materials[i]"). Values set here apply from the next frame.
    shader::ParameterRegistry& parameters() { return mParameters; }
    // The image-based-lighting maps (tests and reports read them back).
    ibl_maps::IblMaps& iblMaps() { return mScene.iblMaps(); }

private:
    // The start every scene and pattern entry point shares: checks the settings, uploads a changed
    // scene or environment and declares the frame's passes in a new graph. With `present`, the
    // tonemap writes the imported presentable image. Throws UserError as capture() does.
    Frame beginFrame(const RenderSettings& settings, const PresentTarget* present = nullptr);
    // Submits the frame with the settings' pass toggles (and the present target's semaphores).
    std::chrono::steady_clock::time_point submit(Frame frame, const RenderSettings& settings,
                                                 const PresentTarget* present = nullptr);
    // submit(), then waits for the frame and finishes it.
    FrameTiming execute(Frame frame, const RenderSettings& settings);
    // After the last frame completed: the maps take over what its precompute computed, and its
    // time is recorded.
    void finishFrame();

    vk::Context& mContext;
    RendererOptions mOptions;
    shader::ParameterRegistry mParameters;
    FrameRunner mRunner;
    SceneState mScene;
    FrameBuilder mBuilder;
    Readback mReadback;
    Readback mOutputReadback;  // the per-pixel outputs besides colour
    PrecomputeTime mLastPrecompute;
    uint32_t mPrecomputes = 0;
};

}  // namespace candela
