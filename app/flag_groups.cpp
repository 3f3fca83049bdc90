// The shared flag groups (flag_groups.h): the flags render, view and bench share, and the device flags.

#include "flag_groups.h"

#include "cli_values.h"
#include "options/draw_selection.h"

#include <algorithm>
#include <optional>
#include <string_view>

namespace candela::app {

std::vector<FlagSpec<SceneOptions>> sceneFlags() {
    using O = SceneOptions;
    return {
        {"--scene", "FILE", "a glTF 2.0 scene (.gltf or .glb) [the built-in 7 x 7 sphere grid]", "", parsed(&O::scene, parsePath)},
        {"--scene-index", "N", "which of the glTF file's scenes to draw [the file's default scene, else 0]", "",
         parsed(&O::sceneIndex, parseDimension)},
        {"--grid", "N", "the built-in grid with N x N spheres over its 7 x 7 materials, framed alike [7]", "",
         [](O& o, Str flag, Str v) {
             o.grid = parseDimension(flag, v);
             if (*o.grid == 0 || *o.grid > 1000) throw UserError(flag + ": expected 1 to 1000 spheres a side, got '" + v + "'");
         }},
        {"--distinct-materials", "",
         "the built-in grid with a material of its own on every sphere (N x N materials: a stress scene)", "",
         setsTo(&O::distinctMaterials, true)},
        {"--variant", "NAME",
         "draw the file's KHR_materials_variants variant NAME (an unknown name is an error that lists the "
         "file's variants; render: all draws each variant, --out then needs {variant}) [the default materials]",
         "",
         [](O& o, Str flag, Str v) {
             if (v.empty()) throw UserError(flag + ": expected a variant name");
             o.variant = v;
         }},
        {"--animation", "LIST",
         "the glTF animations to play: indices or names, all or none (rest pose); comma-separated or "
         "repeated [0, when the scene has animations]",
         "",
         [](O& o, Str flag, Str v) {
             for (const std::string& item : commaSeparated(v)) {
                 if (item.empty()) throw UserError(flag + ": expected indices, names, all or none, got '" + v + "'");
                 o.animations.push_back(item);
             }
         }},
        {"--time", "SECONDS", "the moment of the animations to draw; each loops over its own duration", "0",
         parsed(&O::time, parseSeconds)},
        {"--camera", "INDEX", "use the scene's glTF camera INDEX", "", parsed(&O::camera, parseDimension)},
        {"--camera-orbit", "T,P,R",
         "orbit camera: azimuth T and polar angle P in degrees, distance R in metres (eye = target + R(sin P "
         "sin T, cos P, sin P cos T); R <= 0 frames the scene: the nearest distance where its bounding box fits "
         "the image at a 45-degree field of view) [0,75,0: from the front, 15 degrees above the horizon, framing "
         "the scene; the built-in grid head-on, 0,90,0; --explain prints the camera used as flags]",
         "", parsed(&O::cameraOrbit, parseTriple)},
        {"--target", "X,Y,Z", "the point the orbit camera looks at [the centre of the scene bounds]", "",
         parsed(&O::target, parseTriple)},
        {"--fov", "DEGREES",
         "vertical field of view of the orbit camera; framing keeps its distance, so a narrower field "
         "shows the model bigger [framing fits it to the silhouette with a 10% margin; 45 with a distance]",
         "",
         [](O& o, Str flag, Str v) {
             o.fovDegrees = parseNumber(flag, v);
             if (*o.fovDegrees <= 0.0f || *o.fovDegrees >= 180.0f)
                 throw UserError(flag + ": expected degrees between 0 and 180, got '" + v + "'");
         }},
    };
}

std::vector<FlagSpec<ImageOptions>> imageFlags(bool viewer) {
    using O = ImageOptions;
    const options::DrawSelection selection;
    FlagSpec<O> precompile =
        viewer ? choiceFlag("--precompile", "{choices}", "as for render; debug-views: a switch of the debug view does not stall",
                            options::precompileName(options::Precompile::DebugViews), &O::precompile, options::kPrecompileNames)
               : choiceFlag("--precompile", "{choices}",
                            "when the scene's pipeline variants compile: at each first draw (off), on worker threads before the "
                            "frame's draws (frame), and also every debug view's in the background (debug-views)",
                            options::precompileName(options::Precompile::Frame), &O::precompile, options::kPrecompileNames);
    return {
        choiceFlag("--shading", "MODEL",
                   "the shading model: {choices} (pbr: height-correlated Smith GGX; pbr-schlick-ggx: the original "
                   "project's geometry term; blinn-phong: its first shader)",
                   "pbr", &O::shading, options::kShadingModelNames),
        choiceFlag("--debug-view", "NAME",
                   "show a material input or a shading term instead of the image (d, g, f: the GGX terms toward the "
                   "first light; docs/shading.md): {choices}",
                   "none", &O::debugView, options::kDebugViewNames),
        choiceFlag("--tonemap", "OP", "the tone mapping operator: {choices} (aces: Hill's RRT+ODT fit)", "pbr-neutral", &O::tonemap,
                   options::kTonemapNames),
        {"--exposure", "EV", "exposure in stops", "0", parsed(&O::exposureEv, parseNumber)},
        {"--background", "BG",
         "what shows where the scene draws nothing: {choices} (auto: the skybox with an environment, #262626 "
         "without; transparent: alpha 0 in PNG)",
         "auto",
         [](O& o, Str flag, Str v) {
             o.background = v.rfind('#', 0) == 0 ? Background{Background::Kind::Color, parseHexColor(flag, v)}
                                                 : Background{parseChoice(flag, kBackgroundNames, v, "#rrggbb")};
         },
         namesOf(kBackgroundNames), "#rrggbb"},
        choiceFlag("--msaa", "{choices}",
                   "samples per pixel of the scene's draw targets, resolved into the HDR image; clamped to what the "
                   "device supports, with a warning [4 on GPUs, 1 on CPU devices such as lavapipe: `candela "
                   "info` says which]",
                   "", &O::msaa, kSampleCounts),
        std::move(precompile),
        choiceFlag("--shading-path", "{choices}",
                   "how opaque and masked surfaces are shaded: as their triangles are rasterized (forward), or once per "
                   "covered pixel from a visibility buffer, in compute (visibility); auto: the device's default "
                   "(candela info says which and why)",
                   options::shadingPathName(options::ShadingPath::Auto), &O::shadingPath, options::kShadingPathNames),
        choiceFlag("--specular-aa", "{choices}",
                   "widen the roughness by the normal's change across a pixel and by what a normal map's mips average "
                   "away (less shimmering highlights)",
                   options::ShadingOptions{}.specularAntiAliasing ? "on" : "off", &O::specularAa, kOnOff),
        {"--lod-error", "PIXELS",
         "draw each mesh at the coarsest level of detail whose geometric error covers at most PIXELS on "
         "screen; 0: full detail",
         valueText(selection.lodErrorPixels), [](O& o, Str flag, Str v) { o.lodErrorPixels = parsePixels(flag, v, true); }},
        {"--lod", "{choices}", "levels of detail (on: --lod-error " + valueText(selection.lodErrorPixels) + ", off: 0)", "",
         [](O& o, Str flag, Str v) {
             o.lodErrorPixels = parseChoice(flag, kOnOff, v) ? options::DrawSelection::kDefaultLodErrorPixels : 0.0f;
         },
         namesOf(kOnOff)},
        choiceFlag("--cull", "{choices}", "leave out draws outside the view frustum", selection.frustumCulling ? "on" : "off",
                   &O::frustumCulling, kOnOff),
        {"--disable-pass", "NAME",
         "switch a pass off (repeatable): the frame is drawn without what it adds (skybox: no sky; "
         "transmission_background: transmissive surfaces see only the background; skin_morph: skinned and "
         "morphed meshes left out); a pass the image cannot be made without is an error naming it",
         "", [](O& o, Str, Str v) { o.disabledPasses.push_back(v); }},
    };
}

namespace {

// The IBL flags that set a whole-number member of the IBL quality (checked by IblQuality::validate).
FlagSpec<LightingOptions> iblQualityFlag(std::string name, std::string help, uint32_t ibl::IblQuality::*member) {
    return {std::move(name), "N", std::move(help), valueText(ibl::IblQuality{}.*member),
            [member](LightingOptions& o, Str flag, Str v) { o.iblQuality.*member = parseDimension(flag, v); }};
}

}  // namespace

std::vector<FlagSpec<LightingOptions>> lightingFlags() {
    using O = LightingOptions;
    const ibl::IblQuality quality;
    const ibl::IblLook look;
    return {
        {"--no-default-lights", "", "no key and fill light for a scene without punctual lights and environment", "",
         setsTo(&O::defaultLights, false)},
        choiceFlag("--scene-lights", "{choices}",
                   "the file's own KHR_lights_punctual lights (off: image-based lighting only, for comparisons; the "
                   "scene then counts as one without lights)",
                   "on", &O::sceneLights, kOnOff),
        {"--env", "ENV",
         "image-based lighting from an equirectangular .hdr or .exr file, the built-in procedural sky (sky), "
         "or none. Orientation: the glTF Sample Viewer's (the image centre faces +X, top row +Y); see "
         "docs/environments.md",
         "sky", parsed(&O::env, parseEnvironment)},
        {"--env-rotation", "DEG", "turn the environment about +Y (from +X towards +Z)", valueText(look.rotationDegrees),
         [](O& o, Str flag, Str v) { o.iblLook.rotationDegrees = parseNumber(flag, v); }},
        {"--env-intensity", "K", "scale the environment's radiance", valueText(look.intensity),
         [](O& o, Str flag, Str v) {
             o.iblLook.intensity = parseNumber(flag, v);
             if (o.iblLook.intensity < 0.0f) throw UserError(flag + ": must be ≥ 0, got '" + v + "'");
         }},
        {"--skybox-blur", "B", "show the environment behind the scene blurred like roughness B, 0..1", valueText(look.skyboxBlur),
         [](O& o, Str flag, Str v) {
             o.iblLook.skyboxBlur = parseNumber(flag, v);
             if (o.iblLook.skyboxBlur < 0.0f || o.iblLook.skyboxBlur > 1.0f)
                 throw UserError(flag + ": expected 0 (sharp) to 1, got '" + v + "'");
         }},
        {"--no-multiscatter", "", "single-scattering split sum only (no Fdez-Aguera energy compensation)", "",
         [](O& o, Str, Str) { o.iblLook.multiscatter = false; }},
        {"--ibl-cache", "DIR|off",
         "keep the environment's precomputed maps in DIR across runs, keyed by its content, the quality settings and the "
         "precompute shaders (a damaged file is ignored and replaced; beyond 1 GiB the least recently used are removed); "
         "off: compute them every run [$XDG_CACHE_HOME/candela/ibl, else ~/.cache/candela/ibl]",
         "", parsed(&O::iblCache, parsePath)},
        {"--lod-cache", "DIR|off",
         "keep meshes' levels of detail in DIR across runs, keyed by their positions, indices and the simplifier's "
         "settings, and until they are built the frames drawn without them: a render builds them once drawing every "
         "run's frames at full detail would cost more (a damaged file is ignored and replaced; beyond 1 GiB the least "
         "recently used are removed); off: this run's frames alone decide [$XDG_CACHE_HOME/candela/lod, else "
         "~/.cache/candela/lod]",
         "", parsed(&O::lodCache, parsePath)},
        {"--irradiance", "{choices}", "diffuse irradiance as 9 spherical-harmonic coefficients (sh9) or a cube",
         ibl::irradianceModeName(quality.irradiance),
         [](O& o, Str flag, Str v) { o.iblQuality.irradiance = parseChoice(flag, ibl::kIrradianceModeNames, v); },
         namesOf(ibl::kIrradianceModeNames)},
        iblQualityFlag("--ibl-cube-size", "environment cube face size, 2^k from 16 to 2048", &ibl::IblQuality::cubeSize),
        iblQualityFlag("--ibl-levels", "specular roughness levels (mips)", &ibl::IblQuality::specularLevels),
        iblQualityFlag("--ibl-prefilter-samples",
                       "GGX samples per texel of the first rough specular mip; 4x more per coarser mip, at most 4096",
                       &ibl::IblQuality::prefilterSamples),
        {"--ibl-lod-bias", "B", "filtered-importance-sampling lod bias (more: less noise, more blur)", valueText(quality.lodBias),
         [](O& o, Str flag, Str v) { o.iblQuality.lodBias = parseNumber(flag, v); }},
        iblQualityFlag("--ibl-bright-texels",
                       "the environment's brightest texels (a sun) summed exactly by the filters, not sampled; 0: none",
                       &ibl::IblQuality::brightTexels),
        iblQualityFlag("--ibl-sh-size", "face size of the cube mip projected onto SH9", &ibl::IblQuality::shSourceSize),
        iblQualityFlag("--ibl-irradiance-size", "irradiance cube face size (--irradiance cube)", &ibl::IblQuality::irradianceSize),
        iblQualityFlag("--ibl-irradiance-samples", "cosine samples per irradiance cube texel (--irradiance cube)",
                       &ibl::IblQuality::irradianceSamples),
        iblQualityFlag("--ibl-lut-size", "BRDF LUT size", &ibl::IblQuality::lutSize),
        iblQualityFlag("--ibl-lut-samples", "BRDF LUT samples per texel", &ibl::IblQuality::lutSamples),
    };
}

std::vector<FlagSpec<SceneRenderOptions>> sceneRenderFlags(bool viewer) {
    using O = SceneRenderOptions;
    std::vector<FlagSpec<O>> flags = bindTo<O>(sceneFlags());
    append(flags, bindTo<O>(imageFlags(viewer)));
    append(flags, bindTo<O>(lightingFlags()));
    append(flags, bindTo<O>(&O::common, deviceFlags(true)));
    append(flags, bindTo<O>(&O::common, std::vector{verboseFlag(true)}));
    return flags;
}

EnvironmentChoice parseEnvironment(Str flag, Str v) {
    if (v.empty()) throw UserError(flag + ": expected an .hdr/.exr file, sky or none");
    return v == "sky"    ? EnvironmentChoice{}
           : v == "none" ? EnvironmentChoice{EnvironmentChoice::Kind::None}
                         : EnvironmentChoice{EnvironmentChoice::Kind::File, v};
}

std::vector<FlagSpec<CommonOptions>> deviceFlags(bool rendering) {
    using O = CommonOptions;
    std::vector<FlagSpec<O>> flags = {
        {"--device", "SEL",
         "device index or case-insensitive name substring (see candela info); without it CANDELA_DEVICE; one naming "
         "swiftshader adds the SwiftShader driver of Debian's chromium package",
         "",
         [](O& o, Str, Str v) { o.device = v; }},
        {"--device-profile", "NAME",
         "see the device through a profile: minimum (what Vulkan 1.3 guarantees), desktop or apple (published "
         "device reports) or native, the device itself [CANDELA_DEVICE_PROFILE, else native]",
         "",
         [](O& o, Str flag, Str v) {
             const std::optional<options::DeviceProfile> profile = options::parseDeviceProfile(v);
             if (!profile) throw UserError(flag + ": no device profile '" + v + "' (profiles: " + options::deviceProfileList() + ")");
             o.deviceProfile = *profile;
         }},
        {"--validate", "", "Khronos validation with synchronization validation (also CANDELA_VALIDATE=1)", "",
         setsTo(&O::validate, true)},
    };
    if (!rendering) return flags;
    flags.push_back({"--memory-budget", "MIB",
                     "allocate at most MIB MiB of device memory (simulates a small device: what does not fit is an error "
                     "naming the resource, exit code 4, or a lower IBL resolution with a warning)",
                     "", [](O& o, Str flag, Str v) {
                         o.memoryBudgetMib = parseDimension(flag, v);
                         if (o.memoryBudgetMib == 0) throw UserError(flag + ": need at least 1 MiB");
                     }});
    flags.push_back({"--pipeline-cache", "DIR|off",
                     "keep compiled pipelines in a file in DIR across runs, one per device and driver (a damaged or "
                     "foreign file is ignored and replaced); off: in memory only [$XDG_CACHE_HOME/candela, else "
                     "~/.cache/candela]",
                     "", parsed(&O::pipelineCache, parsePath)});
    return flags;
}

FlagSpec<CommonOptions> verboseFlag(bool camera) {
    const std::string help = "also print notes on the files read (such as the degenerate triangles a glTF file's primitives had, "
                             "dropped quietly)";
    return {"--verbose", "", camera ? help + " and the camera used, as the flags that reproduce it" : help, "",
            setsTo(&CommonOptions::verbose, true)};
}

FlagSpec<CommonOptions> quietFlag() {
    return {"--quiet", "",
            "no progress line (render: of an image sequence); one that rewrites itself on a terminal, a plain "
            "line every 10 s otherwise",
            "", setsTo(&CommonOptions::quiet, true)};
}

}  // namespace candela::app

