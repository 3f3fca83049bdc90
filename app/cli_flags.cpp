#include "cli_flags.h"

#include "core/errors.h"

#include <algorithm>
#include <charconv>

namespace candela::app {
namespace {

using Kind = Command::Kind;
using Str = const std::string&;  // a setter's flag name and value

constexpr CommandSet kAll{Kind::Render, Kind::View, Kind::Bench, Kind::IblReport, Kind::ScaleReport,
                          Kind::QualityReport, Kind::Soak, Kind::Info};
constexpr CommandSet kRenderViewBench{Kind::Render, Kind::View, Kind::Bench};

constexpr std::pair<bool, const char*> kOnOff[] = {{true, "on"}, {false, "off"}};
constexpr std::pair<uint32_t, const char*> kSampleCounts[] = {{1, "1"}, {2, "2"}, {4, "4"}, {8, "8"}};

// A default the engine owns, written as the flag would take it ("0.5", "256").
std::string valueText(float value) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}
std::string valueText(uint32_t value) { return std::to_string(value); }

std::string panelList(const std::set<ui::Panel>& panels) {
    std::string out;
    for (const auto& [panel, name] : ui::kPanelNames)
        if (panels.count(panel)) out += (out.empty() ? "" : ",") + std::string(name);
    return out;
}

// Calls f with the options of the command being parsed; the flag's command set guarantees that
// they have the member f sets (a flag test checks that every use changes the result).
template <class F>
void onOptions(Command& c, F&& f) {
    switch (c.kind) {
        case Kind::Render:
        case Kind::View:
        case Kind::Bench: return f(c.render);
        case Kind::Info: return f(c.info);
        case Kind::IblReport: return f(c.iblReport);
        case Kind::Soak: return f(c.soak);
        case Kind::ScaleReport: return f(c.scaleReport);
        case Kind::QualityReport: return f(c.qualityReport);
        case Kind::Diff: return f(c.diff);
        case Kind::Help:
        case Kind::Version: break;
    }
    throw InternalError("a flag was parsed without a command");
}

std::string commandName(Kind kind) {
    for (const CommandInfo& command : commandTable())
        if (command.kind == kind) return command.name;
    return "candela";
}

// --width and --height: each command's frame (or window) size.
Flag sizeFlag(bool width) {
    const std::string name = width ? "--width" : "--height", value = width ? "W" : "H", noun = width ? "width" : "height";
    const auto pixels = [width](uint32_t w, uint32_t h) { return valueText(width ? w : h); };
    return {.name = name,
            .uses = {{{Kind::Render, Kind::Bench, Kind::ScaleReport}, value, "frame " + noun + " in pixels", pixels(1280, 720)},
                     {{Kind::View}, value, "initial window " + noun, pixels(1280, 720)},
                     {{Kind::IblReport}, value, noun + " of the end-to-end images", pixels(320, 180)},
                     {{Kind::QualityReport}, value, "frame " + noun + " (the reference renders 4x as many pixels a side)",
                      pixels(640, 360)},
                     {{Kind::Soak}, value, "frame " + noun, pixels(320, 180)}},
            .set = [width](Command& c, Str flag, Str v) {
                const uint32_t size = parseCount(flag, v);
                onOptions(c, [&](auto& o) { if constexpr (requires { o.width; }) (width ? o.width : o.height) = size; });
            },
            .example = width ? "64" : "48"};
}

// diff's numbers: a finite number > 0, and one from 0 to 1.
float positiveNumber(Str flag, Str v, const char* unit) {
    const float value = parseNumber(flag, v);
    if (!(value > 0.0f)) throw UserError(flag + ": expected " + unit + " > 0, got '" + v + "'");
    return value;
}
double unitFraction(Str flag, Str v) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), value);
    if (error != std::errc() || end != v.data() + v.size() || !(value >= 0.0 && value <= 1.0))
        throw UserError(flag + ": expected a number from 0 to 1, got '" + v + "'");
    return value;
}

// The table's rows that set a whole-number member of the IBL quality (checked by IblQuality::validate).
Flag iblQualityFlag(const std::string& name, const char* help, uint32_t ibl::IblQuality::*member, const char* example) {
    return {.name = name,
            .uses = {{kRenderViewBench, "N", help, valueText(ibl::IblQuality{}.*member)}},
            .set = [member](Command& c, Str flag, Str v) { c.render.iblQuality.*member = parseDimension(flag, v); },
            .example = example};
}

