#pragma once
// `candela view`'s options and flags.

#include "flag_spec.h"
#include "scene_render_options.h"
#include "options/viewer_panels.h"

#include <set>
#include <string>
#include <vector>

namespace candela::app {

struct ViewOptions : SceneRenderOptions {
    uint32_t frames = 0;          // --frames N: frames to render before exiting (0: until the window is closed)
    std::string screenshot;       // --screenshot FILE (saves the last of --frames N)
    bool vsync = true;            // --no-vsync
    bool ui = true;               // --no-ui
    std::string shaderDir;        // --shaders DIR (hot reload; default: the source tree's shaders/)
    std::string iblReport;        // --ibl-report FILE (an ibl-report CSV for the environment panel)
    std::set<options::Panel> panels;   // --panels A,B,... (open at start)
    bool operator==(const ViewOptions&) const = default;
};

// Every flag view takes.
std::vector<FlagSpec<ViewOptions>> viewFlags();
// The SCENE argument: the scene, as --scene; a UserError for a second one.
void takeViewArgument(ViewOptions& options, const std::string& argument);
// The checks that involve more than one flag; a UserError naming them.
void checkViewOptions(const ViewOptions& options);

}  // namespace candela::app
