#pragma once
// Command-line parsing for the `candela` executable. Pure (no Vulkan), unit-tested.
// Every malformed argument throws candela::UserError with a one-line message naming the flag.

#include "ibl/ibl_settings.h"
#include "passes/draw_selection.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace candela::app {

struct CommonOptions {
    std::string device;     // --device INDEX|NAME
    bool validate = false;  // --validate
    bool verbose = false;   // --verbose
    bool quiet = false;     // --quiet: no progress lines
    uint32_t memoryBudgetMib = 0;  // --memory-budget MIB (0: the device's memory)
};

struct RenderOptions {
    CommonOptions common;
    std::string scene;                // --scene FILE (.gltf/.glb); empty: the built-in sphere grid
    std::optional<uint32_t> sceneIndex;  // --scene-index N: which of the file's scenes [its `scene`, else 0]
    std::optional<uint32_t> camera;   // --camera INDEX (glTF camera)
    std::optional<std::array<float, 3>> cameraOrbit;  // --camera-orbit THETA,PHI,RADIUS
    std::optional<std::array<float, 3>> target;       // --target X,Y,Z
    float fovDegrees = 45.0f;         // --fov DEGREES (vertical)
    std::string shading = "pbr";      // --shading pbr|pbr-schlick-ggx|blinn-phong
    std::string debugView = "none";   // --debug-view NAME (passes::parseDebugView)
    std::string tonemap = "pbr-neutral";  // --tonemap pbr-neutral|aces|agx|reinhard|linear
    float exposureEv = 0.0f;          // --exposure EV
    std::string background = "auto";  // --background auto|transparent|#rrggbb|skybox
    std::string env = "sky";          // --env FILE|sky|none (sky: the built-in procedural sky)
    ibl::IblQuality iblQuality;       // --irradiance, --ibl-cube-size, --ibl-prefilter-samples, ...
    ibl::IblLook iblLook;             // --env-rotation, --env-intensity, --skybox-blur, --no-multiscatter
    std::string iblCache;             // --ibl-cache DIR
    bool dither = false;              // --dither
    bool defaultLights = true;        // --no-default-lights turns off the key/fill lights of light-less scenes
    bool sceneLights = true;          // --scene-lights off leaves out the file's own punctual lights
    std::string variant;              // --variant NAME: a KHR_materials_variants variant ("" = defaults)
    float lodErrorPixels = passes::DrawSelection::kDefaultLodErrorPixels;  // --lod-error PIXELS (0, or --lod off: full detail)
    bool frustumCulling = true;       // --cull on|off
    bool specularAa = false;          // --specular-aa on|off
    std::optional<uint32_t> msaa;     // --msaa 1|2|4|8 (unset: the device default)
    bool explain = false;             // --explain
    uint32_t frames = 20;             // bench: --frames N; view: frames to render before exiting (0: until closed)
    std::string screenshot;           // view: --screenshot FILE (saves the last of --frames N)
    bool vsync = true;                // view: --no-vsync
    bool ui = true;                   // view: --no-ui
    std::string shaderDir;            // view: --shaders DIR (hot reload; default: the source tree's shaders/)
    std::string iblReport;            // view: --ibl-report FILE (an ibl-report CSV for the environment panel)
    std::vector<std::string> panels = {"graph", "parameters", "stats"};  // view: --panels A,B,... (open at start)
    bool json = false;                // bench: --json
    uint32_t grid = 7;                // --grid N: N × N spheres of the built-in grid
    std::string out = "candela.png";  // --out FILE (.png, .exr, .pfm)
    uint32_t width = 1280;            // --width W
    uint32_t height = 720;            // --height H
    std::string graphDot;             // --graph-dot FILE
    std::string graphJson;            // --graph-json FILE
    std::vector<std::string> disabledPasses;  // --disable-pass NAME (repeatable)
    // --animation LIST (repeatable, comma-separated: indices, names, all, none); empty: animation 0
    std::vector<std::string> animations;
    double time = 0.0;                // --time SECONDS (each animation loops over its duration)
    // render: an image sequence of --frames N (default 1) frames at --fps F, written to the --out
    // pattern (one %d, e.g. frame_%04d.png); frame i shows --time + i / F, and with
    // --turntable DEGREES the orbit camera turns that far over the sequence.
    double fps = 30.0;
    float turntableDegrees = 0.0f;
};

