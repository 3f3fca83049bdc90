#pragma once
// Where the viewer's panels go: two columns docked to the window's left and right edges, their
// widths in multiples of the UI font's size (what fits at one font size fits at another), the
// scene centred in the part between them. The right column holds the frame statistics on top
// (as tall as their lines) and the panels below them. Pure arithmetic: no ImGui, no Vulkan.

#include <string>

namespace candela::ui {

struct PanelRect {
    float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
    float right() const { return x + width; }
    float bottom() const { return y + height; }
};

struct PanelLayout {
    PanelRect left;   // the file, render graph, shader parameters, materials
    PanelRect right;  // frame stats, then environment, camera, animation, debug view
    // The horizontal range the scene is centred in: [sceneLeft, sceneRight).
    float sceneLeft = 0.0f, sceneRight = 0.0f;
    // The off-axis shift (CameraSettings::lensShiftX, NDC units) that centres the projection in
    // the scene's range of a window `width` pixels wide.
    float lensShiftX(float width) const;
    // Width / height of the scene's range in a window `height` pixels high.
    float sceneAspect(float height) const;
};

// One window of the panels as a frame laid it out (window pixels), with the room its content
// needs (Dear ImGui's ideal content size: the widest line, a table's columns fitted to their
// headers and cells) and the room it has (inside its padding and scroll bars).
struct UiWindow {
    std::string name;
    PanelRect rect;
    float contentWidth = 0.0f, contentHeight = 0.0f;
    float roomWidth = 0.0f, roomHeight = 0.0f;
    bool scrollsY = false;  // has a vertical scroll bar (content taller than the room scrolls)
};

// The column widths in font sizes: what the widest lines need (the IBL table's five columns and
// the debug views' two columns on the right; a pass name with its GPU time, or a slider with its
// label, on the left).
inline constexpr float kLeftColumnEms = 27.0f;
inline constexpr float kRightColumnEms = 31.0f;

// The layout of a `width` × `height` window whose UI font is `fontSize` pixels high. Each column
// gets its width in ems while the scene keeps at least a third of the window; narrower windows
// shrink both columns in proportion (their text then wraps, or is cut at their edge). Precondition:
// sizes ≥ 0.
PanelLayout layoutPanels(float width, float height, float fontSize);

}  // namespace candela::ui
