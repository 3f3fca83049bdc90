#pragma once
// The options render, view and bench share (SceneRenderOptions): the scene and camera, the
// shading and image, and the lighting, each a struct that its flag group (flag_groups.h) fills.

#include "common_options.h"
#include "ibl/ibl_settings.h"
#include "options/debug_view.h"
#include "options/draw_selection.h"
#include "options/precompile.h"
#include "options/shading_model.h"
#include "options/shading_path.h"
#include "options/tonemap_operator.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace candela::app {

// The scene, its animations and the camera.
struct SceneOptions {
    std::string scene;                   // --scene FILE (.gltf/.glb), or view's SCENE; empty: the built-in sphere grid
    std::optional<uint32_t> sceneIndex;  // --scene-index N: which of the file's scenes [its `scene`, else 0]
    std::optional<uint32_t> grid;        // --grid N: N × N spheres of the built-in grid (unset: its own 7 × 7)
    bool distinctMaterials = false;      // --distinct-materials: a material per sphere of the grid
    std::string variant;                 // --variant NAME: a KHR_materials_variants variant ("" = defaults; render: "all")
    // --animation LIST (repeatable, comma-separated: indices, names, all, none); empty: animation 0
    std::vector<std::string> animations;
    double time = 0.0;                   // --time SECONDS (each animation loops over its duration)
    std::optional<uint32_t> camera;      // --camera INDEX (glTF camera)
    std::optional<std::array<float, 3>> cameraOrbit;  // --camera-orbit THETA,PHI,RADIUS
    std::optional<std::array<float, 3>> target;       // --target X,Y,Z
    std::optional<float> fovDegrees;                  // --fov DEGREES (vertical; none: framing fits it)
    bool operator==(const SceneOptions&) const = default;
};

// How the frame is shaded and drawn.
struct ImageOptions {
    options::ShadingModel shading{};      // --shading
    options::DebugView debugView{};       // --debug-view
    options::Tonemap tonemap{};           // --tonemap
    float exposureEv = 0.0f;             // --exposure EV
    Background background;               // --background
    std::optional<uint32_t> msaa;        // --msaa 1|2|4|8 (unset: the device default)
    options::Precompile precompile{};     // --precompile off|frame|debug-views
    options::ShadingPath shadingPath{};   // --shading-path auto|forward|visibility
    bool specularAa = false;             // --specular-aa on|off
    float lodErrorPixels = 0.0f;         // --lod-error PIXELS (0, or --lod off: full detail)
    bool frustumCulling = true;          // --cull on|off
    std::vector<std::string> disabledPasses;  // --disable-pass NAME (repeatable)
    bool operator==(const ImageOptions&) const = default;
};

// The lights and image-based lighting.
struct LightingOptions {
    bool defaultLights = true;   // --no-default-lights turns off the key/fill lights of light-less scenes
    bool sceneLights = true;     // --scene-lights off leaves out the file's own punctual lights
    EnvironmentChoice env;       // --env FILE|sky|none
    ibl::IblLook iblLook;        // --env-rotation, --env-intensity, --skybox-blur, --no-multiscatter
    ibl::IblQuality iblQuality;  // --irradiance, --ibl-cube-size, --ibl-prefilter-samples, ...
    std::string iblCache;        // --ibl-cache DIR|off ("": the user's cache folder's)
    std::string lodCache;        // --lod-cache DIR|off ("": the user's cache folder's)
    bool operator==(const LightingOptions&) const = default;
};

// What render, view and bench share: the device, the frame (or window) size and the three groups.
struct SceneRenderOptions : SceneOptions, ImageOptions, LightingOptions {
    CommonOptions common;
    uint32_t width = 0;   // --width W
    uint32_t height = 0;  // --height H
    bool operator==(const SceneRenderOptions&) const = default;
};

}  // namespace candela::app
