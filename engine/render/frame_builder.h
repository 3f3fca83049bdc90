#pragma once
// FrameBuilder: declares a frame's passes into its graph from the frame's settings and the scene
// state, and says what it left out and why (Frame::notes, for --explain). Owns the frame passes.
//
// Scene frame:   [skin_morph] → [IBL precompute, when the maps are pending] → forward (HDR + depth)
//                → [skybox] → [transmission_background → forward_transmission] → tonemap (8-bit);
//                on the visibility path (docs/shading-paths.md) visibility → visibility_classify →
//                visibility_shade replace forward (the sky composited by the tonemap, or drawn under
//                the image by skybox), and the blended draws follow in forward_blended when no
//                transmissive draw does; at MSAA, msaa_expand first gives them a multisampled image.
// Test pattern:  pattern (compute, HDR) → encode (graphics, 8-bit sRGB).
// Calibration:   calibration alone (benchmarks' unit of time).

#include "passes/calibration_pass.h"
#include "passes/encode_pass.h"
#include "passes/forward_pass.h"
#include "passes/msaa_expand_pass.h"
#include "passes/pattern_pass.h"
#include "passes/skin_morph_pass.h"
#include "passes/skybox_pass.h"
#include "passes/tonemap_pass.h"
#include "passes/transmission_background_pass.h"
#include "render/frame.h"
#include "render/render_settings.h"
#include "render/scene_state.h"
#include "render/visibility_path.h"
#include "shader/parameter_registry.h"
#include "vk/msaa.h"

#include <optional>

namespace candela {

class FrameBuilder {
public:
    // Preconditions: the arguments outlive the builder.
    FrameBuilder(vk::Context& context, SceneState& scene, shader::ParameterRegistry& parameters);

    // The scene was uploaded anew (SceneState::prepareScene): the forward pass binds it.
    void sceneUploaded();
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
    void finishPipelineBuilds() { mForward.finishBuilds(); }

    // The view `camera` selects for `scene` at `aspect` (width / height). With an animated `pose`,
    // glTF cameras are where the pose puts them and framing contains the whole animation.
    static scene::ViewSetup resolveView(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                        const scene::ScenePose* pose = nullptr);
    // The orbit camera `camera` gives when it names no glTF camera: the interactive one as it is,
    // else scene::OrbitCamera::framing of the scene's bounds (with an animated `pose`, the bounds
    // of the whole animation) from --camera-orbit's direction or scene::defaultOrbitAngles, then
    // the distance (r > 0) and --target when given, with the --fov.
    static scene::OrbitCamera orbitCamera(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                          const scene::ScenePose* pose = nullptr);
    // The command-line flags that reproduce resolveView's view: "--camera N" for a glTF camera,
    // else scene::orbitCameraFlags (--camera-orbit, --target, --fov); printed by --explain and
    // --verbose. The viewer's lens shift has no flag.
    static std::string cameraFlags(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                   const scene::ScenePose* pose = nullptr);

private:
    // The shading path of a frame of `variant` asked for `requested`: Visibility or Forward, and
    // why (for --explain; "" when the request was followed without a reason to give).
    std::pair<passes::ShadingPath, std::string> shadingPath(passes::ShadingPath requested,
                                                            const passes::FrameVariant& variant) const;
    // Adds the skin_morph pass for the pose's deformed draws; nullopt (and a note) when none is, or
    // when the pass is `disabled` (--disable-pass skin_morph: it is declared, to be switched off, and
    // the caller leaves the deformed draws out of the frame).
    std::optional<passes::ForwardPass::DeformedVertices> addSkinMorph(Frame& frame, const scene::ScenePose& pose, bool disabled);
    // The per-frame buffers of an animated pose — the posed draws (a node moves), lights (a light
    // moves, shows, hides or has an animated property) and materials (and their layer data) with
    // animated properties — each only when something it holds animates; and a note for --explain
    // when the pose animates properties (KHR_animation_pointer).
    passes::ForwardPass::PosedDraws addPosedDraws(Frame& frame, const scene::Scene& scene, const scene::ScenePose& pose);
    // The IBL inputs of the forward pass, when the maps have an environment.
    std::optional<passes::ForwardPass::Ibl> addIbl(Frame& frame, const RenderSettings& settings);
    // The tonemap's settings for the frame (debug views: data shown linearly, grey background).
    passes::TonemapSettings tonemapOf(const RenderSettings& settings, bool ibl) const;
    // What the scene frame added besides the forward draws.
    struct Scheduled {
        bool sheenLut = false, transmission = false;
        bool seesOpaqueImage = false;  // the transmissive draws read transmission_background (it is not disabled)
        bool ibl = false, skybox = false, skyInTonemap = false;
    };
    // Adds the frame's notes: lights, MSAA, the forward passes' `forward` lines, the maps, sheen LUT,
    // transmission, debug view and skybox.
    void addNotes(Frame& frame, const RenderSettings& settings, const vk::MsaaChoice& msaa, std::vector<std::string> forward,
                  const Scheduled& scheduled);

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
    VisibilityPath mVisibility;
    passes::DrawStats mStats;  // of the last scene frame; the recorder adds its state changes
    std::optional<uint32_t> mMsaaWarnedFor;  // the clamped request last warned of (once per request)
};

}  // namespace candela