std::vector<Flag> makeFlagTable() {
    const ibl::IblQuality quality;
    const ibl::IblLook look;
    const passes::DrawSelection selection;
    std::vector<Flag> flags = {
        // ---- output and size ----
        {.name = "--out",
         .uses = {{{Kind::Render}, "FILE",
                   "the output image: .png (8-bit sRGB), .exr (linear half float) or .pfm (linear float); a pattern "
                   "with {name}, {path}, {variant} and {frame} names each scene's images (folders are created); with "
                   "--frames N and no {frame}, one %d or %04d holds the frame number",
                   "candela.png"},
                  {{Kind::IblReport}, "DIR", "where report.csv, report.md and the plots go (created)", "ibl-report"},
                  {{Kind::ScaleReport}, "DIR", "where report.csv, report.md and frame_vs_triangles.png go (created)",
                   "scale-report"},
                  {{Kind::QualityReport}, "DIR", "where report.csv, report.md and the plots go (created)", "quality-report"},
                  {{Kind::Soak}, "FILE", "also write the samples as CSV", ""}},
         .set = [](Command& c, Str flag, Str v) {
             onOptions(c, [&](auto& o) { if constexpr (requires { o.out; }) o.out = parsePath(flag, v); });
         },
         .example = "out"},
        sizeFlag(true),
        sizeFlag(false),
        {.name = "--frames",
         .uses = {{{Kind::Render}, "N", "an image sequence of N frames (--out then holds a %04d-style frame number)", "1"},
                  {{Kind::View}, "N", "render N frames, then exit [run until the window is closed]", ""},
                  {{Kind::Bench}, "N", "frames measured after warm-up", "20"},
                  {{Kind::ScaleReport}, "N", "frames measured per setting", "5"},
                  {{Kind::QualityReport}, "N", "timed frames per setting", "5"},
                  {{Kind::Soak}, "N", "frames to render", "10000"}},
         .set = [](Command& c, Str flag, Str v) {
             onOptions(c, [&](auto& o) { if constexpr (requires { o.frames; }) o.frames = parseCount(flag, v); });
         },
         .example = "3"},
        {.name = "--fps",
         .uses = {{{Kind::Render}, "F", "frames per second of an image sequence; frame i shows --time + i/F", "30"}},
         .set = [](Command& c, Str flag, Str v) {
             c.render.fps = parseSeconds(flag, v);
             if (!(c.render.fps > 0.0)) throw UserError(flag + ": expected frames per second > 0, got '" + v + "'");
         },
         .example = "24"},
        {.name = "--turntable",
         .uses = {{{Kind::Render}, "DEGREES",
                   "turn the orbit camera by DEGREES over an image sequence (360: once round), framed at one "
                   "distance",
                   "0"}},
         .set = [](Command& c, Str flag, Str v) { c.render.turntableDegrees = parseNumber(flag, v); },
         .example = "90"},
        {.name = "--report",
         .uses = {{{Kind::Render}, "FILE",
                   "write a JSON report of the run: per scene the load, upload and frame times, triangles, draws, "
                   "textures and their bytes, extensions, warnings and the files written",
                   ""},
                  {{Kind::Diff}, "FILE",
                   "write the viewing parameters, every pair's numbers, status and error map, and the totals as JSON",
                   ""}},
         .set = [](Command& c, Str flag, Str v) { (c.kind == Kind::Diff ? c.diff.report : c.render.report) = parsePath(flag, v); },
         .example = "report.json"},
        {.name = "--html",
         .uses = {{{Kind::Render}, "FILE",
                   "write an HTML page of the run: a row per scene with its images, times, sizes, warnings and "
                   "failure, sortable (self-contained: no network; images beside it)",
                   ""},
                  {{Kind::Diff}, "FILE",
                   "write an HTML page of the comparison: a row per pair with reference, test and FLIP map, the "
                   "numbers, failures first, sortable (self-contained: no network; images beside it)",
                   ""}},
         .set = [](Command& c, Str flag, Str v) { (c.kind == Kind::Diff ? c.diff.html : c.render.html) = parsePath(flag, v); },
         .example = "index.html"},
        {.name = "--inline-images",
         .uses = {{{Kind::Render, Kind::Diff}, "", "put the images into the --html page (one file to pass on) instead of linking them", ""}},
         .set = [](Command& c, Str, Str) { (c.kind == Kind::Diff ? c.diff.inlineImages : c.render.inlineImages) = true; },
         },
        {.name = "--shard",
         .uses = {{{Kind::Render}, "I/N",
                   "render only share I of N of the scenes (every N-th, from the I-th): one machine's part of a "
                   "library spread over N machines",
                   ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.shard = parseShard(flag, v); },
         .example = "2/4"},
        {.name = "--graph-dot",
         .uses = {{{Kind::Render}, "FILE", "write the compiled render graph as Graphviz dot", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.graphDot = parsePath(flag, v); },
         .example = "graph.dot"},
        {.name = "--graph-json",
         .uses = {{{Kind::Render}, "FILE", "write the compiled render graph as JSON (passes, resources, barriers, timings)", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.graphJson = parsePath(flag, v); },
         .example = "graph.json"},
        {.name = "--explain",
         .uses = {{{Kind::Render}, "",
                   "print the camera used (as the flags that reproduce it) and which passes and shader variants were "
                   "left out, and why",
                   ""},
                  {{Kind::Bench}, "",
                   "print the camera used (as the flags that reproduce it) and which passes and shader variants the "
                   "measured frames left out, and why (with --json: as \"explain\")",
                   ""}},
         .set = [](Command& c, Str, Str) { c.render.explain = true; }},
        {.name = "--dither",
         .uses = {{{Kind::Render, Kind::Bench}, "", "dither the 8-bit output (the viewer always does)", ""}},
         .set = [](Command& c, Str, Str) { c.render.dither = true; }},
        {.name = "--json",
         .uses = {{{Kind::Bench}, "", "machine-readable output", ""}},
         .set = [](Command& c, Str, Str) { c.render.json = true; }},
        {.name = "--in-flight",
         .uses = {{{Kind::Bench}, "", "also run the frames as the viewer does, into an offscreen image with frames in "
                                      "flight: frame time and how far recording overlaps the GPU", ""}},
         .set = [](Command& c, Str, Str) { c.render.inFlight = true; }},
        // ---- the viewer ----
        {.name = "--screenshot",
         .uses = {{{Kind::View}, "FILE", "save the last of the --frames N frames, UI included, as PNG", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.screenshot = parsePath(flag, v); },
         .example = "shot.png"},
        {.name = "--no-vsync",
         .uses = {{{Kind::View}, "", "present without waiting for the display (mailbox or immediate)", ""}},
         .set = [](Command& c, Str, Str) { c.render.vsync = false; }},
        {.name = "--no-ui",
         .uses = {{{Kind::View}, "", "hide the ImGui panels (the ImGui pass is left out)", ""}},
         .set = [](Command& c, Str, Str) { c.render.ui = false; }},
        {.name = "--panels",
         .uses = {{{Kind::View}, "LIST", "the panels open at start, comma-separated: {choices}", panelList(ui::kPanelsOpenByDefault)}},
         .choices = namesOf(ui::kPanelNames),
         .set = [](Command& c, Str flag, Str v) {
             c.render.panels.clear();
             for (const std::string& item : commaSeparated(v)) c.render.panels.insert(parseChoice(flag, ui::kPanelNames, item));
         },
         .example = "camera,debug"},
        {.name = "--shaders",
         .uses = {{{Kind::View}, "DIR", "hot-reload the shaders from DIR [the source tree's shaders/ folder]", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.shaderDir = parsePath(flag, v); },
         .example = "shaders"},
        {.name = "--ibl-report",
         .uses = {{{Kind::View}, "FILE", "show this ibl-report CSV's figures in the environment panel too", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.iblReport = parsePath(flag, v); },
         .example = "report.csv"},
        // ---- scene, animation and camera ----
        {.name = "--scene",
         .uses = {{kRenderViewBench, "FILE", "a glTF 2.0 scene (.gltf or .glb) [the built-in 7 x 7 sphere grid]", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.scene = parsePath(flag, v); },
         .example = "model.glb"},
        {.name = "--scene-index",
         .uses = {{kRenderViewBench, "N", "which of the glTF file's scenes to draw [the file's default scene, else 0]", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.sceneIndex = parseDimension(flag, v); },
         .example = "1"},
        {.name = "--grid",
         .uses = {{kRenderViewBench, "N", "the built-in grid with N x N spheres over its 7 x 7 materials, framed alike [7]", ""}},
         .set = [](Command& c, Str flag, Str v) {
             c.render.grid = parseDimension(flag, v);
             if (*c.render.grid == 0 || *c.render.grid > 1000)
                 throw UserError(flag + ": expected 1 to 1000 spheres a side, got '" + v + "'");
         },
         .example = "3"},
        {.name = "--distinct-materials",
         .uses = {{kRenderViewBench, "",
                   "the built-in grid with a material of its own on every sphere (N x N materials: a stress scene)", ""}},
         .set = [](Command& c, Str, Str) { c.render.distinctMaterials = true; }},
        {.name = "--variant",
         .uses = {{kRenderViewBench, "NAME",
                   "draw the file's KHR_materials_variants variant NAME (an unknown name is an error that lists the "
                   "file's variants; render: all draws each variant, --out then needs {variant}) [the default materials]",
                   ""}},
         .set = [](Command& c, Str flag, Str v) {
             if (v.empty()) throw UserError(flag + ": expected a variant name");
             c.render.variant = v;
         },
         .example = "red"},
        {.name = "--animation",
         .uses = {{kRenderViewBench, "LIST",
                   "the glTF animations to play: indices or names, all or none (rest pose); comma-separated or "
                   "repeated [0, when the scene has animations]",
                   ""}},
         .set = [](Command& c, Str flag, Str v) {
             for (const std::string& item : commaSeparated(v)) {
                 if (item.empty()) throw UserError(flag + ": expected indices, names, all or none, got '" + v + "'");
                 c.render.animations.push_back(item);
             }
         },
         .example = "Walk,2"},
        {.name = "--time",
         .uses = {{kRenderViewBench, "SECONDS", "the moment of the animations to draw; each loops over its own duration", "0"}},
         .set = [](Command& c, Str flag, Str v) { c.render.time = parseSeconds(flag, v); },
         .example = "1.5"},
        {.name = "--camera",
         .uses = {{kRenderViewBench, "INDEX", "use the scene's glTF camera INDEX", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.camera = parseDimension(flag, v); },
         .example = "0"},
        {.name = "--camera-orbit",
         .uses = {{kRenderViewBench, "T,P,R",
                   "orbit camera: azimuth T and polar angle P in degrees, distance R in metres (eye = target + R(sin P "
                   "sin T, cos P, sin P cos T); R <= 0 frames the scene: the nearest distance where its bounding box fits "
                   "the image at a 45-degree field of view) [0,75,0: from the front, 15 degrees above the horizon, framing "
                   "the scene; the built-in grid head-on, 0,90,0; --explain prints the camera used as flags]",
                   ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.cameraOrbit = parseTriple(flag, v); },
         .example = "30,70,5"},
        {.name = "--target",
         .uses = {{kRenderViewBench, "X,Y,Z", "the point the orbit camera looks at [the centre of the scene bounds]", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.target = parseTriple(flag, v); },
         .example = "0,1,0"},
        {.name = "--fov",
         .uses = {{kRenderViewBench, "DEGREES",
                   "vertical field of view of the orbit camera; framing keeps its distance, so a narrower field "
                   "shows the model bigger", "45"}},
         .set = [](Command& c, Str flag, Str v) {
             c.render.fovDegrees = parseNumber(flag, v);
             if (c.render.fovDegrees <= 0.0f || c.render.fovDegrees >= 180.0f)
                 throw UserError(flag + ": expected degrees between 0 and 180, got '" + v + "'");
         },
         .example = "60"},
        // ---- shading and image ----
        {.name = "--shading",
         .uses = {{kRenderViewBench, "MODEL",
                   "the shading model: {choices} (pbr: height-correlated Smith GGX; pbr-schlick-ggx: the original "
                   "project's geometry term; blinn-phong: its first shader)",
                   "pbr"}},
         .choices = namesOf(passes::kShadingModelNames),
         .set = [](Command& c, Str flag, Str v) { c.render.shading = parseChoice(flag, passes::kShadingModelNames, v); },
         .example = "blinn-phong"},
        {.name = "--debug-view",
         .uses = {{kRenderViewBench, "NAME",
                   "show a material input or a shading term instead of the image (d, g, f: the GGX terms toward the "
                   "first light; docs/shading.md): {choices}",
                   "none"}},
         .choices = namesOf(passes::kDebugViewNames),
         .set = [](Command& c, Str flag, Str v) { c.render.debugView = parseChoice(flag, passes::kDebugViewNames, v); },
         .example = "roughness"},
        {.name = "--tonemap",
         .uses = {{kRenderViewBench, "OP", "the tone mapping operator: {choices} (aces: Hill's RRT+ODT fit)", "pbr-neutral"}},
         .choices = namesOf(passes::kTonemapNames),
         .set = [](Command& c, Str flag, Str v) { c.render.tonemap = parseChoice(flag, passes::kTonemapNames, v); },
         .example = "agx"},
        {.name = "--exposure",
         .uses = {{kRenderViewBench, "EV", "exposure in stops", "0"}},
         .set = [](Command& c, Str flag, Str v) { c.render.exposureEv = parseNumber(flag, v); },
         .example = "1"},
        {.name = "--background",
         .uses = {{kRenderViewBench, "BG",
                   "what shows where the scene draws nothing: {choices} (auto: the skybox with an environment, #262626 "
                   "without; transparent: alpha 0 in PNG)",
                   "auto"}},
         .choices = namesOf(kBackgroundNames),
         .otherForm = "#rrggbb",
         .set = [](Command& c, Str flag, Str v) {
             c.render.background = v.rfind('#', 0) == 0
                                       ? Background{Background::Kind::Color, parseHexColor(flag, v)}
                                       : Background{parseChoice(flag, kBackgroundNames, v, "#rrggbb")};
         },
         .example = "#102030"},
        {.name = "--msaa",
         .uses = {{kRenderViewBench, "{choices}",
                   "samples per pixel of the scene's draw targets, resolved into the HDR image; clamped to what the "
                   "device supports, with a warning [4 on GPUs, 1 on CPU devices such as lavapipe: `candela "
                   "info` says which]",
                   ""},
                  {{Kind::QualityReport}, "N,N,...", "sample counts, each {choices} (those the device lacks are clamped, noted)",
                   "1,2,4,8"}},
         .choices = namesOf(kSampleCounts),
         .set = [](Command& c, Str flag, Str v) {
             if (c.kind != Kind::QualityReport) {
                 c.render.msaa = parseChoice(flag, kSampleCounts, v);
                 return;
             }
             c.qualityReport.msaa.clear();
             for (const std::string& item : commaSeparated(v)) c.qualityReport.msaa.push_back(parseChoice(flag, kSampleCounts, item));
         },
         .example = "2"},
        {.name = "--precompile",
         .uses = {{{Kind::Render, Kind::Bench}, "{choices}",
                   "when the scene's pipeline variants compile: at each first draw (off), on worker threads before the "
                   "frame's draws (frame), and also every debug view's in the background (debug-views)",
                   passes::precompileName(passes::Precompile::Frame)},
                  {{Kind::View}, "{choices}", "as for render; debug-views: a switch of the debug view does not stall",
                   passes::precompileName(passes::Precompile::DebugViews)}},
         .choices = namesOf(passes::kPrecompileNames),
         .set = [](Command& c, Str flag, Str v) { c.render.precompile = parseChoice(flag, passes::kPrecompileNames, v); },
         .example = "off"},
        {.name = "--shading-path",
         .uses = {{kRenderViewBench, "{choices}",
                   "how opaque and masked surfaces are shaded: as their triangles are rasterized (forward), or once per "
                   "covered pixel from a visibility buffer, in compute (visibility); auto: the device's default "
                   "(candela info says which and why)",
                   passes::shadingPathName(passes::ShadingPath::Auto)}},
         .choices = namesOf(passes::kShadingPathNames),
         .set = [](Command& c, Str flag, Str v) { c.render.shadingPath = parseChoice(flag, passes::kShadingPathNames, v); },
         .example = "visibility"},
        {.name = "--specular-aa",
         .uses = {{kRenderViewBench, "{choices}",
                   "widen the roughness by the normal's change across a pixel and by what a normal map's mips average "
                   "away (less shimmering highlights)",
                   passes::ShadingOptions{}.specularAntiAliasing ? "on" : "off"}},
         .choices = namesOf(kOnOff),
         .set = [](Command& c, Str flag, Str v) { c.render.specularAa = parseChoice(flag, kOnOff, v); },
         .example = "on"},
        {.name = "--lod-error",
         .uses = {{kRenderViewBench, "PIXELS",
                   "draw each mesh at the coarsest level of detail whose geometric error covers at most PIXELS on "
                   "screen; 0: full detail",
                   valueText(selection.lodErrorPixels)},
                  {{Kind::ScaleReport}, "PIXELS", "the level-of-detail error of the \"on\" runs", valueText(selection.lodErrorPixels)}},
         .set = [](Command& c, Str flag, Str v) {
             const bool scaleReport = c.kind == Kind::ScaleReport;
             (scaleReport ? c.scaleReport.lodErrorPixels : c.render.lodErrorPixels) = parsePixels(flag, v, !scaleReport);
         },
         .example = "2"},
        {.name = "--lod",
         .uses = {{kRenderViewBench, "{choices}", "levels of detail (on: --lod-error " + valueText(selection.lodErrorPixels) + ", off: 0)", ""}},
         .choices = namesOf(kOnOff),
         .set = [](Command& c, Str flag, Str v) {
             c.render.lodErrorPixels = parseChoice(flag, kOnOff, v) ? passes::DrawSelection::kDefaultLodErrorPixels : 0.0f;
         },
         .example = "off"},
        {.name = "--cull",
         .uses = {{kRenderViewBench, "{choices}", "leave out draws outside the view frustum", selection.frustumCulling ? "on" : "off"}},
         .choices = namesOf(kOnOff),
         .set = [](Command& c, Str flag, Str v) { c.render.frustumCulling = parseChoice(flag, kOnOff, v); },
         .example = "off"},
        {.name = "--disable-pass",
         .uses = {{kRenderViewBench, "NAME", "switch a pass off (repeatable): the frame is drawn without what it adds (skybox: no sky; "
                   "transmission_background: transmissive surfaces see only the background; skin_morph: skinned and "
                   "morphed meshes left out); a pass the image cannot be made without is an error naming it", ""}},
         .set = [](Command& c, Str, Str v) { c.render.disabledPasses.push_back(v); },
         .example = "skybox"},
        // ---- lights and image-based lighting ----
        {.name = "--no-default-lights",
         .uses = {{kRenderViewBench, "", "no key and fill light for a scene without punctual lights and environment", ""}},
         .set = [](Command& c, Str, Str) { c.render.defaultLights = false; }},
        {.name = "--scene-lights",
         .uses = {{kRenderViewBench, "{choices}",
                   "the file's own KHR_lights_punctual lights (off: image-based lighting only, for comparisons; the "
                   "scene then counts as one without lights)",
                   "on"}},
         .choices = namesOf(kOnOff),
         .set = [](Command& c, Str flag, Str v) { c.render.sceneLights = parseChoice(flag, kOnOff, v); },
         .example = "off"},
        {.name = "--env",
         .uses = {{kRenderViewBench, "ENV",
                   "image-based lighting from an equirectangular .hdr or .exr file, the built-in procedural sky (sky), "
                   "or none. Orientation: the glTF Sample Viewer's (the image centre faces +X, top row +Y); see "
                   "docs/environments.md",
                   "sky"},
                  {{Kind::IblReport}, "ENV", "the environment measured: an .hdr/.exr file or sky", "sky"},
                  {{Kind::QualityReport}, "ENV", "the glTF scenes' environment: an .hdr/.exr file or sky (the grid: the sky)", "sky"}},
         .set = [](Command& c, Str flag, Str v) {
             if (v.empty()) throw UserError(flag + ": expected an .hdr/.exr file, sky or none");
             const EnvironmentChoice env = v == "sky"    ? EnvironmentChoice{}
                                           : v == "none" ? EnvironmentChoice{EnvironmentChoice::Kind::None}
                                                         : EnvironmentChoice{EnvironmentChoice::Kind::File, v};
             if (env.kind == EnvironmentChoice::Kind::None && c.kind != Kind::Render && c.kind != Kind::View && c.kind != Kind::Bench)
                 throw UserError(flag + ": " + commandName(c.kind) + " needs an environment (an .hdr/.exr file or sky)");
             onOptions(c, [&](auto& o) { if constexpr (requires { o.env; }) o.env = env; });
         },
         .example = "studio.hdr"},
        {.name = "--env-rotation",
         .uses = {{kRenderViewBench, "DEG", "turn the environment about +Y (from +X towards +Z)", valueText(look.rotationDegrees)}},
         .set = [](Command& c, Str flag, Str v) { c.render.iblLook.rotationDegrees = parseNumber(flag, v); },
         .example = "90"},
        {.name = "--env-intensity",
         .uses = {{kRenderViewBench, "K", "scale the environment's radiance", valueText(look.intensity)}},
         .set = [](Command& c, Str flag, Str v) {
             c.render.iblLook.intensity = parseNumber(flag, v);
             if (c.render.iblLook.intensity < 0.0f) throw UserError(flag + ": must be ≥ 0, got '" + v + "'");
         },
         .example = "2"},
        {.name = "--skybox-blur",
         .uses = {{kRenderViewBench, "B", "show the environment behind the scene blurred like roughness B, 0..1", valueText(look.skyboxBlur)}},
         .set = [](Command& c, Str flag, Str v) {
             c.render.iblLook.skyboxBlur = parseNumber(flag, v);
             if (c.render.iblLook.skyboxBlur < 0.0f || c.render.iblLook.skyboxBlur > 1.0f)
                 throw UserError(flag + ": expected 0 (sharp) to 1, got '" + v + "'");
         },
         .example = "0.3"},
        {.name = "--no-multiscatter",
         .uses = {{kRenderViewBench, "", "single-scattering split sum only (no Fdez-Aguera energy compensation)", ""}},
         .set = [](Command& c, Str, Str) { c.render.iblLook.multiscatter = false; }},
        {.name = "--ibl-cache",
         .uses = {{kRenderViewBench, "DIR", "keep precomputed IBL maps in DIR, keyed by environment content and quality", ""}},
         .set = [](Command& c, Str flag, Str v) { c.render.iblCache = parsePath(flag, v); },
         .example = "cache"},
        {.name = "--irradiance",
         .uses = {{kRenderViewBench, "{choices}", "diffuse irradiance as 9 spherical-harmonic coefficients (sh9) or a cube",
                   ibl::irradianceModeName(quality.irradiance)}},
         .choices = namesOf(ibl::kIrradianceModeNames),
         .set = [](Command& c, Str flag, Str v) {
             c.render.iblQuality.irradiance = parseChoice(flag, ibl::kIrradianceModeNames, v);
         },
         .example = "sh9"},
        iblQualityFlag("--ibl-cube-size", "environment cube face size, 2^k from 16 to 2048", &ibl::IblQuality::cubeSize, "128"),
        iblQualityFlag("--ibl-levels", "specular roughness levels (mips)", &ibl::IblQuality::specularLevels, "5"),
        iblQualityFlag("--ibl-prefilter-samples",
                       "GGX samples per texel of the first rough specular mip; 4x more per coarser mip, at most 4096",
                       &ibl::IblQuality::prefilterSamples, "32"),
        {.name = "--ibl-lod-bias",
         .uses = {{kRenderViewBench, "B", "filtered-importance-sampling lod bias (more: less noise, more blur)", valueText(quality.lodBias)}},
         .set = [](Command& c, Str flag, Str v) { c.render.iblQuality.lodBias = parseNumber(flag, v); },
         .example = "1"},
        iblQualityFlag("--ibl-bright-texels",
                       "the environment's brightest texels (a sun) summed exactly by the filters, not sampled; 0: none",
                       &ibl::IblQuality::brightTexels, "0"),
        iblQualityFlag("--ibl-sh-size", "face size of the cube mip projected onto SH9", &ibl::IblQuality::shSourceSize, "16"),
        iblQualityFlag("--ibl-irradiance-size", "irradiance cube face size (--irradiance cube)", &ibl::IblQuality::irradianceSize, "16"),
        iblQualityFlag("--ibl-irradiance-samples", "cosine samples per irradiance cube texel (--irradiance cube)",
                       &ibl::IblQuality::irradianceSamples, "128"),
        iblQualityFlag("--ibl-lut-size", "BRDF LUT size", &ibl::IblQuality::lutSize, "64"),
        iblQualityFlag("--ibl-lut-samples", "BRDF LUT samples per texel", &ibl::IblQuality::lutSamples, "128"),
        // ---- the report commands and soak ----
        {.name = "--repeats",
         .uses = {{{Kind::IblReport}, "N",
                   "rounds of precompute runs over every setting, a calibration run before each; the median time and "
                   "its quartiles are reported, over the median calibration",
                   "3"},
                  {{Kind::QualityReport}, "N",
                   "rounds of --frames timed frames over every setting; the median ratio and its quartiles are "
                   "reported",
                   "5"}},
         .set = [](Command& c, Str flag, Str v) {
             onOptions(c, [&](auto& o) { if constexpr (requires { o.repeats; }) o.repeats = parseCount(flag, v); });
         },
         .example = "1"},
        {.name = "--quick",
         .uses = {{{Kind::IblReport}, "", "a reduced sweep (smoke tests)", ""}},
         .set = [](Command& c, Str, Str) { c.iblReport.quick = true; }},
        {.name = "--reference-samples",
         .uses = {{{Kind::IblReport}, "N", "samples per pixel of the ground-truth render (at least 16)", "4096"}},
         .set = [](Command& c, Str flag, Str v) {
             c.iblReport.referenceSamples = parseDimension(flag, v);
             if (c.iblReport.referenceSamples < 16) throw UserError(flag + ": need at least 16");
         },
         .example = "64"},
        {.name = "--sizes",
         .uses = {{{Kind::ScaleReport}, "N,N,...", "grid sides", "1,2,5,10,20,50,100"}},
         .set = [](Command& c, Str flag, Str v) {
             c.scaleReport.sizes.clear();
             for (const std::string& item : commaSeparated(v)) {
                 const uint32_t side = parseDimension(flag, item);
                 if (side == 0 || side > 1000) throw UserError(flag + ": expected grid sides from 1 to 1000, got '" + v + "'");
                 c.scaleReport.sizes.push_back(side);
             }
         },
         .example = "1,3"},
        {.name = "--scenes",
         .uses = {{{Kind::QualityReport}, "A,B,...", "default (the built-in grid under the sky) and/or glTF files", "default"}},
         .set = [](Command& c, Str flag, Str v) {
             c.qualityReport.scenes = commaSeparated(v);
             const std::vector<std::string>& scenes = c.qualityReport.scenes;
             if (std::find(scenes.begin(), scenes.end(), "") != scenes.end())
                 throw UserError(flag + ": expected default or glTF files, comma-separated, got '" + v + "'");
         },
         .example = "default,model.glb"},
        {.name = "--lod-errors",
         .uses = {{{Kind::QualityReport}, "PX,PX,...", "level-of-detail errors in pixels", "0,0.5,1,2,4"}},
         .set = [](Command& c, Str flag, Str v) {
             c.qualityReport.lodErrors.clear();
             for (const std::string& item : commaSeparated(v)) {
                 const float pixels = parseNumber(flag, item);
                 if (!(pixels >= 0.0f)) throw UserError(flag + ": expected pixels ≥ 0, got '" + v + "'");
                 c.qualityReport.lodErrors.push_back(pixels);
             }
         },
         .example = "0,1"},
        {.name = "--orbit-frames",
         .uses = {{{Kind::QualityReport}, "N", "frames of the 1-degree-per-frame orbit (error and temporal difference)", "6"}},
         .set = [](Command& c, Str flag, Str v) { c.qualityReport.orbitFrames = parseCount(flag, v); },
         .example = "2"},
        {.name = "--switch-every",
         .uses = {{{Kind::Soak}, "K", "frames per environment (4 procedural skies, cycled; each switch reruns the IBL precompute)", "100"}},
         .set = [](Command& c, Str flag, Str v) { c.soak.switchEvery = parseCount(flag, v); },
         .example = "10"},
        {.name = "--sample-every",
         .uses = {{{Kind::Soak}, "K", "frames between memory samples", "100"}},
         .set = [](Command& c, Str flag, Str v) { c.soak.sampleEvery = parseCount(flag, v); },
         .example = "10"},
        // ---- diff ----
        {.name = "--ppd",
         .uses = {{{Kind::Diff}, "PPD",
                   "pixels per degree of visual angle the images are seen at; overrides the monitor flags [from "
                   "them: about 67]",
                   ""}},
         .set = [](Command& c, Str flag, Str v) { c.diff.ppd = positiveNumber(flag, v, "pixels per degree"); },
         .example = "40"},
        {.name = "--monitor-distance",
         .uses = {{{Kind::Diff}, "M", "distance from the viewer to the monitor in metres", "0.7"}},
         .set = [](Command& c, Str flag, Str v) { c.diff.monitorDistance = positiveNumber(flag, v, "metres"); },
         .example = "1"},
        {.name = "--monitor-width",
         .uses = {{{Kind::Diff}, "M", "width of the monitor's picture in metres", "0.7"}},
         .set = [](Command& c, Str flag, Str v) { c.diff.monitorWidth = positiveNumber(flag, v, "metres"); },
         .example = "0.5"},
        {.name = "--monitor-resolution",
         .uses = {{{Kind::Diff}, "PX", "the monitor's horizontal resolution in pixels", "3840"}},
         .set = [](Command& c, Str flag, Str v) { c.diff.monitorResolution = positiveNumber(flag, v, "pixels"); },
         .example = "1920"},
        {.name = "--threshold",
         .uses = {{{Kind::Diff}, "LEVELS",
                   "a pixel is over the threshold when one of its channels differs by more than LEVELS levels of "
                   "255 (EXR: LEVELS/255 in linear units)",
                   "5"}},
         .set = [](Command& c, Str flag, Str v) {
             c.diff.threshold = parseNumber(flag, v);
             if (c.diff.threshold < 0.0) throw UserError(flag + ": expected levels >= 0, got '" + v + "'");
         },
         .example = "2"},
        {.name = "--max-flip",
         .uses = {{{Kind::Diff}, "X", "fail a pair whose mean FLIP is above X (0 to 1) [not checked]", ""}},
         .set = [](Command& c, Str flag, Str v) { c.diff.maxFlip = unitFraction(flag, v); },
         .example = "0.05"},
        {.name = "--max-fraction",
         .uses = {{{Kind::Diff}, "F",
                   "fail a pair whose fraction of pixels over --threshold is above F (0 to 1; Filament's renderdiff "
                   "gate is --threshold 5 --max-fraction 0.001) [not checked]",
                   ""}},
         .set = [](Command& c, Str flag, Str v) { c.diff.maxFraction = unitFraction(flag, v); },
         .example = "0.001"},
        {.name = "--error-maps",
         .uses = {{{Kind::Diff}, "DIR",
                   "write each compared pair's FLIP error map as a magma-coloured PNG under DIR, at the pair's relative "
                   "path (an EXR pair's with .png added)",
                   ""}},
         .set = [](Command& c, Str flag, Str v) { c.diff.errorMaps = parsePath(flag, v); },
         .example = "maps"},
        // ---- device and output of every command ----
        {.name = "--device",
         .uses = {{kAll, "SEL", "device index or case-insensitive name substring (see candela info)", ""}},
         .set = [](Command& c, Str, Str v) { c.common().device = v; },
         .example = "0"},
        {.name = "--device-profile",
         .uses = {{kAll, "NAME",
                   "see the device through a profile: minimum (what Vulkan 1.3 guarantees), desktop or apple (published "
                   "device reports) or native, the device itself [CANDELA_DEVICE_PROFILE, else native]",
                   ""}},
         .set = [](Command& c, Str flag, Str v) {
             const std::optional<vk::DeviceProfile> profile = vk::parseDeviceProfile(v);
             if (!profile) throw UserError(flag + ": no device profile '" + v + "' (profiles: " + vk::deviceProfileList() + ")");
             c.common().deviceProfile = *profile;
         },
         .example = "minimum"},
        {.name = "--validate",
         .uses = {{kAll, "", "Khronos validation with synchronization validation (also CANDELA_VALIDATE=1)", ""}},
         .set = [](Command& c, Str, Str) { c.common().validate = true; }},
        {.name = "--memory-budget",
         .uses = {{{Kind::Render, Kind::View, Kind::Bench, Kind::IblReport, Kind::ScaleReport, Kind::QualityReport, Kind::Soak},
                   "MIB",
                   "allocate at most MIB MiB of device memory (simulates a small device: what does not fit is an error "
                   "naming the resource, exit code 4, or a lower IBL resolution with a warning)",
                   ""}},
         .set = [](Command& c, Str flag, Str v) {
             c.common().memoryBudgetMib = parseDimension(flag, v);
             if (c.common().memoryBudgetMib == 0) throw UserError(flag + ": need at least 1 MiB");
         },
         .example = "64"},
        {.name = "--pipeline-cache",
         .uses = {{{Kind::Render, Kind::View, Kind::Bench, Kind::IblReport, Kind::ScaleReport, Kind::QualityReport, Kind::Soak},
                   "DIR|off",
                   "keep compiled pipelines in a file in DIR across runs, one per device and driver (a damaged or "
                   "foreign file is ignored and replaced); off: in memory only [$XDG_CACHE_HOME/candela, else "
                   "~/.cache/candela]",
                   ""}},
         .set = [](Command& c, Str flag, Str v) { c.common().pipelineCache = parsePath(flag, v); },
         .example = "cache"},
        {.name = "--verbose",
         .uses = {{{Kind::Render, Kind::View, Kind::Bench}, "",
                   "also print notes on the files read (such as the degenerate triangles a glTF file's primitives had, "
                   "dropped quietly) and the camera used, as the flags that reproduce it",
                   ""},
                  {{Kind::IblReport, Kind::QualityReport}, "",
                   "also print notes on the files read (such as the degenerate triangles a glTF file's primitives had, "
                   "dropped quietly)",
                   ""}},
         .set = [](Command& c, Str, Str) { c.common().verbose = true; }},
        {.name = "--quiet",
         .uses = {{{Kind::Render, Kind::IblReport, Kind::ScaleReport, Kind::QualityReport, Kind::Soak}, "",
                   "no progress line (render: of an image sequence); one that rewrites itself on a terminal, a plain "
                   "line every 10 s otherwise",
                   ""}},
         .set = [](Command& c, Str, Str) { c.common().quiet = true; }},
    };
    return flags;
}

}  // namespace

const std::vector<Flag>& flagTable() {
    static const std::vector<Flag> flags = makeFlagTable();
    return flags;
}

const Flag* findFlag(std::string_view name) {
    for (const Flag& flag : flagTable())
        if (flag.name == name) return &flag;
    return nullptr;
}

const FlagUse* Flag::use(Command::Kind kind) const {
    for (const FlagUse& u : uses)
        if (u.commands.contains(kind)) return &u;
    return nullptr;
}

CommandSet Flag::commands() const {
    CommandSet all{};
    for (const FlagUse& u : uses) all.bits |= u.commands.bits;
    return all;
}

}  // namespace candela::app
