#include "cli.h"

#include "core/check.h"
#include "passes/debug_view.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>

namespace candela::app {
namespace {

// Flag handlers of one subcommand: a flag either takes a value or is a switch.
struct FlagTable {
    std::map<std::string, std::function<void(const std::string&)>> withValue;
    std::map<std::string, std::function<void()>> switches;
    std::function<void(const std::string&)> positional;  // null: no positional arguments
};

}  // namespace

const CommonOptions& Command::common() const {
    static const CommonOptions defaults;
    switch (kind) {
        case Kind::Help: return defaults;
        case Kind::Render:
        case Kind::View:
        case Kind::Bench: return render.common;
        case Kind::Info: return info.common;
        case Kind::IblReport: return iblReport.common;
        case Kind::Soak: return soak.common;
        case Kind::ScaleReport: return scaleReport.common;
        case Kind::QualityReport: return qualityReport.common;
    }
    return defaults;
}

namespace {

void addCommon(FlagTable& table, CommonOptions& common) {
    table.withValue["--device"] = [&](const std::string& v) { common.device = v; };
    table.switches["--validate"] = [&] { common.validate = true; };
    table.switches["--verbose"] = [&] { common.verbose = true; };
    table.switches["--quiet"] = [&] { common.quiet = true; };
    table.withValue["--memory-budget"] = [&](const std::string& v) {
        common.memoryBudgetMib = parseDimension("--memory-budget", v);
        if (common.memoryBudgetMib == 0) throw UserError("--memory-budget: need at least 1 MiB");
    };
}

// --out DIR of the report commands: the folder their files go to (created when they run).
void addOutputFolder(FlagTable& table, std::string& out) {
    table.withValue["--out"] = [&out](const std::string& v) {
        if (v.empty()) throw UserError("--out: expected a directory");
        out = v;
    };
}

void parseFlags(const std::string& command, const std::vector<std::string>& args, size_t first, const FlagTable& table) {
    for (size_t i = first; i < args.size(); ++i) {
        std::string flag = args[i];
        std::optional<std::string> inlineValue;
        if (const size_t eq = flag.find('='); flag.rfind("--", 0) == 0 && eq != std::string::npos) {
            inlineValue = flag.substr(eq + 1);
            flag = flag.substr(0, eq);
        }
        if (auto it = table.switches.find(flag); it != table.switches.end()) {
            if (inlineValue) throw UserError(flag + " takes no value");
            it->second();
            continue;
        }
        auto it = table.withValue.find(flag);
        if (it == table.withValue.end()) {
            if (flag.rfind("-", 0) == 0)
                throw UserError("unknown option '" + flag + "' for 'candela " + command + "' (see candela --help)");
            if (table.positional) {
                table.positional(flag);
                continue;
            }
            throw UserError("unexpected argument '" + flag + "' for 'candela " + command + "' (see candela --help)");
        }
        if (inlineValue) {
            it->second(*inlineValue);
        } else {
            if (i + 1 >= args.size()) throw UserError(flag + " needs a value");
            it->second(args[++i]);
        }
    }
}

}  // namespace

uint32_t parseDimension(const std::string& flag, const std::string& value) {
    const bool digits = !value.empty() && value.size() <= 10 &&
                        std::all_of(value.begin(), value.end(), [](unsigned char c) { return std::isdigit(c); });
    const unsigned long long number = digits ? std::stoull(value) : 0;
    if (!digits || number > 0xffffffffull)
        throw UserError(flag + ": expected a whole number of pixels, got '" + value + "'");
    return static_cast<uint32_t>(number);
}

float parseNumber(const std::string& flag, const std::string& value) {
    size_t used = 0;
    float number = 0.0f;
    try {
        number = std::stof(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (value.empty() || used != value.size() || !std::isfinite(number))
        throw UserError(flag + ": expected a number, got '" + value + "'");
    return number;
}

// The comma-separated items of `value`, empty ones included ("" gives one empty item).
static std::vector<std::string> commaSeparated(const std::string& value) {
    std::vector<std::string> items;
    for (size_t start = 0;;) {
        const size_t comma = value.find(',', start);
        items.push_back(value.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

std::array<float, 3> parseTriple(const std::string& flag, const std::string& value) {
    std::array<float, 3> out{};
    size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const size_t comma = value.find(',', start);
        if ((i < 2) != (comma != std::string::npos))
            throw UserError(flag + ": expected three comma-separated numbers, got '" + value + "'");
        out[i] = parseNumber(flag, value.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        start = comma + 1;
    }
    return out;
}

std::string sequenceFileName(const std::string& pattern, uint32_t index) {
    std::string out;
    int fields = 0;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        size_t j = i + 1;
        int width = 0;
        if (j < pattern.size() && pattern[j] == '0')
            while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width < 100)
                width = width * 10 + (pattern[j++] - '0');
        if (j >= pattern.size() || pattern[j] != 'd')
            throw UserError("--out " + pattern + ": an image sequence needs one %d or %0Nd for the frame number (and %% for a %)");
        std::string number = std::to_string(index);
        if (int(number.size()) < width) number.insert(0, size_t(width) - number.size(), '0');
        out += number;
        ++fields;
        i = j;
    }
    if (fields != 1)
        throw UserError("--out " + pattern + ": an image sequence needs exactly one %d or %0Nd for the frame number");
    return out;
}

double parseSeconds(const std::string& flag, const std::string& value) {
    double seconds = 0.0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), seconds);
    if (error != std::errc() || end != value.data() + value.size() || !std::isfinite(seconds) || seconds < 0.0)
        throw UserError(flag + ": expected a number of seconds >= 0, got '" + value + "'");
    return seconds;
}

std::array<float, 3> parseHexColor(const std::string& flag, const std::string& value) {
    const bool ok = value.size() == 7 && value[0] == '#' &&
                    std::all_of(value.begin() + 1, value.end(), [](unsigned char c) { return std::isxdigit(c); });
    if (!ok) throw UserError(flag + ": expected #rrggbb, got '" + value + "'");
    std::array<float, 3> out{};
    for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(std::stoi(value.substr(1 + 2 * i, 2), nullptr, 16)) / 255.0f;
    return out;
}

Command parseCommandLine(const std::vector<std::string>& args) {
    Command command;
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") return command;
    const std::string& name = args[0];
    FlagTable table;
    if (name == "render" || name == "bench" || name == "view") {
        command.kind = name == "render" ? Command::Kind::Render : name == "bench" ? Command::Kind::Bench : Command::Kind::View;
        RenderOptions& o = command.render;
        addCommon(table, o.common);
        if (command.kind != Command::Kind::View) table.withValue["--out"] = [&](const std::string& v) { o.out = v; };
        table.withValue["--width"] = [&](const std::string& v) { o.width = parseDimension("--width", v); };
        table.withValue["--height"] = [&](const std::string& v) { o.height = parseDimension("--height", v); };
        table.withValue["--graph-dot"] = [&](const std::string& v) { o.graphDot = v; };
        table.withValue["--graph-json"] = [&](const std::string& v) { o.graphJson = v; };
        table.withValue["--disable-pass"] = [&](const std::string& v) { o.disabledPasses.push_back(v); };
        table.withValue["--scene"] = [&](const std::string& v) { o.scene = v; };
        table.withValue["--grid"] = [&](const std::string& v) {
            o.grid = parseDimension("--grid", v);
            if (o.grid == 0 || o.grid > 1000) throw UserError("--grid: expected 1 to 1000 spheres a side, got '" + v + "'");
        };
        table.withValue["--scene-index"] = [&](const std::string& v) { o.sceneIndex = parseDimension("--scene-index", v); };
        table.withValue["--animation"] = [&](const std::string& v) {
            for (const std::string& item : commaSeparated(v)) {
                if (item.empty()) throw UserError("--animation: expected indices, names, all or none, got '" + v + "'");
                o.animations.push_back(item);
            }
        };
        table.withValue["--time"] = [&](const std::string& v) { o.time = parseSeconds("--time", v); };
        table.withValue["--camera"] = [&](const std::string& v) { o.camera = parseDimension("--camera", v); };
        table.withValue["--camera-orbit"] = [&](const std::string& v) { o.cameraOrbit = parseTriple("--camera-orbit", v); };
        table.withValue["--target"] = [&](const std::string& v) { o.target = parseTriple("--target", v); };
        table.withValue["--fov"] = [&](const std::string& v) {
            o.fovDegrees = parseNumber("--fov", v);
            if (o.fovDegrees <= 0.0f || o.fovDegrees >= 180.0f)
                throw UserError("--fov: expected degrees between 0 and 180, got '" + v + "'");
        };
        table.withValue["--shading"] = [&](const std::string& v) {
            if (v != "pbr" && v != "pbr-schlick-ggx" && v != "blinn-phong")
                throw UserError("--shading: unknown model '" + v + "' (pbr, pbr-schlick-ggx, blinn-phong)");
            o.shading = v;
        };
        table.withValue["--debug-view"] = [&](const std::string& v) {
            if (!passes::parseDebugView(v)) {
                std::string names;
                for (passes::DebugView view : passes::allDebugViews()) names += std::string(names.empty() ? "" : ", ") + passes::debugViewName(view);
                throw UserError("--debug-view: unknown view '" + v + "' (" + names + ")");
            }
            o.debugView = v;
        };
        table.withValue["--tonemap"] = [&](const std::string& v) {
            if (v != "pbr-neutral" && v != "aces" && v != "agx" && v != "reinhard" && v != "linear")
                throw UserError("--tonemap: unknown operator '" + v + "' (pbr-neutral, aces, agx, reinhard, linear)");
            o.tonemap = v;
        };
        table.withValue["--exposure"] = [&](const std::string& v) { o.exposureEv = parseNumber("--exposure", v); };
        table.withValue["--background"] = [&](const std::string& v) {
            if (v != "auto" && v != "transparent" && v != "skybox") parseHexColor("--background", v);
            o.background = v;
        };
        table.withValue["--env"] = [&](const std::string& v) {
            if (v.empty()) throw UserError("--env: expected a file, sky or none");
            o.env = v;
        };
        table.withValue["--env-rotation"] = [&](const std::string& v) {
            o.iblLook.rotationDegrees = parseNumber("--env-rotation", v);
        };
        table.withValue["--env-intensity"] = [&](const std::string& v) {
            o.iblLook.intensity = parseNumber("--env-intensity", v);
            if (o.iblLook.intensity < 0.0f) throw UserError("--env-intensity: must be ≥ 0, got '" + v + "'");
        };
        table.withValue["--skybox-blur"] = [&](const std::string& v) {
            o.iblLook.skyboxBlur = parseNumber("--skybox-blur", v);
            if (o.iblLook.skyboxBlur < 0.0f || o.iblLook.skyboxBlur > 1.0f)
                throw UserError("--skybox-blur: expected 0 (sharp) to 1, got '" + v + "'");
        };
        table.switches["--no-multiscatter"] = [&] { o.iblLook.multiscatter = false; };
        table.withValue["--irradiance"] = [&](const std::string& v) {
            const std::optional<ibl::IrradianceMode> mode = ibl::parseIrradianceMode(v);
            if (!mode) throw UserError("--irradiance '" + v + "': expected sh9 or cube");
            o.iblQuality.irradiance = *mode;
        };
        table.withValue["--ibl-lod-bias"] = [&](const std::string& v) {
            o.iblQuality.lodBias = parseNumber("--ibl-lod-bias", v);
        };
        table.withValue["--ibl-cache"] = [&](const std::string& v) {
            if (v.empty()) throw UserError("--ibl-cache: expected a directory");
            o.iblCache = v;
        };
        const std::pair<const char*, uint32_t ibl::IblQuality::*> qualityFlags[] = {
            {"--ibl-cube-size", &ibl::IblQuality::cubeSize},
            {"--ibl-levels", &ibl::IblQuality::specularLevels},
            {"--ibl-prefilter-samples", &ibl::IblQuality::prefilterSamples},
            {"--ibl-sh-size", &ibl::IblQuality::shSourceSize},
            {"--ibl-irradiance-size", &ibl::IblQuality::irradianceSize},
            {"--ibl-irradiance-samples", &ibl::IblQuality::irradianceSamples},
            {"--ibl-lut-size", &ibl::IblQuality::lutSize},
            {"--ibl-lut-samples", &ibl::IblQuality::lutSamples}};
        for (const auto& [flag, member] : qualityFlags)
            table.withValue[flag] = [&o, flag, member](const std::string& v) { o.iblQuality.*member = parseDimension(flag, v); };
        table.switches["--dither"] = [&] { o.dither = true; };
        table.switches["--no-default-lights"] = [&] { o.defaultLights = false; };
        table.withValue["--scene-lights"] = [&](const std::string& v) {
            if (v != "on" && v != "off") throw UserError("--scene-lights: expected on or off, got '" + v + "'");
            o.sceneLights = v == "on";
        };
        table.withValue["--lod-error"] = [&](const std::string& v) {
            o.lodErrorPixels = parseNumber("--lod-error", v);
            if (!(o.lodErrorPixels >= 0.0f)) throw UserError("--lod-error: expected pixels ≥ 0, got '" + v + "'");
        };
        table.withValue["--lod"] = [&](const std::string& v) {
            if (v != "on" && v != "off") throw UserError("--lod: expected on or off, got '" + v + "'");
            o.lodErrorPixels = v == "on" ? passes::DrawSelection::kDefaultLodErrorPixels : 0.0f;
        };
        table.withValue["--specular-aa"] = [&](const std::string& v) {
            if (v != "on" && v != "off") throw UserError("--specular-aa: expected on or off, got '" + v + "'");
            o.specularAa = v == "on";
        };
        table.withValue["--msaa"] = [&](const std::string& v) {
            if (v != "1" && v != "2" && v != "4" && v != "8") throw UserError("--msaa: expected 1, 2, 4 or 8, got '" + v + "'");
            o.msaa = uint32_t(std::stoul(v));
        };
        table.withValue["--cull"] = [&](const std::string& v) {
            if (v != "on" && v != "off") throw UserError("--cull: expected on or off, got '" + v + "'");
            o.frustumCulling = v == "on";
        };
        table.withValue["--variant"] = [&](const std::string& v) {
            if (v.empty()) throw UserError("--variant: expected a variant name");
            o.variant = v;
        };
        table.switches["--explain"] = [&] { o.explain = true; };
        if (command.kind == Command::Kind::Render) {
            o.frames = 1;
            table.withValue["--frames"] = [&](const std::string& v) {
                o.frames = parseDimension("--frames", v);
                if (o.frames == 0) throw UserError("--frames: need at least 1 frame");
            };
            table.withValue["--fps"] = [&](const std::string& v) {
                o.fps = parseSeconds("--fps", v);
                if (!(o.fps > 0.0)) throw UserError("--fps: expected frames per second > 0, got '" + v + "'");
            };
            table.withValue["--turntable"] = [&](const std::string& v) { o.turntableDegrees = parseNumber("--turntable", v); };
        }
        if (command.kind == Command::Kind::Bench) {
            table.withValue["--frames"] = [&](const std::string& v) {
                o.frames = parseDimension("--frames", v);
                if (o.frames == 0) throw UserError("--frames: need at least 1 frame");
            };
            table.switches["--json"] = [&] { o.json = true; };
        }
        if (command.kind == Command::Kind::View) {
            o.frames = 0;
            table.positional = [&](const std::string& v) {
                if (!o.scene.empty()) throw UserError("unexpected argument '" + v + "': the scene is already " + o.scene);
                o.scene = v;
            };
            table.withValue["--frames"] = [&](const std::string& v) {
                o.frames = parseDimension("--frames", v);
                if (o.frames == 0) throw UserError("--frames: need at least 1 frame");
            };
            table.withValue["--screenshot"] = [&](const std::string& v) {
                if (v.empty()) throw UserError("--screenshot: expected a .png file");
                o.screenshot = v;
            };
            table.switches["--no-vsync"] = [&] { o.vsync = false; };
            table.switches["--no-ui"] = [&] { o.ui = false; };
            table.withValue["--shaders"] = [&](const std::string& v) {
                if (v.empty()) throw UserError("--shaders: expected the folder holding the shaders' GLSL");
                o.shaderDir = v;
            };
            table.withValue["--panels"] = [&](const std::string& v) {
                static const std::vector<std::string> known = {"graph", "parameters", "materials", "environment",
                                                               "camera", "animation", "debug", "stats"};
                o.panels.clear();
                for (const std::string& panel : commaSeparated(v)) {
                    if (std::find(known.begin(), known.end(), panel) == known.end())
                        throw UserError("--panels: unknown panel '" + panel +
                                        "' (graph, parameters, materials, environment, camera, debug, stats)");
                    o.panels.push_back(panel);
                }
            };
            table.withValue["--ibl-report"] = [&](const std::string& v) {
                if (v.empty()) throw UserError("--ibl-report: expected a report.csv written by candela ibl-report");
                o.iblReport = v;
            };
        }
    } else if (name == "info") {
        command.kind = Command::Kind::Info;
        addCommon(table, command.info.common);
    } else if (name == "ibl-report") {
        command.kind = Command::Kind::IblReport;
        IblReportOptions& o = command.iblReport;
        addCommon(table, o.common);
        table.withValue["--env"] = [&](const std::string& v) {
            if (v.empty() || v == "none") throw UserError("--env: ibl-report needs an environment (a file or sky)");
            o.env = v;
        };
        addOutputFolder(table, o.out);
        table.withValue["--repeats"] = [&](const std::string& v) {
            o.repeats = parseDimension("--repeats", v);
            if (o.repeats == 0) throw UserError("--repeats: need at least 1");
        };
        table.withValue["--width"] = [&](const std::string& v) { o.width = parseDimension("--width", v); };
        table.withValue["--height"] = [&](const std::string& v) { o.height = parseDimension("--height", v); };
        table.withValue["--reference-samples"] = [&](const std::string& v) {
            o.referenceSamples = parseDimension("--reference-samples", v);
            if (o.referenceSamples < 16) throw UserError("--reference-samples: need at least 16");
        };
        table.switches["--quick"] = [&] { o.quick = true; };
    } else if (name == "scale-report") {
        command.kind = Command::Kind::ScaleReport;
        ScaleReportOptions& o = command.scaleReport;
        addCommon(table, o.common);
        addOutputFolder(table, o.out);
        table.withValue["--sizes"] = [&](const std::string& v) {
            o.sizes.clear();
            for (const std::string& item : commaSeparated(v)) {
                const uint32_t side = parseDimension("--sizes", item);
                if (side == 0 || side > 1000) throw UserError("--sizes: expected grid sides from 1 to 1000, got '" + v + "'");
                o.sizes.push_back(side);
            }
        };
        table.withValue["--frames"] = [&](const std::string& v) {
            o.frames = parseDimension("--frames", v);
            if (o.frames == 0) throw UserError("--frames: need at least 1 frame");
        };
        table.withValue["--lod-error"] = [&](const std::string& v) {
            o.lodErrorPixels = parseNumber("--lod-error", v);
            if (!(o.lodErrorPixels > 0.0f)) throw UserError("--lod-error: expected pixels > 0, got '" + v + "'");
        };
        table.withValue["--width"] = [&](const std::string& v) { o.width = parseDimension("--width", v); };
        table.withValue["--height"] = [&](const std::string& v) { o.height = parseDimension("--height", v); };
    } else if (name == "quality-report") {
        command.kind = Command::Kind::QualityReport;
        QualityReportOptions& o = command.qualityReport;
        addCommon(table, o.common);
        addOutputFolder(table, o.out);
        table.withValue["--scenes"] = [&](const std::string& v) {
            o.scenes = commaSeparated(v);
            if (o.scenes.empty() || std::find(o.scenes.begin(), o.scenes.end(), "") != o.scenes.end())
                throw UserError("--scenes: expected default or glTF files, comma-separated, got '" + v + "'");
        };
        table.withValue["--env"] = [&](const std::string& v) {
            if (v.empty() || v == "none") throw UserError("--env: expected an .hdr/.exr file or sky");
            o.env = v;
        };
        table.withValue["--msaa"] = [&](const std::string& v) {
            o.msaa.clear();
            for (const std::string& item : commaSeparated(v)) {
                if (item != "1" && item != "2" && item != "4" && item != "8")
                    throw UserError("--msaa: expected sample counts from 1, 2, 4, 8, got '" + v + "'");
                o.msaa.push_back(uint32_t(std::stoul(item)));
            }
        };
        table.withValue["--lod-errors"] = [&](const std::string& v) {
            o.lodErrors.clear();
            for (const std::string& item : commaSeparated(v)) {
                const float pixels = parseNumber("--lod-errors", item);
                if (!(pixels >= 0.0f)) throw UserError("--lod-errors: expected pixels ≥ 0, got '" + v + "'");
                o.lodErrors.push_back(pixels);
            }
        };
        const std::pair<const char*, uint32_t QualityReportOptions::*> counts[] = {
            {"--frames", &QualityReportOptions::frames}, {"--orbit-frames", &QualityReportOptions::orbitFrames},
            {"--width", &QualityReportOptions::width}, {"--height", &QualityReportOptions::height}};
        for (const auto& [flag, member] : counts)
            table.withValue[flag] = [&o, flag, member](const std::string& v) {
                o.*member = parseDimension(flag, v);
                if (o.*member == 0) throw UserError(std::string(flag) + ": must be at least 1");
            };
    } else if (name == "soak") {
        command.kind = Command::Kind::Soak;
        SoakOptions& o = command.soak;
        addCommon(table, o.common);
        const std::pair<const char*, uint32_t SoakOptions::*> counts[] = {{"--frames", &SoakOptions::frames},
                                                                        {"--switch-every", &SoakOptions::switchEvery},
                                                                        {"--sample-every", &SoakOptions::sampleEvery},
                                                                        {"--width", &SoakOptions::width},
                                                                        {"--height", &SoakOptions::height}};
        for (const auto& [flag, member] : counts)
            table.withValue[flag] = [&o, flag, member](const std::string& v) {
                o.*member = parseDimension(flag, v);
                if (o.*member == 0) throw UserError(std::string(flag) + ": must be at least 1");
            };
        table.withValue["--out"] = [&](const std::string& v) {
            if (v.empty()) throw UserError("--out: expected a .csv file");
            o.out = v;
        };
    } else {
        throw UserError("unknown command '" + name +
                        "' (commands: render, view, bench, ibl-report, scale-report, quality-report, soak, info; see candela --help)");
    }
    bool help = false;
    table.switches["--help"] = [&] { help = true; };
    parseFlags(name, args, 1, table);
    if (help) command.kind = Command::Kind::Help;
    if (command.kind == Command::Kind::View && !command.render.screenshot.empty() && command.render.frames == 0)
        throw UserError("--screenshot: also give --frames N (the frame to save; the viewer then exits)");
    if (command.kind == Command::Kind::Render || command.kind == Command::Kind::Bench || command.kind == Command::Kind::View) {
        command.render.iblQuality.validate();
        if (command.render.env == "none" && command.render.background == "skybox")
            throw UserError("--background skybox: there is no environment to show (--env none)");
    }
    return command;
}

std::string usageText() {
    return R"(candela: a physically based renderer on Vulkan 1.3, built around a frame render graph

usage:
  candela render [options]   render a frame headless and write it to a file
  candela view [SCENE] [options]
                             open the interactive viewer (window, orbit camera, ImGui panels)
  candela bench [options]    render N frames and report frame and pass times, also as ratios to a
                             calibration pass run in the same process
  candela ibl-report [opts]  sweep the IBL quality settings: precompute time against the error of the
                             maps and of the final image, as CSV, markdown and log-log plots
  candela scale-report [opts]  frame time against scene triangles for N x N sphere grids, levels of
                             detail on and off, as CSV, markdown and a log-log plot
  candela quality-report [opts]  image error (against a 16-sample reference, and frame to frame over a
                             slow orbit) against frame time for MSAA x specular AA x LOD error
  candela soak [options]     render many frames headless, switching the environment, and report host
                             and device memory over time (leaks show as growth after warm-up)
  candela info [options]     list the Vulkan devices, the one chosen and why, and the features enabled

render options:
  --out FILE            output image: .png (8-bit sRGB), .exr (linear half float) or .pfm (linear float)
                        [candela.png]
  --width W, --height H image size in pixels [1280 x 720]
  --graph-dot FILE      write the compiled render graph as Graphviz dot
  --graph-json FILE     write the compiled render graph as JSON (passes, resources, barriers, timings)
  --disable-pass NAME   switch a pass off (repeatable); passes that lose their input are culled too
  --scene FILE          a glTF 2.0 scene (.gltf or .glb) [the built-in 7x7 sphere grid]
  --grid N              the built-in grid with N x N spheres over its 7 x 7 materials, framed alike [7]
  --animation LIST      the glTF animations to play: indices or names, all or none (rest pose);
                        comma-separated or repeated [0, when the scene has animations]
  --time SECONDS        the moment of the animations to draw; each loops over its own duration [0]
  --frames N            render: an image sequence of N frames (--out holds a %04d-style frame number)
                        [1]
  --fps F               render: frames per second of the sequence; frame i shows --time + i/F [30]
  --turntable DEGREES   render: turn the orbit camera by DEGREES over the sequence (360: once round)
  --scene-index N       which of the glTF file's scenes to draw [the file's default scene, else 0]
  --camera INDEX        use the scene's glTF camera INDEX
  --camera-orbit T,P,R  orbit camera: azimuth T and polar angle P in degrees, distance R in metres
                        (eye = target + R(sin P sin T, cos P, sin P cos T); R <= 0 frames the scene)
                        [0,90,0: from +Z, framing the scene bounds]
  --target X,Y,Z        point the orbit camera looks at [the centre of the scene bounds]
  --fov DEGREES         vertical field of view of the orbit camera [45]
  --shading MODEL       pbr (height-correlated Smith GGX), pbr-schlick-ggx (the original project's
                        geometry term) or blinn-phong (the original project's first shader) [pbr]
  --debug-view NAME     show a material input or a shading term instead of the image: base-color,
                        geometric-normal, mapped-normal, roughness, metallic, occlusion, emissive,
                        d, g, f (GGX terms toward the first light), diffuse, specular [none]
  --tonemap OP          pbr-neutral, aces (Hill's RRT+ODT fit), agx, reinhard or linear [pbr-neutral]
  --exposure EV         exposure in stops [0]
  --background BG       auto, skybox, transparent (alpha 0 in PNG) or #rrggbb
                        [auto: the skybox with an environment, #262626 without]
  --env ENV             image-based lighting from an equirectangular .hdr or .exr file, the built-in
                        procedural sky (sky), or none [sky]. Orientation: the glTF Sample Viewer's
                        (the image centre faces +X, top row +Y); see docs/environments.md
  --env-rotation DEG    turn the environment about +Y (from +X towards +Z) [0]
  --env-intensity K     scale the environment's radiance [1]
  --skybox-blur B       show the environment behind the scene blurred like roughness B, 0..1 [0]
  --no-multiscatter     single-scattering split sum only (no Fdez-Aguera energy compensation)
  --irradiance MODE     diffuse irradiance as sh9 (9 spherical-harmonic coefficients) or cube [sh9]
  --ibl-cache DIR       keep precomputed IBL maps in DIR, keyed by environment content and quality
  --ibl-cube-size N     environment cube face size, 2^k from 16 to 2048 [256]
  --ibl-levels N        specular roughness levels (mips) [6]
  --ibl-prefilter-samples N   GGX samples per texel of the first rough specular mip; 4x more per
                        coarser mip, at most 4096 [32]
  --ibl-lod-bias B      filtered-importance-sampling lod bias (more: less noise, more blur) [0.5]
  --ibl-sh-size N       face size of the cube mip projected onto SH9 [32]
  --ibl-irradiance-size N, --ibl-irradiance-samples N   irradiance cube (cube mode) [32, 256]
  --ibl-lut-size N, --ibl-lut-samples N                  BRDF LUT size and samples [128, 256]
  --dither              dither the 8-bit output
  --no-default-lights   a scene without punctual lights normally gets a default key and fill light
  --scene-lights on|off the file's own KHR_lights_punctual lights (off: image-based lighting only,
                        for comparisons; the scene then counts as one without lights) [on]
  --lod-error PIXELS    draw each mesh at the coarsest level of detail whose geometric error covers
                        at most PIXELS on screen; 0: full detail [0.5]
  --lod on|off          --lod-error 0.5 or 0
  --cull on|off         leave out draws outside the view frustum [on]
  --msaa 1|2|4|8        samples per pixel of the scene's draw targets, resolved into the HDR image;
                        clamped to what the device supports, with a warning [4 on GPUs, 1 on CPU
                        devices such as lavapipe: `candela info` says which]
  --specular-aa on|off  widen the roughness by the normal's change across a pixel and by what a
                        normal map's mips average away (less shimmering highlights) [off]
  --variant NAME        draw the file's KHR_materials_variants variant NAME (an unknown name is an
                        error that lists the file's variants) [the default materials]
  --explain             print which passes and shader variants were left out, and why

view options: the render options (except --out, --width and --height: the window's size), and
  SCENE                 a .gltf/.glb file (same as --scene) [the built-in sphere grid]
  --width W, --height H initial window size [1280 x 720]
  --frames N            render N frames, then exit [run until the window is closed]
  --screenshot FILE     save the last of the --frames N frames, UI included, as PNG
  --no-vsync            present without waiting for the display (mailbox or immediate)
  --no-ui               hide the ImGui panels (the ImGui pass is left out)
  --panels LIST         panels open at start, comma-separated: graph, parameters, materials,
                        environment, camera, animation, debug, stats [graph,parameters,stats]
  --shaders DIR         hot-reload the shaders from DIR [the source tree's shaders/ folder]
  --ibl-report FILE     show this ibl-report CSV's figures in the environment panel too
  mouse and keys: right-drag rotate, middle-drag pan, wheel zoom, F frame the scene, R reset the
  camera, space pause/play the animation, P or F12 screenshot (candela-screenshot.png), Esc quit; drop a .gltf/.glb to open it,
  an .hdr/.exr to light the scene with it

quality-report options: MSAA x specular AA x level-of-detail error, error against a 16-sample reference
  --scenes A,B,...      default (the built-in grid under the sky) and/or glTF files [default]
  --env ENV             the glTF scenes' environment: an .hdr/.exr file or sky [sky]
  --msaa N,N,...        sample counts (those the device lacks are clamped, noted) [1,2,4,8]
  --lod-errors PX,...   level-of-detail errors in pixels [0,0.5,1,2,4]
  --frames N            timed frames per setting [5]
  --orbit-frames N      frames of the 1-degree-per-frame orbit (error and temporal difference) [6]
  --width W, --height H [640, 360] (the reference renders 4x each)
  --out DIR             where report.csv, report.md and the plots go [quality-report]

scale-report options: the built-in grid at N x N spheres (framed alike), levels of detail on and off
  --sizes N,N,...       grid sides [1,2,5,10,20,50,100]
  --frames N            frames measured per setting [5]
  --lod-error PIXELS    the level-of-detail error of the "on" runs [0.5]
  --width W, --height H [1280, 720]
  --out DIR             where report.csv, report.md and frame_vs_triangles.png go [scale-report]

bench options: the render options that choose the scene, camera and shading, and
  --frames N            frames to measure after warm-up [20]
  --json                machine-readable output

ibl-report options:
  --env ENV             an .hdr/.exr file or sky [sky]
  --out DIR             where report.csv, report.md and the plots go [ibl-report]
  --repeats N           precompute runs per setting; the median is reported [3]
  --quick               a reduced sweep (smoke tests)
  --width W, --height H size of the end-to-end images [320 x 180]
  --reference-samples N samples per pixel of the ground-truth render [4096]

soak options:
  --frames N            frames to render [10000]
  --switch-every K      frames per environment (4 procedural skies, cycled; each switch reruns the
                        IBL precompute) [100]
  --sample-every K      frames between memory samples [100]
  --width W, --height H frame size [320 x 180]
  --out FILE            also write the samples as CSV

common options:
  --device SEL          device index or case-insensitive name substring (see candela info)
  --validate            Khronos validation with synchronization validation (also CANDELA_VALIDATE=1)
  --verbose             also print notes (such as the degenerate triangles a glTF file's primitives
                        had, dropped quietly) and timings
  --quiet               no progress line on long commands (ibl-report, soak, quality-report,
                        scale-report, image sequences); one that rewrites itself on a terminal, a
                        plain line every 10 s otherwise
  --memory-budget MIB   allocate at most MIB MiB of device memory (simulates a small device: what does
                        not fit is an error naming the resource, exit code 4, or a lower IBL resolution
                        with a warning)
)";
}

}  // namespace candela::app
