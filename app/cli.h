#pragma once
// Command-line parsing for the `candela` executable. Pure (no Vulkan), unit-tested.
// Every malformed argument throws candela::UserError with a one-line message naming the flag.
// The flags — name, value, help, default, the commands that take them and how each is parsed —
// are declared once, in the flag table (cli_flags.h); the options below hold the parsed values.

#include "cli_values.h"
#include "scene_batch.h"
#include "ibl/ibl_settings.h"
#include "passes/debug_view.h"
#include "passes/draw_selection.h"
#include "passes/precompile.h"
#include "passes/shading_path.h"
#include "passes/tonemap_operator.h"
#include "passes/shading_model.h"
#include "ui/viewer_panels.h"
#include "vk/device_profile.h"

#include <array>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace candela::app {

// An option whose flag declares a default in the table gets it from there (parseCommandLine
// applies the defaults of the command's flags before reading the arguments); the initial values
// below are those of switches and of flags whose default is "not given".

struct CommonOptions {
    std::string device;            // --device INDEX|NAME
    std::string pipelineCache;     // --pipeline-cache DIR|off ("": the user's cache folder)
    bool validate = false;         // --validate
    bool verbose = false;          // --verbose
    bool quiet = false;            // --quiet: no progress lines
    uint32_t memoryBudgetMib = 0;  // --memory-budget MIB (0: the device's memory)
    std::optional<vk::DeviceProfile> deviceProfile;  // --device-profile NAME (unset: CANDELA_DEVICE_PROFILE)
    bool operator==(const CommonOptions&) const = default;
};

// --env: the environment that lights the scene.
struct EnvironmentChoice {
    enum class Kind { Sky, None, File } kind = Kind::Sky;  // Sky: the built-in procedural sky
    std::string file;                                      // Kind::File: an equirectangular .hdr/.exr
    bool operator==(const EnvironmentChoice&) const = default;
};

// --background: what shows where the scene draws nothing.
struct Background {
    enum class Kind { Auto, Skybox, Transparent, Color } kind = Kind::Auto;  // Auto: the skybox with an environment, #262626 without
    std::array<float, 3> srgb{};  // Kind::Color: sRGB-encoded components in [0,1]
    bool operator==(const Background&) const = default;
};

inline constexpr std::pair<Background::Kind, const char*> kBackgroundNames[] = {
    {Background::Kind::Auto, "auto"}, {Background::Kind::Skybox, "skybox"}, {Background::Kind::Transparent, "transparent"}};

