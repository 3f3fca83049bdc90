// The camera panel, as in the original project: position, target, vertical field of view, near
// plane and the mouse speeds. Every edit changes the orbit camera, from which the view and
// projection matrices are recomputed for the next frame.

#include "ui/orbit_controls.h"
#include "ui/panels.h"
#include "ui/viewer.h"

#include <glm/gtc/type_ptr.hpp>
#include <imgui.h>

#include <algorithm>

namespace candela::ui {

void drawCameraPanel(Viewer& viewer) {
    scene::OrbitCamera& camera = viewer.camera();
    const float step = std::max(camera.radius * 0.005f, 1e-4f);
    glm::vec3 eye = camera.eye();
    if (ImGui::DragFloat3("position", glm::value_ptr(eye), step)) setEye(camera, eye);
    ImGui::DragFloat3("target", glm::value_ptr(camera.target), step);
    ImGui::SliderFloat("vertical FOV", &camera.fovYDegrees, 5.0f, 120.0f, "%.1f deg");
    float znear = camera.znear > 0.0f ? camera.znear : camera.radius * 1e-3f;
    if (ImGui::DragFloat("near plane", &znear, znear * 0.01f, 1e-5f, camera.radius, "%.5f", ImGuiSliderFlags_Logarithmic))
        camera.znear = std::max(znear, 1e-5f);
    ImGui::DragFloat("distance", &camera.radius, step, 1e-4f, 1e6f, "%.3f");
    ImGui::DragFloat("azimuth", &camera.thetaDegrees, 0.5f, -180.0f, 180.0f, "%.1f deg");
    ImGui::SliderFloat("polar angle", &camera.phiDegrees, 1.0f, 179.0f, "%.1f deg");
    OrbitSpeeds& speeds = viewer.speeds();
    ImGui::SliderFloat("rotate speed", &speeds.rotateDegreesPerPixel, 0.02f, 2.0f, "%.2f deg/px");
    ImGui::SliderFloat("zoom speed", &speeds.zoomPerStep, 0.01f, 0.5f, "%.2f per step");
    ImGui::SliderFloat("pan speed", &speeds.panScale, 0.1f, 4.0f, "%.2f");
    if (ImGui::Button("Frame scene (F)")) viewer.frameScene();
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) viewer.resetCamera();
    textDisabledWrapped("right-drag: rotate, middle-drag: pan, wheel: zoom");
}

}  // namespace candela::ui
