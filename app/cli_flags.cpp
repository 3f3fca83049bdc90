// The flag table (cli_flags.h): every command's flags merged into one row per flag.

#include "cli_flags.h"

#include "core/errors.h"

#include <map>
#include <memory>

namespace candela::app {
namespace {

// Every flag in the order help lists them (grouped as in `candela --help`: output, the viewer,
// scene and camera, shading, lighting and IBL, the reports, diff, the device), with a value that
// parses for every command taking it and differs from its default ("" for a switch), for the tests.
constexpr std::pair<const char*, const char*> kFlagOrder[] = {
    {"--out", "out"}, {"--width", "64"}, {"--height", "48"}, {"--frames", "3"}, {"--fps", "24"}, {"--turntable", "90"},
    {"--report", "report.json"}, {"--html", "index.html"}, {"--inline-images", ""}, {"--shard", "2/4"},
    {"--graph-dot", "graph.dot"}, {"--graph-json", "graph.json"}, {"--explain", ""}, {"--dither", ""}, {"--json", ""},
    {"--in-flight", ""},
    {"--screenshot", "shot.png"}, {"--no-vsync", ""}, {"--no-ui", ""}, {"--panels", "camera,debug"}, {"--shaders", "shaders"},
    {"--ibl-report", "report.csv"},
    {"--scene", "model.glb"}, {"--scene-index", "1"}, {"--grid", "3"}, {"--distinct-materials", ""}, {"--variant", "red"},
    {"--animation", "Walk,2"}, {"--time", "1.5"}, {"--camera", "0"}, {"--camera-orbit", "30,70,5"}, {"--target", "0,1,0"},
    {"--fov", "60"},
    {"--shading", "blinn-phong"}, {"--debug-view", "roughness"}, {"--tonemap", "agx"}, {"--exposure", "1"},
    {"--background", "#102030"}, {"--msaa", "2"}, {"--precompile", "off"}, {"--shading-path", "visibility"},
    {"--specular-aa", "on"}, {"--lod-error", "2"}, {"--lod", "off"}, {"--cull", "off"}, {"--disable-pass", "skybox"},
    {"--no-default-lights", ""}, {"--scene-lights", "off"}, {"--env", "studio.hdr"}, {"--env-rotation", "90"},
    {"--env-intensity", "2"}, {"--skybox-blur", "0.3"}, {"--no-multiscatter", ""}, {"--ibl-cache", "cache"},
    {"--irradiance", "sh9"}, {"--ibl-cube-size", "128"}, {"--ibl-levels", "5"}, {"--ibl-prefilter-samples", "32"},
    {"--ibl-lod-bias", "1"}, {"--ibl-bright-texels", "0"}, {"--ibl-sh-size", "16"}, {"--ibl-irradiance-size", "16"},
    {"--ibl-irradiance-samples", "128"}, {"--ibl-lut-size", "64"}, {"--ibl-lut-samples", "128"},
    {"--repeats", "1"}, {"--quick", ""}, {"--reference-samples", "64"}, {"--sizes", "1,3"}, {"--scenes", "default,model.glb"},
    {"--lod-errors", "0,1"}, {"--orbit-frames", "2"}, {"--switch-every", "10"}, {"--sample-every", "10"},
    {"--ppd", "40"}, {"--monitor-distance", "1"}, {"--monitor-width", "0.5"}, {"--monitor-resolution", "1920"},
    {"--threshold", "2"}, {"--max-flip", "0.05"}, {"--max-fraction", "0.001"}, {"--error-maps", "maps"},
    {"--device", "0"}, {"--device-profile", "minimum"}, {"--validate", ""}, {"--memory-budget", "64"},
    {"--pipeline-cache", "cache"}, {"--verbose", ""}, {"--quiet", ""},
};

using Setters = std::map<Command::Kind, Setter<Command>>;

// Adds `kind`'s use of a flag to its row: to a use that reads the same, else as a new use.
void addUse(Flag& flag, Setters& setters, Command::Kind kind, FlagSpec<Command>&& spec) {
    for (FlagUse& use : flag.uses)
        if (use.value == spec.value && use.help == spec.help && use.defaultValue == spec.defaultValue) {
            use.commands.bits |= CommandSet{kind}.bits;
            setters.emplace(kind, std::move(spec.set));
            return;
        }
    if (!flag.uses.empty() && (flag.choices != spec.choices || flag.otherForm != spec.otherForm))
        throw InternalError(flag.name + ": two commands accept different values");
    flag.choices = std::move(spec.choices);
    flag.otherForm = std::move(spec.otherForm);
    flag.uses.push_back({CommandSet{kind}, std::move(spec.value), std::move(spec.help), std::move(spec.defaultValue)});
    setters.emplace(kind, std::move(spec.set));
}

std::vector<Flag> makeFlagTable() {
    std::vector<Flag> flags;
    std::map<std::string, size_t> row;
    for (const auto& [name, example] : kFlagOrder) {
        row.emplace(name, flags.size());
        flags.push_back({.name = name, .example = example});
    }
    std::vector<Setters> setters(flags.size());
    for (const CommandInfo& command : commandTable())
        for (FlagSpec<Command>& spec : command.flags()) {
            const auto it = row.find(spec.name);
            if (it == row.end()) throw InternalError(command.name + " declares " + spec.name + ", which kFlagOrder lacks");
            if (flags[it->second].use(command.kind)) throw InternalError(command.name + " declares " + spec.name + " twice");
            addUse(flags[it->second], setters[it->second], command.kind, std::move(spec));
        }
    for (size_t i = 0; i < flags.size(); ++i) {
        if (flags[i].uses.empty()) throw InternalError(flags[i].name + ": no command takes it");
        flags[i].set = [bound = std::make_shared<const Setters>(std::move(setters[i]))](Command& c, const std::string& flag,
                                                                                       const std::string& value) {
            bound->at(c.kind)(c, flag, value);
        };
    }
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