namespace candela::app {

void checkSceneFlags(const SceneRenderOptions& o, bool moreScenes, bool everyVariant) {
    const bool scenes = !o.scene.empty() || moreScenes;
    if (o.sceneIndex && !scenes) throw UserError("--scene-index: give a glTF file with --scene");
    if (o.grid && scenes) throw UserError("--grid: sizes the built-in sphere grid; not with --scene or scene arguments");
    if (!everyVariant && o.variant == "all") throw UserError("--variant all: only render draws every variant (one image each)");
}

void checkLightingFlags(const SceneRenderOptions& o) {
    o.iblQuality.validate();
    if (o.env.kind == EnvironmentChoice::Kind::None && o.background.kind == Background::Kind::Skybox)
        throw UserError("--background skybox: there is no environment to show (--env none)");
}

options::PixelOutputs parseOutputs(const std::string& flag, const std::string& value) {
    const std::vector<std::string> names = commaSeparated(value);
    const std::vector<std::string_view> views(names.begin(), names.end());
    std::string_view bad;
    if (const std::optional<options::PixelOutputs> outputs = options::pixelOutputsNamed(views, &bad)) return *outputs;
    std::vector<std::string> known = namesOf(options::kPixelOutputNames);
    known.emplace_back("ids");
    throw UserError(flag + ": expected " + joinChoices(known) + ", got '" + std::string(bad) + "'");
}

}  // namespace candela::app
