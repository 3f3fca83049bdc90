#include "ui/panel_layout.h"

#include <algorithm>

namespace candela::ui {

float PanelLayout::lensShiftX(float width) const {
    if (width <= 0.0f) return 0.0f;
    // NDC x spans 2 over the window: the centre moves by (sceneLeft + sceneRight - width) / 2 pixels.
    return (sceneLeft + sceneRight - width) / width;
}

float PanelLayout::sceneAspect(float height) const {
    return height > 0.0f ? std::max(sceneRight - sceneLeft, 1.0f) / height : 1.0f;
}

PanelLayout layoutPanels(float width, float height, float fontSize) {
    float left = kLeftColumnEms * fontSize, right = kRightColumnEms * fontSize;
    // The columns leave the scene at least a third of the window.
    const float most = width * 2.0f / 3.0f;
    if (left + right > most) {
        const float scale = most / (left + right);
        left *= scale;
        right *= scale;
    }
    PanelLayout layout;
    layout.left = {0.0f, 0.0f, left, height};
    layout.right = {width - right, 0.0f, right, height};
    layout.sceneLeft = left;
    layout.sceneRight = width - right;
    return layout;
}

}  // namespace candela::ui
