// The command table (cli_flags.h): every command, its usage and what it does, and its flags,
// arguments and checks (from its own file, render_cli.h...) bound to its options in Command.
#include "cli_flags.h"

namespace candela::app {
namespace {

using Kind = Command::Kind;

template <class O>
std::function<std::vector<FlagSpec<Command>>()> flagsOf(O Command::*options, std::vector<FlagSpec<O>> (*flags)()) {
    return [options, flags] { return bindTo<Command>(options, flags()); };
}

template <class O>
std::function<void(Command&, const std::string&)> argumentOf(O Command::*options, void (*take)(O&, const std::string&)) {
    return [options, take](Command& c, const std::string& argument) { take(c.*options, argument); };
}

template <class O>
std::function<void(const Command&)> checkOf(O Command::*options, void (*check)(const O&)) {
    return [options, check](const Command& c) { check(c.*options); };
}

}  // namespace

const std::vector<CommandInfo>& commandTable() {
    static const std::vector<CommandInfo> commands = {
        {Kind::Render, "render", "[SCENE...] [flags]",
         "render a frame (or an image sequence) headless and write it to a file; with several scenes (glTF files, "
         "folders walked for .gltf/.glb, @LIST files) one run renders them all on one device with one environment "
         "precompute",
         "A scene that fails is reported and the run goes on; the exit code is then non-zero and the failures are "
         "listed at the end. --out names each output from a pattern: {name} (the file's name without extension), "
         "{path} (its path without extension, under the folder it was found in), {variant} and {frame}.",
         flagsOf(&Command::render, renderFlags), argumentOf(&Command::render, takeRenderArgument),
         checkOf(&Command::render, checkRenderOptions)},
        {Kind::View, "view", "[SCENE] [flags]",
         "open the interactive viewer (window, orbit camera, ImGui panels); SCENE: a .gltf/.glb file, as --scene",
         "mouse and keys: right-drag rotate, middle-drag pan, wheel zoom, F frame the scene, R reset the camera, space "
         "pause/play the animation, P or F12 screenshot (candela-screenshot.png), Esc quit; drop a .gltf/.glb to open "
         "it, an .hdr/.exr to light the scene with it",
         flagsOf(&Command::view, viewFlags), argumentOf(&Command::view, takeViewArgument),
         checkOf(&Command::view, checkViewOptions)},
        {Kind::Bench, "bench", "[flags]",
         "render N frames and report frame and pass times, also as ratios to a calibration pass run in the same process",
         "",
         flagsOf(&Command::bench, benchFlags), {}, checkOf(&Command::bench, checkBenchOptions)},
        {Kind::IblReport, "ibl-report", "[flags]",
         "sweep the IBL quality settings: precompute time against the error of the maps and of the final image, as "
         "CSV, markdown and log-log plots",
         "",
         flagsOf(&Command::iblReport, iblReportFlags)},
        {Kind::ScaleReport, "scale-report", "[flags]",
         "frame time against scene triangles for N x N sphere grids, levels of detail on and off, as CSV, markdown and "
         "a log-log plot",
         "",
         flagsOf(&Command::scaleReport, scaleReportFlags)},
        {Kind::QualityReport, "quality-report", "[flags]",
         "image error (against a 16-sample reference, and frame to frame over a slow orbit) against frame time for "
         "MSAA x specular AA x LOD error",
         "",
         flagsOf(&Command::qualityReport, qualityReportFlags)},
        {Kind::Soak, "soak", "[flags]",
         "render many frames headless, switching the environment, and report host and device memory over time (leaks "
         "show as growth after warm-up)",
         "",
         flagsOf(&Command::soak, soakFlags)},
        {Kind::Diff, "diff", "A B [flags]",
         "compare two images, or two folders of images matched by relative path: FLIP (PNG: LDR-FLIP, EXR: "
         "HDR-FLIP), PSNR, the largest channel difference and the pixels over a threshold",
         "exit code 0 when every pair passes, 1 when one is over a threshold, missing on one side or of another "
         "size, 2 for bad usage or an unreadable image; see docs/pipelines.md#candela-diff",
         flagsOf(&Command::diff, diffFlags), argumentOf(&Command::diff, takeDiffArgument)},
        {Kind::Info, "info", "[flags]", "list the Vulkan devices, the one chosen and why, and the features enabled", "",
         flagsOf(&Command::info, infoFlags)},
    };
    return commands;
}

const CommandInfo* findCommand(std::string_view name) {
    for (const CommandInfo& command : commandTable())
        if (command.name == name) return &command;
    return nullptr;
}

std::string commandList(CommandSet set, bool allBut) {
    std::vector<std::string> in, out;
    for (const CommandInfo& command : commandTable()) (set.contains(command.kind) ? in : out).push_back(command.name);
    if (out.empty()) return "every command";
    if (allBut && in.size() > 4) return "every command but " + joinWords(out, "and");
    return joinWords(in, "and");
}

}  // namespace candela::app
