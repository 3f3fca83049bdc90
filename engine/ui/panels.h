#pragma once
// The viewer's ImGui panels, one file each. Each draws its section of a panel column for the
// current frame and acts through the Viewer's actions. Precondition: inside ImGui::NewFrame() /
// ImGui::Render().

#include <string>

namespace candela::ui {

class Viewer;

// Text in the disabled (grey) colour, wrapped at the panel's width (viewer_ui.cpp).
void textDisabledWrapped(const std::string& text);
// Text holding a file path, wrapped at the panel's width after a '/' or a space (viewer_ui.cpp).
void textPathWrapped(const std::string& text, bool disabled = false);

void drawGraphPanel(Viewer& viewer);      // graph_panel.cpp: passes, toggles, times, resources, memory, export
void drawCameraPanel(Viewer& viewer);     // camera_panel.cpp: position, target, field of view, near plane, speeds
void drawAnimationPanel(Viewer& viewer);  // animation_panel.cpp: which animations play, pause, speed, loop, time
void drawStatsPanel(Viewer& viewer);      // stats_panel.cpp: frame time, pass times, draws and triangles
void drawParameterPanel(Viewer& viewer);  // parameter_panel.cpp: reflected shader parameters of the active passes
void drawMaterialPanel(Viewer& viewer);   // material_panel.cpp: pick a material, edit its factors
void drawDebugViewPanel(Viewer& viewer);   // debug_view_panel.cpp: material inputs and shading terms alone
void drawEnvironmentPanel(Viewer& viewer); // environment_panel.cpp: environment, look, quality with measured figures

}  // namespace candela::ui
