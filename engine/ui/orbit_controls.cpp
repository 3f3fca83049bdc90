#include "ui/orbit_controls.h"

#include <algorithm>
#include <cmath>

namespace candela::ui {

void applyPointer(scene::OrbitCamera& camera, const PointerInput& input, const OrbitSpeeds& speeds) {
    if (input.rotate) {
        camera.thetaDegrees -= input.delta.x * speeds.rotateDegreesPerPixel;
        camera.thetaDegrees = std::remainder(camera.thetaDegrees, 360.0f);
        camera.phiDegrees = std::clamp(camera.phiDegrees - input.delta.y * speeds.rotateDegreesPerPixel, 1.0f, 179.0f);
    }
    if (input.pan && input.viewportHeight > 0.0f) {
        const scene::ViewSetup view = camera.view(1.0f);
        const glm::vec3 right(view.view[0][0], view.view[1][0], view.view[2][0]);
        const glm::vec3 up(view.view[0][1], view.view[1][1], view.view[2][1]);
        // World units per pixel at the target's distance.
        const float perPixel =
            2.0f * camera.radius * std::tan(glm::radians(camera.fovYDegrees) * 0.5f) / input.viewportHeight;
        camera.target += (-input.delta.x * right + input.delta.y * up) * perPixel * speeds.panScale;
    }
    if (input.scroll != 0.0f) {
        const float factor = std::pow(1.0f - std::clamp(speeds.zoomPerStep, 0.0f, 0.9f), input.scroll);
        const float radius = std::max(camera.radius * factor, 1e-6f);
        // Keep the near plane proportional to the distance when it was derived from it.
        if (camera.znear > 0.0f) camera.znear *= radius / camera.radius;
        camera.radius = radius;
    }
}

void setEye(scene::OrbitCamera& camera, const glm::vec3& eye) {
    const glm::vec3 offset = eye - camera.target;
    const float radius = glm::length(offset);
    if (!(radius > 0.0f) || !std::isfinite(radius)) return;
    camera.radius = radius;
    camera.phiDegrees = glm::degrees(std::acos(std::clamp(offset.y / radius, -1.0f, 1.0f)));
    camera.thetaDegrees = glm::degrees(std::atan2(offset.x, offset.z));
}

}  // namespace candela::ui
