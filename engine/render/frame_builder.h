#pragma once
// FrameBuilder: declares a frame's passes into its graph from the frame's settings and the scene
// state, and says what it left out and why (Frame::explanation, for --explain). Owns the frame passes.
// A scene frame is built in three steps: the facts (settings, device, pose, draw list) → the plan
// (frame_plan.h: a pure function, unit-tested) → the plan's passes declared, and its --explain
// lines (explain_plan.h) placed beside the passes' own.
//
// Scene frame:   [skin_morph] → [IBL precompute, when the maps are pending] → forward (HDR + depth)
//                → [skybox] → [transmission_background → forward_transmission] → tonemap (8-bit);
//                on the visibility path (docs/shading-paths.md) visibility → visibility_classify →
//                visibility_shade replace forward (the sky composited by the tonemap, or drawn under
//                the image by skybox), the points and lines follow in forward_points_lines and the
//                blended draws in forward_blended when no transmissive draw does; at MSAA,
//                msaa_expand first gives them a multisampled image.
// Test pattern:  pattern (compute, HDR) → encode (graphics, 8-bit sRGB).
// Calibration:   calibration alone (benchmarks' unit of time).

#include "passes/aov/aov_pass.h"
#include "passes/diagnostics/calibration_pass.h"
#include "passes/post/encode_pass.h"
#include "passes/forward/forward_pass.h"
#include "passes/visibility/msaa_expand_pass.h"
#include "passes/diagnostics/pattern_pass.h"
#include "passes/deform/skin_morph_pass.h"
#include "passes/backdrop/skybox_pass.h"
#include "passes/post/tonemap_pass.h"
#include "passes/backdrop/transmission_background_pass.h"
#include "render/frame.h"
#include "render/frame_plan.h"
#include "render/render_settings.h"
#include "render/scene_state.h"
#include "render/visibility_path.h"
#include "shader/parameter_registry.h"
#include "vk/msaa.h"

#include <optional>
#include <span>

namespace candela {

class FrameBuilder {
public:
    // Preconditions: the arguments outlive the builder.
    FrameBuilder(vk::Context& context, SceneState& scene, shader::ParameterRegistry& parameters);

    // The scene was uploaded anew (SceneState::prepareScene): the forward pass binds it.
    void sceneUploaded();
    // Before a scene whose materials have `keys` (passes::MaterialKeys::of) is uploaded, drawn with
    // `lights`: queues its forward pipelines for a frame like the last one, or before any for the
    // one `settings` give (firstFrameVariant) (ForwardPass::prepareAhead), so that they compile
    // while it uploads.
    // The tonemap's pipelines too (prepareTonemapAhead).
    void prepareAhead(const passes::MaterialKeys& keys, const RenderSettings& settings, std::span<const scene::Light> lights);
    // Queues on the forward pass's workers the tonemap pipelines of a first scene frame of
    // `settings` drawing every draw of materials with `keys` (null: none transmissive or blended;
    // the frame plan of the facts the settings and the device give), so that they compile before
    // that frame — while its scene loads or uploads. A frame planned otherwise (its transmissive or
    // blended draws all culled) builds its own at its tonemap and leaves these unused. Nothing with
    // --precompile off.
    void prepareTonemapAhead(const RenderSettings& settings, const passes::MaterialKeys* keys);
    // The forward variant bits (passes::FrameVariant, lights aside) of a scene frame of `settings`,
    // known before its scene and environment are uploaded: what buildScene will find, from the
    // same settings (GpuTest.AFirstScenesPipelinesCompileWhileItUploadsForTheFrameItsSettingsGive).
    // Nullopt with MSAA, where alpha to coverage is the frame plan's choice, and for the visibility
    // path (asked, or the device's default), whose frames may not draw on the forward path.
    std::optional<passes::FrameVariant> firstFrameVariant(const RenderSettings& settings) const;
    // Declares the scene frame for `settings` (a scene is uploaded, the environment prepared): the
    // tonemap writes `target` when given (a presentable image), else a new transient "ldr".
    // Throws UserError for a bad camera choice.
    void buildScene(Frame& frame, const RenderSettings& settings, std::optional<graph::TextureId> target);
    void buildPattern(Frame& frame, const RenderSettings& settings);
    void buildCalibration(Frame& frame, uint32_t width, uint32_t height);
    // Imports the IBL maps into `frame`, with the precompute passes when they are pending (and the
    // ground truth's inputs with `reference`); records which declared passes the precompute added.
    // Precondition: the maps have an environment.
    passes::IblHandles addIblMaps(Frame& frame, bool reference);

    // What the forward passes of the last scene frame drew (scene vs submitted draws and
    // triangles; state changes once the frame is recorded).
    const passes::DrawStats& drawStats() const { return mStats; }
    // The sample count `requested` (RenderSettings::msaa) gives on this device, and why.
    vk::MsaaChoice msaa(std::optional<uint32_t> requested) const;
    passes::ForwardPass& forward() { return mForward; }
    // Waits for the pipelines queued ahead of use (RenderSettings::precompile) to be built.
    void finishPipelineBuilds() {
        mForward.finishBuilds();
        mTonemap.finishBuilds();
    }

