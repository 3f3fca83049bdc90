#pragma once
// RenderSettings: what one frame is — what to draw (the scene, its pose, the environment), how
// (camera, shading, debug view, tonemap, draw selection, MSAA, image-based lighting) and into what
// (size, 8-bit or float). How the renderer runs frames (frames in flight, the viewer's tolerance of
// unknown pass toggles, test hooks) is RendererOptions (renderer.h).

#include "assets/environment.h"
#include "ibl/ibl_settings.h"
#include "options/debug_view.h"
#include "options/draw_selection.h"
#include "options/pixel_output.h"
#include "passes/drawing/shading_variant.h"
#include "options/precompile.h"
#include "options/shading_path.h"
#include "passes/post/tonemap_pass.h"
#include "pose/scene_pose.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <filesystem>
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
    // --fov; none: framing fits it (scene/framing.h), else 45° (a given distance, a placed camera).
    std::optional<float> fovYDegrees;
    // A camera placed by its camera-to-world matrix (the API's look-at and placed cameras):
    // overrides orbit and target (scene::placedView).
    std::optional<glm::mat4> cameraToWorld;
    // Pinhole intrinsics (fractions of the image) of the orbit or placed camera: override
    // fovYDegrees. Not with a glTF camera.
    std::optional<scene::Intrinsics> intrinsics;
    // An interactive camera (the viewer's), used as is; overrides the three above.
    std::optional<scene::OrbitCamera> orbitCamera;
    // Moves the image centre right by this many NDC units (off-axis projection; negative: left):
    // the viewer centres the scene between its panel columns.
    float lensShiftX = 0.0f;
    // How framing chose the orbit camera above, when a front end resolved it once for a whole
    // sequence (api/cameras.h frameSequence): printed by --explain; empty otherwise.
    std::string framing;
};

struct RenderSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    bool floatOutput = false;  // capture linear HDR (EXR/PFM) instead of 8-bit sRGB (PNG)
    // What a capture reads back (docs/outputs.md): the colour image and any per-pixel outputs
    // besides it (the aov pass, declared only when one is asked for). Without colour the passes
    // that make the image are culled (a scene frame only).
    options::PixelOutputs outputs{options::PixelOutput::Color};
    // The scene to draw; null renders the procedural test pattern instead (passes/diagnostics/pattern_pass.h).
    const scene::Scene* scene = nullptr;
    // The scene as its animations pose it this frame (a pose of `scene`, owned by the caller);
    // null, or a pose that animates nothing, draws the loaded rest pose with the static draw data.
    const pose::ScenePose* pose = nullptr;
    CameraSettings camera;
    options::ShadingModel shading = options::ShadingModel::Pbr;
    // A debug view of the forward pass instead of the shaded image (a variant of the frame graph:
    // no skybox; data views are tonemapped linearly at exposure 0, see options::DebugView).
    options::DebugView debugView = options::DebugView::None;
    // A scene without punctual lights gets a default key and fill light (directional), so that
    // it is visible before image-based lighting exists; false leaves it unlit.
    bool defaultLights = true;
    // The scene's own punctual lights (KHR_lights_punctual); false leaves them out, for comparisons
    // under image-based lighting alone — the scene then counts as one without lights.
    bool sceneLights = true;
    passes::TonemapSettings tonemap;
    // Frustum culling and the level-of-detail error (--lod-error, --cull).
    options::DrawSelection drawSelection;
    // Specular anti-aliasing (--specular-aa).
    options::ShadingOptions shadingOptions;
    // MSAA sample count of the draw targets (--msaa: 1, 2, 4 or 8); nullopt: the device default
    // (vk::chooseMsaa). Clamped to what the device supports, with a warning.
    std::optional<uint32_t> msaa;
    // When the forward pass compiles the variants the frame needs (--precompile; docs/device-layer.md).
    options::Precompile precompile = options::Precompile::Frame;
    // How opaque and masked surfaces are shaded (--shading-path; docs/shading-paths.md).
    options::ShadingPath shadingPath = options::ShadingPath::Auto;
    // Image-based lighting: the environment (null: none; read during the call only, hashed when the
    // pointer or the quality changes), what to precompute and how to look it up.
    const assets::Environment* environment = nullptr;
    ibl::IblQuality iblQuality;
    ibl::IblLook ibl;
    std::filesystem::path iblCacheDir;  // empty: no on-disk cache
    // The on-disk cache of levels of detail (geometry/lod_cache.h), used by the API before the
    // upload (the renderer draws what the scene holds); empty: none.
    std::filesystem::path lodCacheDir;
    float patternExposure = 1.0f;  // test pattern only
    std::vector<std::string> disabledPasses;  // runtime toggles by pass name
    // Each pass submitted and waited for alone, its wall time in the frame's timings
    // (graph::GraphTimings::serialMs): per-pass costs on devices whose timestamps miss deferred
    // work. Slower frames; headless frames only (not with a presentable target).
    bool serialPasses = false;
};

}  // namespace candela
