// The flag table (app/cli_flags.h) held to what it promises, row by row, so that a new flag cannot
// miss one: every command takes exactly the flags the table gives it and each one changes the
// parse; every other flag is a one-line error naming the commands that take it; help lists
// exactly a command's flags; enum-valued flags list in help and errors exactly the names they
// accept, which are the enum's own.

#include "cli.h"
#include "cli_flags.h"
#include "core/errors.h"

#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <set>

namespace candela::app {
namespace {

// Flags that a command takes only together with another: the companions both sides of a
// comparison get.
const std::map<std::string, std::vector<std::string>> kCompanions = {{"--screenshot", {"--frames", "2"}},
                                                                      {"--scene-index", {"--scene", "model.glb"}},
                                                                      {"--view-ring", {"--views", "4"}},
                                                                      {"--light-seed", {"--views", "4"}}};

// A value for each flag that takes one: it parses for every command taking the flag and differs
// from its default.
const std::map<std::string, std::string> kExamples = {
    {"--out", "out"}, {"--width", "64"}, {"--height", "48"}, {"--frames", "3"}, {"--fps", "24"},
    {"--turntable", "90"}, {"--report", "report.json"}, {"--html", "index.html"}, {"--shard", "2/4"},
    {"--views", "6"}, {"--view-ring", "20"}, {"--light-seed", "7"}, {"--outputs", "color,depth,ids"}, {"--outputs-format", "exr"},
    {"--graph-dot", "graph.dot"}, {"--graph-json", "graph.json"}, {"--screenshot", "shot.png"},
    {"--panels", "camera,debug"}, {"--shaders", "shaders"}, {"--ibl-report", "report.csv"},
    {"--scene", "model.glb"}, {"--scene-index", "1"}, {"--grid", "3"}, {"--variant", "red"},
    {"--animation", "Walk,2"}, {"--time", "1.5"}, {"--camera", "0"}, {"--camera-orbit", "30,70,5"},
    {"--target", "0,1,0"}, {"--fov", "60"}, {"--shading", "blinn-phong"}, {"--debug-view", "roughness"},
    {"--tonemap", "agx"}, {"--exposure", "1"}, {"--background", "#102030"}, {"--msaa", "2"},
    {"--precompile", "off"}, {"--shading-path", "visibility"}, {"--specular-aa", "on"}, {"--lod-error", "2"},
    {"--lod", "off"}, {"--cull", "off"}, {"--disable-pass", "skybox"}, {"--scene-lights", "off"},
    {"--env", "studio.hdr"}, {"--env-rotation", "90"}, {"--env-intensity", "2"}, {"--skybox-blur", "0.3"},
    {"--ibl-cache", "cache"}, {"--lod-cache", "cache"}, {"--irradiance", "sh9"}, {"--ibl-cube-size", "128"}, {"--ibl-levels", "5"},
    {"--ibl-prefilter-samples", "32"}, {"--ibl-lod-bias", "1"}, {"--ibl-bright-texels", "0"},
    {"--ibl-sh-size", "16"}, {"--ibl-irradiance-size", "16"}, {"--ibl-irradiance-samples", "128"},
    {"--ibl-lut-size", "64"}, {"--ibl-lut-samples", "128"}, {"--repeats", "1"}, {"--reference-samples", "64"},
    {"--sizes", "1,3"}, {"--scenes", "default,model.glb"}, {"--lod-errors", "0,1"}, {"--orbit-frames", "2"},
    {"--switch-every", "10"}, {"--sample-every", "10"}, {"--ppd", "40"}, {"--monitor-distance", "1"},
    {"--monitor-width", "0.5"}, {"--monitor-resolution", "1920"}, {"--threshold", "2"}, {"--max-flip", "0.05"},
    {"--max-fraction", "0.001"}, {"--error-maps", "maps"}, {"--device", "0"}, {"--device-profile", "minimum"},
    {"--memory-budget", "64"}, {"--pipeline-cache", "cache"}, {"--cold", "2"},
};

// The example of `flag` ("" for a switch).
std::string exampleOf(const Flag& flag) { return flag.isSwitch() ? "" : kExamples.at(flag.name); }

std::vector<std::string> argsWith(const CommandInfo& command, const Flag& flag) {
    std::vector<std::string> args = {command.name, flag.name};
    if (!flag.isSwitch()) args.push_back(exampleOf(flag));
    if (auto it = kCompanions.find(flag.name); it != kCompanions.end()) args.insert(args.end(), it->second.begin(), it->second.end());
    return args;
}

std::vector<std::string> argsWithout(const CommandInfo& command, const Flag& flag) {
    std::vector<std::string> args = {command.name};
    if (auto it = kCompanions.find(flag.name); it != kCompanions.end()) args.insert(args.end(), it->second.begin(), it->second.end());
    return args;
}

std::string errorOf(const std::vector<std::string>& args) {
    try {
        parseCommandLine(args);
    } catch (const UserError& e) {
        return e.what();
    }
    return "(no error)";
}

// Whether `help` has a row for `flag` ("  --flag VALUE…" at the start of a line).
bool listsFlag(const std::string& help, const std::string& flag) {
    for (const char* after : {" ", "\n"})
        if (help.find("\n  " + flag + after) != std::string::npos) return true;
    return false;
}

// The row of `flag` in `help` up to the next flag's row.
std::string rowOf(const std::string& help, const std::string& flag) {
    size_t at = help.find("\n  " + flag + " ");
    if (at == std::string::npos) at = help.find("\n  " + flag + "\n");
    if (at == std::string::npos) return "";
    const size_t end = help.find("\n  -", at + 1);
    return help.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// Whether the options the command of `a` reads are the same in `b`.
bool sameOptions(const Command& a, const Command& b) {
    switch (a.kind) {
        case Command::Kind::Render: return a.render == b.render;
        case Command::Kind::View: return a.view == b.view;
        case Command::Kind::Bench: return a.bench == b.bench;
        case Command::Kind::Info: return a.info == b.info;
        case Command::Kind::IblReport: return a.iblReport == b.iblReport;
        case Command::Kind::Soak: return a.soak == b.soak;
        case Command::Kind::ScaleReport: return a.scaleReport == b.scaleReport;
        case Command::Kind::QualityReport: return a.qualityReport == b.qualityReport;
        case Command::Kind::Diff: return a.diff == b.diff;
        case Command::Kind::Help:
        case Command::Kind::Version: break;
    }
    return a == b;
}

// `text` with each run of spaces and line breaks as one space (help rows wrap at spaces).
std::string squeezed(const std::string& text) {
    std::string out;
    for (char c : text)
        if (c != ' ' && c != '\n') out += c;
        else if (!out.empty() && out.back() != ' ') out += ' ';
    return out;
}

TEST(CliFlags, TableIsWellFormed) {
    std::set<std::string> names;
    for (const Flag& flag : flagTable()) {
        SCOPED_TRACE(flag.name);
        EXPECT_EQ(flag.name.rfind("--", 0), 0u);
        EXPECT_TRUE(names.insert(flag.name).second) << "declared twice";
        ASSERT_FALSE(flag.uses.empty());
        ASSERT_TRUE(flag.set);
        uint32_t seen = 0;
        for (const FlagUse& use : flag.uses) {
            EXPECT_NE(use.commands.bits, 0u);
            EXPECT_EQ(seen & use.commands.bits, 0u) << "two uses for one command";
            seen |= use.commands.bits;
            EXPECT_EQ(use.value.empty(), flag.isSwitch()) << "a switch for some commands only";
            EXPECT_FALSE(use.help.empty());
            if (!flag.choices.empty()) {
                EXPECT_TRUE(use.help.find("{choices}") != std::string::npos || use.value == "{choices}")
                    << "help does not list the names accepted";
            }
        }
        EXPECT_EQ(kExamples.count(flag.name), flag.isSwitch() ? 0u : 1u)
            << "a value flag needs an example in kExamples (a switch none)";
        for (const CommandInfo& command : commandTable()) seen &= ~CommandSet{command.kind}.bits;
        EXPECT_EQ(seen, 0u) << "a use for no command";
    }
    for (const char* reserved : {"--help", "-h", "--version"}) EXPECT_EQ(findFlag(reserved), nullptr) << reserved;
}

TEST(CliFlags, EachCommandsFlagsComeInTheOrderItDeclaresThem) {
    for (const CommandInfo& command : commandTable()) {
        std::vector<std::string> declared, listed;
        for (const FlagSpec<Command>& spec : command.flags()) declared.push_back(spec.name);
        for (const Flag& flag : flagTable())
            if (flag.use(command.kind)) listed.push_back(flag.name);
        EXPECT_EQ(listed, declared) << command.name;
    }
    for (const auto& [name, example] : kExamples) EXPECT_NE(findFlag(name), nullptr) << name << ": no such flag";
}

TEST(CliFlags, EachCommandParsesWithItsDefaults) {
    for (const CommandInfo& command : commandTable()) {
        const Command parsed = parseCommandLine({command.name});
        EXPECT_EQ(parsed.kind, command.kind) << command.name;
    }
}

TEST(CliFlags, EachCommandTakesItsFlagsAndEachChangesTheResult) {
    for (const Flag& flag : flagTable())
        for (const CommandInfo& command : commandTable()) {
            if (!flag.use(command.kind)) continue;
            SCOPED_TRACE(command.name + " " + flag.name + " " + exampleOf(flag));
            Command with, without;
            ASSERT_NO_THROW(with = parseCommandLine(argsWith(command, flag)));
            ASSERT_NO_THROW(without = parseCommandLine(argsWithout(command, flag)));
            EXPECT_FALSE(sameOptions(with, without)) << "the flag changes nothing in the command's options";
        }
}

TEST(CliFlags, EachCommandRejectsEveryFlagItDoesNotTake) {
    for (const Flag& flag : flagTable())
        for (const CommandInfo& command : commandTable()) {
            if (flag.use(command.kind)) continue;
            const std::string error = errorOf(argsWith(command, flag));
            EXPECT_EQ(error.rfind(command.name + " does not take " + flag.name + " (it is a flag of ", 0), 0u) << error;
            EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        }
}

TEST(CliFlags, TheIssuesExamplesAreErrorsNamingTheFlag) {
    EXPECT_EQ(errorOf({"bench", "--graph-json", "g.json", "--out", "x.png", "--explain"}),
              "bench does not take --graph-json (it is a flag of render)");
    EXPECT_EQ(errorOf({"view", "--graph-dot", "g.dot", "--explain"}), "view does not take --graph-dot (it is a flag of render)");
    EXPECT_EQ(errorOf({"bench", "--out", "x.png"}), "bench does not take --out (it is a flag of render, ibl-report, "
                                                    "scale-report, quality-report and soak)");
    EXPECT_EQ(errorOf({"view", "--explain"}), "view does not take --explain (it is a flag of render and bench)");
    EXPECT_EQ(errorOf({"view", "--dither"}), "view does not take --dither (it is a flag of render and bench)");
    EXPECT_EQ(errorOf({"info", "--quiet"}).rfind("info does not take --quiet", 0), 0u);
}

TEST(CliFlags, CommandHelpListsExactlyTheCommandsFlags) {
    for (const CommandInfo& command : commandTable()) {
        const std::string help = commandHelp(command.name);
        EXPECT_EQ(help.rfind("usage: candela " + command.name + " ", 0), 0u) << help;
        for (const Flag& flag : flagTable())
            EXPECT_EQ(listsFlag(help, flag.name), flag.use(command.kind) != nullptr) << command.name << " --help, " << flag.name;
        EXPECT_TRUE(listsFlag(help, "-h, --help")) << command.name;
    }
}

TEST(CliFlags, UsageListsEveryCommandAndFlag) {
    const std::string usage = usageText();
    for (const CommandInfo& command : commandTable()) EXPECT_NE(usage.find("\n  " + command.name + " "), std::string::npos) << command.name;
    for (const Flag& flag : flagTable()) EXPECT_TRUE(listsFlag(usage, flag.name)) << flag.name;
    EXPECT_NE(usage.find("candela COMMAND --help"), std::string::npos);
    EXPECT_NE(usage.find("candela --version"), std::string::npos);
}

TEST(CliFlags, HelpLinesFitOneHundredColumns) {
    std::vector<std::string> texts = {usageText()};
    for (const CommandInfo& command : commandTable()) texts.push_back(commandHelp(command.name));
    for (const std::string& text : texts)
        for (size_t at = 0, end; at < text.size(); at = end + 1) {
            end = std::min(text.find('\n', at), text.size());
            EXPECT_LE(end - at, 100u) << text.substr(at, end - at);
        }
}

// Enum-valued flags: every name help lists parses, and a wrong name's error lists the same names.
TEST(CliFlags, ChoiceFlagsListExactlyWhatTheyAccept) {
    for (const Flag& flag : flagTable()) {
        if (flag.choices.empty()) continue;
        const std::string list = joinChoices(flag.choices, flag.otherForm);
        for (const CommandInfo& command : commandTable()) {
            if (!flag.use(command.kind)) continue;
            SCOPED_TRACE(command.name + " " + flag.name);
            const std::string row = rowOf(commandHelp(command.name), flag.name);
            std::string bars;
            for (const std::string& name : flag.choices) bars += (bars.empty() ? "" : "|") + name;
            const std::string text = squeezed(row);
            EXPECT_TRUE(text.find(list) != std::string::npos || text.find(flag.name + " " + bars + " ") != std::string::npos)
                << row;
            for (const std::string& name : flag.choices) EXPECT_NO_THROW(parseCommandLine({command.name, flag.name, name})) << name;
            EXPECT_EQ(errorOf({command.name, flag.name, "bogus"}), flag.name + ": expected " + list + ", got 'bogus'");
        }
    }
}

TEST(CliFlags, EnumNamesRoundTrip) {
    for (const auto& [op, name] : options::kTonemapNames) {
        EXPECT_EQ(parseCommandLine({"render", "--tonemap", name}).render.tonemap, op);
        EXPECT_STREQ(options::tonemapName(op), name);
    }
    for (const auto& [view, name] : options::kDebugViewNames) {
        EXPECT_EQ(parseCommandLine({"render", "--debug-view", name}).render.debugView, view);
        EXPECT_STREQ(options::debugViewName(view), name);
    }
    for (const auto& [mode, name] : ibl::kIrradianceModeNames) {
        EXPECT_EQ(parseCommandLine({"render", "--irradiance", name}).render.iblQuality.irradiance, mode);
        EXPECT_STREQ(ibl::irradianceModeName(mode), name);
    }
    std::set<options::ShadingModel> models;
    for (const auto& [model, name] : options::kShadingModelNames) {
        EXPECT_EQ(parseCommandLine({"render", "--shading", name}).render.shading, model);
        EXPECT_TRUE(models.insert(model).second) << name;
        EXPECT_STREQ(options::shadingModelName(model), name);
    }
    for (const auto& [panel, name] : options::kPanelNames)
        EXPECT_EQ(parseCommandLine({"view", "--panels", name}).view.panels, std::set<options::Panel>{panel});
    EXPECT_EQ(parseCommandLine({"view"}).view.panels, options::kPanelsOpenByDefault);
}

TEST(CliFlags, UnknownFlagsNameTheNearestOne) {
    EXPECT_EQ(errorOf({"render", "--scen", "x.glb"}), "unknown flag --scen for render (did you mean --scene?)");
    EXPECT_EQ(errorOf({"render", "--widht", "3"}), "unknown flag --widht for render (did you mean --width?)");
    EXPECT_EQ(errorOf({"view", "--env-rot", "90"}), "unknown flag --env-rot for view (did you mean --env-rotation?)");
    EXPECT_EQ(errorOf({"render", "-scene", "x.glb"}), "unknown flag -scene for render (did you mean --scene?)");
    EXPECT_EQ(errorOf({"bench", "--graph-jsn", "g.json"}),
              "unknown flag --graph-jsn for bench (did you mean --graph-json? it is a flag of render)");
    EXPECT_EQ(errorOf({"render", "--frobnicate"}), "unknown flag --frobnicate for render (candela render --help lists its flags)");
    EXPECT_EQ(errorOf({"rendr"}).rfind("unknown command 'rendr' (did you mean render? commands: render, view,", 0), 0u);
    EXPECT_EQ(errorOf({"--verison"}).rfind("unknown command '--verison' (did you mean --version?", 0), 0u);
}

TEST(CliFlags, HelpAndVersion) {
    for (const char* help : {"--help", "-h"}) {
        const Command c = parseCommandLine({"render", "--width", "3", help});
        EXPECT_EQ(c.kind, Command::Kind::Help);
        EXPECT_EQ(c.helpCommand, "render");
        EXPECT_EQ(parseCommandLine({help}).helpCommand, "");
    }
    EXPECT_EQ(parseCommandLine({"help", "soak"}).helpCommand, "soak");
    EXPECT_EQ(errorOf({"help", "sook"}).rfind("unknown command 'sook' (did you mean soak?", 0), 0u);
    EXPECT_EQ(parseCommandLine({"--version"}).kind, Command::Kind::Version);
    EXPECT_THROW(parseCommandLine({"--version", "render"}), UserError);
    const std::string version = versionText();
    ASSERT_GT(version.size(), 8u);
    EXPECT_EQ(version.rfind("candela ", 0), 0u);
    EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(version[8]))) << version;
}

TEST(CliFlags, FramesHasEachCommandsDefault) {
    EXPECT_EQ(parseCommandLine({"render"}).render.frames, 1u);
    EXPECT_EQ(parseCommandLine({"view"}).view.frames, 0u);  // until the window is closed
    EXPECT_EQ(parseCommandLine({"bench"}).bench.frames, 20u);
    EXPECT_EQ(parseCommandLine({"soak"}).soak.frames, 10000u);
    EXPECT_EQ(parseCommandLine({"scale-report"}).scaleReport.frames, 5u);
    EXPECT_EQ(parseCommandLine({"quality-report"}).qualityReport.frames, 5u);
    for (const char* command : {"render", "view", "bench", "soak", "scale-report", "quality-report"})
        EXPECT_EQ(errorOf({command, "--frames", "0"}), "--frames: must be at least 1") << command;
}

TEST(CliFlags, ResultsAreTyped) {
    const RenderOptions o = parseCommandLine({"render", "--background", "#ff0080", "--env", "studio.hdr"}).render;
    EXPECT_EQ(o.background.kind, Background::Kind::Color);
    EXPECT_EQ(o.background.srgb, (std::array<float, 3>{1.0f, 0.0f, 128.0f / 255.0f}));
    EXPECT_EQ(o.env, (EnvironmentChoice{EnvironmentChoice::Kind::File, "studio.hdr"}));
    EXPECT_EQ(parseCommandLine({"render", "--env", "none"}).render.env.kind, EnvironmentChoice::Kind::None);
    EXPECT_EQ(parseCommandLine({"render"}).render.env.kind, EnvironmentChoice::Kind::Sky);
    EXPECT_EQ(parseCommandLine({"render", "--background", "transparent"}).render.background.kind, Background::Kind::Transparent);
    EXPECT_EQ(parseCommandLine({"render", "--msaa", "8"}).render.msaa, 8u);
    EXPECT_EQ(parseCommandLine({"quality-report", "--msaa", "1,4"}).qualityReport.msaa, (std::vector<uint32_t>{1, 4}));
    EXPECT_EQ(parseCommandLine({"render", "--lod", "off"}).render.lodErrorPixels, 0.0f);
    EXPECT_EQ(parseCommandLine({"render"}).render.lodErrorPixels, options::DrawSelection::kDefaultLodErrorPixels);
    EXPECT_EQ(parseCommandLine({"ibl-report", "--env", "sky"}).iblReport.env.kind, EnvironmentChoice::Kind::Sky);
}

}  // namespace
}  // namespace candela::app