// The file name of frame `index` of an image sequence: `pattern` with its one %d or %0Nd replaced.
// Throws UserError when the pattern does not hold exactly one such field (% written as %%).
std::string sequenceFileName(const std::string& pattern, uint32_t index);

struct InfoOptions {
    CommonOptions common;
};

struct IblReportOptions {
    CommonOptions common;
    std::string env = "sky";            // --env FILE|sky
    std::string out = "ibl-report";     // --out DIR (created)
    uint32_t repeats = 3;               // --repeats N: precompute runs per setting (median)
    bool quick = false;                 // --quick: a reduced sweep (tests, smoke runs)
    uint32_t width = 320;               // --width, --height: end-to-end image size
    uint32_t height = 180;
    uint32_t referenceSamples = 4096;   // --reference-samples N: per pixel of the ground-truth render
};

struct SoakOptions {
    CommonOptions common;
    uint32_t frames = 10000;     // --frames N
    uint32_t switchEvery = 100;  // --switch-every K: frames per environment
    uint32_t sampleEvery = 100;  // --sample-every K
    uint32_t width = 320;        // --width, --height
    uint32_t height = 180;
    std::string out;             // --out FILE.csv (optional)
};

struct ScaleReportOptions {
    CommonOptions common;
    std::string out = "scale-report";                            // --out DIR (created)
    std::vector<uint32_t> sizes = {1, 2, 5, 10, 20, 50, 100};     // --sizes N,N,...: grid sides
    uint32_t frames = 5;                                          // --frames N per setting
    float lodErrorPixels = passes::DrawSelection::kDefaultLodErrorPixels;  // --lod-error PIXELS: the "on" setting
    uint32_t width = 1280;                                        // --width, --height
    uint32_t height = 720;
};

struct QualityReportOptions {
    CommonOptions common;
    std::string out = "quality-report";           // --out DIR (created)
    std::vector<std::string> scenes = {"default"};  // --scenes default,FILE,...: the built-in grid or glTF files
    std::string env = "sky";                      // --env FILE|sky: the glTF scenes' environment (the grid: the sky)
    std::vector<uint32_t> msaa = {1, 2, 4, 8};    // --msaa N,N,...
    std::vector<float> lodErrors = {0.0f, 0.5f, 1.0f, 2.0f, 4.0f};  // --lod-errors PX,PX,...
    uint32_t frames = 5;                          // --frames N: timed frames per setting
    uint32_t orbitFrames = 6;                     // --orbit-frames N: frames of the 1°-per-frame orbit
    uint32_t width = 640;                         // --width, --height
    uint32_t height = 360;
};

struct Command {
    enum class Kind { Help, Render, View, Info, Bench, IblReport, Soak, ScaleReport, QualityReport } kind = Kind::Help;
    RenderOptions render;  // render, view and bench
    InfoOptions info;
    IblReportOptions iblReport;
    SoakOptions soak;
    ScaleReportOptions scaleReport;
    QualityReportOptions qualityReport;
    // The common options of the command (defaults for help).
    const CommonOptions& common() const;
};

// Parses argv[1..]. No arguments or --help → Kind::Help.
Command parseCommandLine(const std::vector<std::string>& args);

// Usage text printed by `candela --help`.
std::string usageText();

// Parses a decimal integer in [0, 2^32): "--width" and "abc" → UserError naming the flag.
uint32_t parseDimension(const std::string& flag, const std::string& value);
// Parses a finite decimal number; anything else → UserError naming the flag.
float parseNumber(const std::string& flag, const std::string& value);
// Parses a finite number of seconds >= 0, in double precision.
double parseSeconds(const std::string& flag, const std::string& value);
// Parses "A,B,C" (three finite numbers).
std::array<float, 3> parseTriple(const std::string& flag, const std::string& value);
// Parses "#rrggbb" into sRGB-encoded components in [0,1].
std::array<float, 3> parseHexColor(const std::string& flag, const std::string& value);

}  // namespace candela::app
