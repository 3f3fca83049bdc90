#pragma once
// The flag groups commands assemble their flag lists from, each written for the options struct it
// fills: output (frame size, --dither, --inline-images), scene and camera, shading and image,
// lighting and IBL, reports (--env of the report commands) and device (CommonOptions).

#include "options/pixel_output.h"
#include "flag_spec.h"
#include "scene_render_options.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace candela::app {

inline constexpr std::pair<bool, const char*> kOnOff[] = {{true, "on"}, {false, "off"}};
inline constexpr std::pair<uint32_t, const char*> kSampleCounts[] = {{1, "1"}, {2, "2"}, {4, "4"}, {8, "8"}};

// ---- output ----

// --width and --height; `help` holds "{}" where "width" or "height" goes.
template <class O>
std::vector<FlagSpec<O>> sizeFlags(uint32_t O::*width, uint32_t O::*height, const std::string& help, uint32_t w, uint32_t h) {
    const auto text = [&help](const char* noun) { return std::string(help).replace(help.find("{}"), 2, noun); };
    return {{"--width", "W", text("width"), valueText(w), parsed(width, parseCount)},
            {"--height", "H", text("height"), valueText(h), parsed(height, parseCount)}};
}

// --width and --height of render, bench and scale-report: the frame size in pixels, 1280 x 720.
template <class O>
std::vector<FlagSpec<O>> frameSizeFlags(uint32_t O::*width, uint32_t O::*height) {
    return sizeFlags(width, height, "frame {} in pixels", 1280, 720);
}

// --dither (render and bench).
template <class O>
FlagSpec<O> ditherFlag(bool O::*dither) {
    return {"--dither", "", "dither the 8-bit output (the viewer always does)", "", setsTo(dither, true)};
}

// --outputs LIST (render and bench): the per-pixel outputs (options/pixel_output.h).
options::PixelOutputs parseOutputs(const std::string& flag, const std::string& value);
template <class O>
FlagSpec<O> outputsFlag(options::PixelOutputs O::*outputs) {
    return {"--outputs", "LIST",
            "what each image gives per pixel, comma-separated: color, depth (view depth, metres), clip_depth, "
            "normal (world space), base_color, alpha, metallic_roughness, emissive, node_id, mesh_id, "
            "primitive_id, material_id, instance_id, or ids for the five IDs; all but colour at the pixel "
            "centre, exact at --msaa 1 (docs/outputs.md); a .exr --out holds them all as channels",
            "color", parsed(outputs, parseOutputs)};
}

// --inline-images (render and diff).
template <class O>
FlagSpec<O> inlineImagesFlag(bool O::*inlineImages) {
    return {"--inline-images", "", "put the images into the --html page (one file to pass on) instead of linking them", "",
            setsTo(inlineImages, true)};
}

// ---- render, view and bench ----

// --scene, --scene-index, --grid, --distinct-materials, --variant, --animation, --time and the camera.
std::vector<FlagSpec<SceneOptions>> sceneFlags();
// --shading to --disable-pass; `viewer`: view's --precompile (its help and default).
std::vector<FlagSpec<ImageOptions>> imageFlags(bool viewer);
// --no-default-lights, --scene-lights, --env and the IBL flags.
std::vector<FlagSpec<LightingOptions>> lightingFlags();
// The three groups, --verbose and the device flags (but --quiet): what render, view and bench
// share (their --width and --height differ).
std::vector<FlagSpec<SceneRenderOptions>> sceneRenderFlags(bool viewer);

// The checks of render, view and bench that involve more than one flag, in this order (view checks
// --screenshot between them). `moreScenes`: scene arguments besides --scene; `everyVariant`: the
// command takes --variant all.
void checkSceneFlags(const SceneRenderOptions& options, bool moreScenes, bool everyVariant);
void checkLightingFlags(const SceneRenderOptions& options);

// ---- reports ----

// The --env value: sky, none or a file; a UserError for "".
EnvironmentChoice parseEnvironment(const std::string& flag, const std::string& value);

// --env of a command that needs an environment (`command`: its name, for the error): a file or sky.
template <class O>
FlagSpec<O> requiredEnvFlag(EnvironmentChoice O::*env, std::string help, std::string command) {
    return {"--env", "ENV", std::move(help), "sky", [env, command](O& o, const std::string& flag, const std::string& value) {
                o.*env = parseEnvironment(flag, value);
                if ((o.*env).kind == EnvironmentChoice::Kind::None)
                    throw UserError(flag + ": " + command + " needs an environment (an .hdr/.exr file or sky)");
            }};
}

// ---- device ----

// --device, --device-profile and --validate; with `rendering` also --memory-budget and
// --pipeline-cache (every command but info).
std::vector<FlagSpec<CommonOptions>> deviceFlags(bool rendering);
// --verbose; `camera`: it also prints the camera used (render, view, bench).
FlagSpec<CommonOptions> verboseFlag(bool camera);
// --quiet: no progress line.
FlagSpec<CommonOptions> quietFlag();

}  // namespace candela::app
