#include "cli.h"

#include "core/check.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>

namespace candela::app {
namespace {

// Flag handlers of one subcommand: a flag either takes a value or is a switch.
struct FlagTable {
    std::map<std::string, std::function<void(const std::string&)>> withValue;
    std::map<std::string, std::function<void()>> switches;
};

void addCommon(FlagTable& table, CommonOptions& common) {
    table.withValue["--device"] = [&](const std::string& v) { common.device = v; };
    table.switches["--validate"] = [&] { common.validate = true; };
    table.switches["--verbose"] = [&] { common.verbose = true; };
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

Command parseCommandLine(const std::vector<std::string>& args) {
    Command command;
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") return command;
    const std::string& name = args[0];
    FlagTable table;
    if (name == "render") {
        command.kind = Command::Kind::Render;
        RenderOptions& o = command.render;
        addCommon(table, o.common);
        table.withValue["--out"] = [&](const std::string& v) { o.out = v; };
        table.withValue["--width"] = [&](const std::string& v) { o.width = parseDimension("--width", v); };
        table.withValue["--height"] = [&](const std::string& v) { o.height = parseDimension("--height", v); };
        table.withValue["--graph-dot"] = [&](const std::string& v) { o.graphDot = v; };
        table.withValue["--graph-json"] = [&](const std::string& v) { o.graphJson = v; };
        table.withValue["--disable-pass"] = [&](const std::string& v) { o.disabledPasses.push_back(v); };
    } else if (name == "info") {
        command.kind = Command::Kind::Info;
        addCommon(table, command.info.common);
    } else {
        throw UserError("unknown command '" + name + "' (commands: render, info; see candela --help)");
    }
    bool help = false;
    table.switches["--help"] = [&] { help = true; };
    parseFlags(name, args, 1, table);
    if (help) command.kind = Command::Kind::Help;
    return command;
}

std::string usageText() {
    return R"(candela: a physically based renderer on Vulkan 1.3, built around a frame render graph

usage:
  candela render [options]   render a frame headless and write it to a file
  candela info [options]     list the Vulkan devices, the one chosen and why, and the features enabled

render options:
  --out FILE            output image: .png (8-bit sRGB), .exr (linear half float) or .pfm (linear float)
                        [candela.png]
  --width W, --height H image size in pixels [1280 x 720]
  --graph-dot FILE      write the compiled render graph as Graphviz dot
  --graph-json FILE     write the compiled render graph as JSON (passes, resources, barriers, timings)
  --disable-pass NAME   switch a pass off (repeatable); passes that lose their input are culled too

common options:
  --device SEL          device index or case-insensitive name substring (see candela info)
  --validate            Khronos validation with synchronization validation (also CANDELA_VALIDATE=1)
  --verbose             print progress and timings
)";
}

}  // namespace candela::app