// The options of render, view and bench.
struct RenderOptions {
    CommonOptions common;
    std::string scene;                   // --scene FILE (.gltf/.glb), or view's SCENE; empty: the built-in sphere grid
    // render: SCENE... — glTF files, folders and @lists (scene_batch.h), after --scene's file.
    std::vector<std::string> inputs;
    std::string report;                  // render: --report FILE (JSON: per scene times, sizes, warnings, outputs)
    Shard shard;                         // render: --shard I/N
    std::string html;                    // render: --html FILE (a page of the run)
    bool inlineImages = false;           // render: --inline-images (the page holds its images)
    std::optional<uint32_t> sceneIndex;  // --scene-index N: which of the file's scenes [its `scene`, else 0]
    std::optional<uint32_t> camera;      // --camera INDEX (glTF camera)
    std::optional<std::array<float, 3>> cameraOrbit;  // --camera-orbit THETA,PHI,RADIUS
    std::optional<std::array<float, 3>> target;       // --target X,Y,Z
    float fovDegrees = 0.0f;                         // --fov DEGREES (vertical)
    passes::ShadingModel shading{};                  // --shading
    passes::DebugView debugView{};                   // --debug-view
    passes::Tonemap tonemap{};                       // --tonemap
    float exposureEv = 0.0f;                         // --exposure EV
    Background background;                           // --background
    EnvironmentChoice env;                           // --env FILE|sky|none
    ibl::IblQuality iblQuality;  // --irradiance, --ibl-cube-size, --ibl-prefilter-samples, ...
    ibl::IblLook iblLook;        // --env-rotation, --env-intensity, --skybox-blur, --no-multiscatter
    std::string iblCache;        // --ibl-cache DIR
    bool dither = false;         // --dither (render, bench; the viewer always dithers)
    bool defaultLights = true;   // --no-default-lights turns off the key/fill lights of light-less scenes
    bool sceneLights = true;     // --scene-lights off leaves out the file's own punctual lights
    std::string variant;         // --variant NAME: a KHR_materials_variants variant ("" = defaults; render: "all")
    float lodErrorPixels = 0.0f;  // --lod-error PIXELS (0, or --lod off: full detail)
    bool frustumCulling = true;   // --cull on|off
    bool specularAa = false;      // --specular-aa on|off
    std::optional<uint32_t> msaa;  // --msaa 1|2|4|8 (unset: the device default)
    passes::Precompile precompile{};  // --precompile off|frame|debug-views
    passes::ShadingPath shadingPath{};  // --shading-path auto|forward|visibility
    bool explain = false;          // --explain (render, bench)
    // --frames N: render: frames of an image sequence; bench: frames measured; view: frames to
    // render before exiting (0: until the window is closed).
    uint32_t frames = 0;
    std::string screenshot;       // view: --screenshot FILE (saves the last of --frames N)
    bool vsync = true;            // view: --no-vsync
    bool ui = true;               // view: --no-ui
    std::string shaderDir;        // view: --shaders DIR (hot reload; default: the source tree's shaders/)
    std::string iblReport;        // view: --ibl-report FILE (an ibl-report CSV for the environment panel)
    std::set<ui::Panel> panels;   // view: --panels A,B,... (open at start)
    bool json = false;            // bench: --json
    bool inFlight = false;        // bench: --in-flight (also frames as the viewer runs them, offscreen)
    std::optional<uint32_t> grid;  // --grid N: N × N spheres of the built-in grid (unset: its own 7 × 7)
    bool distinctMaterials = false;  // --distinct-materials: a material per sphere of the grid
    std::string out;              // render: --out FILE (.png, .exr, .pfm), a pattern with {name}, {path}, {variant}, {frame}
    uint32_t width = 0;           // --width W
    uint32_t height = 0;          // --height H
    std::string graphDot;         // render: --graph-dot FILE
    std::string graphJson;        // render: --graph-json FILE
    std::vector<std::string> disabledPasses;  // --disable-pass NAME (repeatable)
    // --animation LIST (repeatable, comma-separated: indices, names, all, none); empty: animation 0
    std::vector<std::string> animations;
    double time = 0.0;  // --time SECONDS (each animation loops over its duration)
    // render: an image sequence of --frames N frames at --fps F, written to the --out pattern (one
    // %d, e.g. frame_%04d.png); frame i shows --time + i / F, and with --turntable DEGREES the
    // orbit camera turns that far over the sequence.
    double fps = 0.0;
    float turntableDegrees = 0.0f;
    bool operator==(const RenderOptions&) const = default;
};

struct InfoOptions {
    CommonOptions common;
    bool operator==(const InfoOptions&) const = default;
};

struct IblReportOptions {
    CommonOptions common;
    EnvironmentChoice env;          // --env FILE|sky (never None)
    std::string out;                // --out DIR (created)
    uint32_t repeats = 0;           // --repeats N: rounds of precompute runs over every setting (median, spread)
    bool quick = false;             // --quick: a reduced sweep (tests, smoke runs)
    uint32_t width = 0;             // --width, --height: end-to-end image size
    uint32_t height = 0;
    uint32_t referenceSamples = 0;  // --reference-samples N: per pixel of the ground-truth render
    bool operator==(const IblReportOptions&) const = default;
};

