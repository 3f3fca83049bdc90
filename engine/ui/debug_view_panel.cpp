// The debug-view panel: the forward pass shows a material input or a shading term instead of the
// image (a variant of the frame graph; `candela render --debug-view NAME` renders the same).

#include "ui/panels.h"
#include "ui/viewer.h"

#include <imgui.h>

namespace candela::ui {

void drawDebugViewPanel(Viewer& viewer) {
    options::DebugView& view = viewer.settings().debugView;
    if (ImGui::RadioButton("none (the image)", view == options::DebugView::None)) view = options::DebugView::None;
    int column = 0;
    for (options::DebugView candidate : options::allDebugViews()) {
        if (column++ % 2 == 1) ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
        if (ImGui::RadioButton(options::debugViewName(candidate), view == candidate)) view = candidate;
    }
    textDisabledWrapped("d, g, f: toward the first light; data shown as value x 255");
}

}  // namespace candela::ui
