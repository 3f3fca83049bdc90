// `candela view`'s flags: the window and the scripted run, then what it shares with render and bench.

#include "view_cli.h"

#include "flag_groups.h"

namespace candela::app {
namespace {

std::string panelList(const std::set<options::Panel>& panels) {
    std::string out;
    for (const auto& [panel, name] : options::kPanelNames)
        if (panels.count(panel)) out += (out.empty() ? "" : ",") + std::string(name);
    return out;
}

}  // namespace

std::vector<FlagSpec<ViewOptions>> viewFlags() {
    using O = ViewOptions;
    std::vector<FlagSpec<O>> flags = {
        {"--frames", "N", "render N frames, then exit [run until the window is closed]", "", parsed(&O::frames, parseCount)},
        {"--screenshot", "FILE", "save the last of the --frames N frames, UI included, as PNG", "", parsed(&O::screenshot, parsePath)},
        {"--no-vsync", "", "present without waiting for the display (mailbox or immediate)", "", setsTo(&O::vsync, false)},
        {"--no-ui", "", "hide the ImGui panels (the ImGui pass is left out)", "", setsTo(&O::ui, false)},
        {"--panels", "LIST", "the panels open at start, comma-separated: {choices}", panelList(options::kPanelsOpenByDefault),
         [](O& o, Str flag, Str v) {
             o.panels.clear();
             for (const std::string& item : commaSeparated(v)) o.panels.insert(parseChoice(flag, options::kPanelNames, item));
         },
         namesOf(options::kPanelNames)},
        {"--shaders", "DIR",
         "hot-reload the shaders from DIR [the shaders/ folder of the source tree the executable was built in, "
         "when it runs from there]",
         "", parsed(&O::shaderDir, parsePath)},
        {"--ibl-report", "FILE", "show this ibl-report CSV's figures in the environment panel too", "",
         parsed(&O::iblReport, parsePath)},
    };
    append(flags, bindTo<O>(sizeFlags(&O::width, &O::height, "initial window {}", 1280, 720)));
    append(flags, bindTo<O>(sceneRenderFlags(true)));
    return flags;
}

void takeViewArgument(ViewOptions& options, const std::string& argument) {
    if (!options.scene.empty())
        throw UserError("unexpected argument '" + argument + "': the scene is already " + options.scene);
    options.scene = argument;
}

void checkViewOptions(const ViewOptions& options) {
    checkSceneFlags(options, false, false);
    if (!options.screenshot.empty() && options.frames == 0)
        throw UserError("--screenshot: also give --frames N (the frame to save; the viewer then exits)");
    checkLightingFlags(options);
}

}  // namespace candela::app