struct SoakOptions {
    CommonOptions common;
    uint32_t frames = 0;       // --frames N
    uint32_t switchEvery = 0;  // --switch-every K: frames per environment
    uint32_t sampleEvery = 0;  // --sample-every K
    uint32_t width = 0;        // --width, --height
    uint32_t height = 0;
    std::string out;           // --out FILE.csv (optional)
    bool operator==(const SoakOptions&) const = default;
};

struct ScaleReportOptions {
    CommonOptions common;
    std::string out;               // --out DIR (created)
    std::vector<uint32_t> sizes;   // --sizes N,N,...: grid sides
    uint32_t frames = 0;           // --frames N per setting
    float lodErrorPixels = 0.0f;   // --lod-error PIXELS: the "on" setting
    uint32_t width = 0;            // --width, --height
    uint32_t height = 0;
    bool operator==(const ScaleReportOptions&) const = default;
};

struct QualityReportOptions {
    CommonOptions common;
    std::string out;                  // --out DIR (created)
    std::vector<std::string> scenes;  // --scenes default,FILE,...: the built-in grid or glTF files
    EnvironmentChoice env;            // --env FILE|sky: the glTF scenes' environment (the grid: the sky)
    std::vector<uint32_t> msaa;       // --msaa N,N,...
    std::vector<float> lodErrors;     // --lod-errors PX,PX,...
    uint32_t frames = 0;              // --frames N: timed frames per setting
    uint32_t orbitFrames = 0;         // --orbit-frames N: frames of the 1°-per-frame orbit
    uint32_t repeats = 0;             // --repeats N: rounds of timing over every setting
    uint32_t width = 0;               // --width, --height
    uint32_t height = 0;
    bool operator==(const QualityReportOptions&) const = default;
};

// `candela diff A B`: two PNG or EXR files, or two folders of them.
struct DiffOptions {
    CommonOptions common;              // (diff takes none of the common flags)
    std::string reference;             // A
    std::string test;                  // B
    std::optional<float> ppd;          // --ppd PPD (unset: from the monitor flags)
    float monitorDistance = 0.0f;      // --monitor-distance M
    float monitorWidth = 0.0f;         // --monitor-width M
    float monitorResolution = 0.0f;    // --monitor-resolution PX
    double threshold = 0.0;            // --threshold LEVELS
    std::optional<double> maxFlip;     // --max-flip X
    std::optional<double> maxFraction; // --max-fraction F
    std::string errorMaps;             // --error-maps DIR
    std::string report;                // --report FILE (JSON)
    std::string html;                  // --html FILE (a page of the comparison)
    bool inlineImages = false;         // --inline-images
    bool operator==(const DiffOptions&) const = default;
};

struct Command {
    enum class Kind { Help, Render, View, Info, Bench, IblReport, Soak, ScaleReport, QualityReport, Diff, Version } kind = Kind::Help;
    std::string helpCommand;  // Help: the command whose flags to list ("" for `candela --help`)
    RenderOptions render;     // render, view and bench
    InfoOptions info;
    IblReportOptions iblReport;
    SoakOptions soak;
    ScaleReportOptions scaleReport;
    QualityReportOptions qualityReport;
    DiffOptions diff;
    // The common options of the command (defaults for help and version).
    const CommonOptions& common() const;
    CommonOptions& common();
    bool operator==(const Command&) const = default;
};

// Parses argv[1..]. No arguments, --help or -h → Kind::Help (with a command: that command's
// help); --version → Kind::Version.
Command parseCommandLine(const std::vector<std::string>& args);

// `candela --help`: the commands and every flag, grouped by the commands that take them.
std::string usageText();
// `candela COMMAND --help`: the flags of `command` only. Precondition: `command` is a command name.
std::string commandHelp(std::string_view command);
// `candela --version`: "candela 0.1.0" (CMake's PROJECT_VERSION).
std::string versionText();

}  // namespace candela::app