    // The view `camera` selects for `scene` at `aspect` (width / height). With an animated `pose`,
    // glTF cameras are where the pose puts them and framing fits the pose as it stands.
    static scene::ViewSetup resolveView(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                        const pose::ScenePose* pose = nullptr);
    // The orbit camera `camera` gives when it names no glTF camera: the interactive one as it is,
    // else scene::frame of what the scene shows (pose/shown_points.h: with an animated `pose`, the
    // pose as it stands) from --camera-orbit's direction or scene::defaultOrbitAngles, with the
    // distance (r > 0), --target and --fov where given (45° with a distance and no --fov). A front
    // end that draws a sequence resolves framing once for all its frames (api/cameras.h).
    static scene::OrbitCamera orbitCamera(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                          const pose::ScenePose* pose = nullptr);
    // The command-line flags that reproduce resolveView's view: "--camera N" for a glTF camera,
    // else scene::orbitCameraFlags (--camera-orbit, --target, --fov); printed by --explain and
    // --verbose. The viewer's lens shift has no flag.
    static std::string cameraFlags(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                   const pose::ScenePose* pose = nullptr);

private:
    // The facts of a frame of `settings` at `samples` samples that the settings, the device and the
    // scene state give (FrameFacts; buildScene adds the pose's and the draw list's).
    FrameFacts facts(const RenderSettings& settings, uint32_t samples) const;
    // Adds the skin_morph pass for the pose's deformed draws (`work`) as `plan` says, with its
    // --explain lines; the deformed vertices, or nullopt when nothing is deformed or the pass is
    // disabled (it is then declared, to be switched off, and the deformed draws are left out of the
    // frame).
    std::optional<passes::DeformedVertices> addSkinMorph(Frame& frame, const FramePlan& plan, const FrameFacts& facts,
                                                         passes::SkinMorphFrame& work);
    // The per-frame buffers of an animated pose — the posed draws (a node moves), lights (a light
    // moves, shows, hides or has an animated property) and materials (and their layer data) with
    // animated properties — each only when something it holds animates; and what it animates
    // besides nodes (Frame::posed) with its --explain line.
    passes::PosedBuffers addPosedDraws(Frame& frame, const scene::Scene& scene, const pose::ScenePose& pose);
    // The IBL inputs of the draws, when the maps have an environment.
    std::optional<passes::IblInputs> addIbl(Frame& frame, const RenderSettings& settings);
    // Declares the plan's draw passes of `desc`'s list: the shading path's (with the visibility
    // path's `tables`), the skybox, the MSAA expansion, the blended and the transmissive draws.
    // Returns the targets drawn last.
    passes::DrawTarget addDraws(Frame& frame, const FramePlan& plan, const FrameFacts& facts, const VisibilityPath::FrameDesc& desc,
                                const passes::VisibilityFrameTables* tables, const scene::ViewSetup& view,
                                const passes::IblInputs* ibl);
    // Adds the tonemap of frame.hdr into `target` (or a new "ldr"), with the sky where the plan puts it
    // there: only where `depth` (the scene's) is the far plane's when plan.skyWhereUncovered.
    void addTonemap(Frame& frame, const RenderSettings& settings, const FramePlan& plan, std::optional<graph::TextureId> target,
                    const scene::ViewSetup& view, const passes::IblInputs* ibl, graph::TextureId depth);
    // The tonemap's settings for the frame: the settings' own, with the plan's look and grey
    // background for a debug view.
    static passes::TonemapSettings tonemapOf(const RenderSettings& settings, const FramePlan& plan);
    // Adds the frame's --explain lines: lights, MSAA, the `shading` lines (the draws and their
    // variants: passes::explainShading), the pipelines, the maps, and the plan's (explain_plan.h).
    void addExplanation(Frame& frame, const RenderSettings& settings, const vk::MsaaChoice& msaa,
                        std::vector<std::string> shading, const FramePlan& plan, const FrameFacts& facts);

    vk::Context& mContext;
    SceneState& mScene;
    shader::ParameterRegistry& mParameters;
    passes::PatternPass mPattern;
    passes::EncodePass mEncode;
    passes::ForwardPass mForward;
    passes::SkyboxPass mSkybox;
    passes::MsaaExpandPass mExpand;
    passes::TransmissionBackgroundPass mTransmissionBackground;
    passes::SkinMorphPass mSkinMorph;
    passes::TonemapPass mTonemap;
    passes::CalibrationPass mCalibration;
    passes::AovPass mAov;
    VisibilityPath mVisibility;
    passes::DrawStats mStats;  // of the last scene frame; the recorder adds its state changes
    std::optional<uint32_t> mMsaaWarnedFor;  // the clamped request last warned of (once per request)
};

}  // namespace candela
