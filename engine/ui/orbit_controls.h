#pragma once
// Mouse control of the orbit camera, as in the original project: right-drag rotates about the
// target, the scroll wheel zooms (changes the distance), middle-drag pans (moves the target in the
// view plane). Pure functions of the camera and the input: unit-tested without a window.

#include "scene/camera.h"

#include <glm/glm.hpp>

namespace candela::ui {

struct OrbitSpeeds {
    float rotateDegreesPerPixel = 0.25f;
    float zoomPerStep = 0.1f;  // fraction of the distance per scroll step
    float panScale = 1.0f;     // 1: the point under the cursor follows the cursor (at the target's depth)
};

struct PointerInput {
    glm::vec2 delta{0.0f};  // cursor movement since the last frame, pixels (y down)
    bool rotate = false;    // right button held
    bool pan = false;       // middle button held
    float scroll = 0.0f;    // wheel steps (positive: zoom in)
    float viewportHeight = 1.0f;  // pixels
};

// Applies one frame of pointer input. The polar angle stays within [1°, 179°] and the distance
// positive.
void applyPointer(scene::OrbitCamera& camera, const PointerInput& input, const OrbitSpeeds& speeds);

// Moves the eye to `eye`, keeping the target: recomputes the angles and the distance (the camera
// panel's position field). An eye on the target leaves the camera unchanged.
void setEye(scene::OrbitCamera& camera, const glm::vec3& eye);

}  // namespace candela::ui
