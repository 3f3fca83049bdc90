// The animation panel: the scene's animations with a checkbox each (the ones ticked play
// together; when they drive the same channels, a line says which and which wins), play/pause
// (also the space key), speed, looping, and a time slider that scrubs.

#include "pose/animation_conflicts.h"
#include "ui/panels.h"
#include "ui/viewer.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace candela::ui {

void drawAnimationPanel(Viewer& viewer) {
    const scene::Scene& scene = viewer.scene();
    if (scene.animations.empty()) {
        ImGui::TextDisabled("the scene has no animations");
        return;
    }
    std::vector<uint32_t> playing = viewer.pose().playing();
    bool changed = false;
    for (uint32_t a = 0; a < scene.animations.size(); ++a) {
        bool on = std::find(playing.begin(), playing.end(), a) != playing.end();
        const std::string label = scene.animations[a].name + " (" + std::to_string(scene.animations[a].duration).substr(0, 5) +
                                  " s)##animation" + std::to_string(a);
        if (ImGui::Checkbox(label.c_str(), &on)) {
            if (on) playing.push_back(a);
            else playing.erase(std::find(playing.begin(), playing.end(), a));
            changed = true;
        }
    }
    if (changed) {
        std::sort(playing.begin(), playing.end());
        viewer.setPlayingAnimations(playing);
    }
    // Ticked animations that drive the same channels: which, and which wins.
    if (const std::string overlap = pose::describeAnimationConflicts(scene, pose::animationConflicts(scene, viewer.pose().playing()));
        !overlap.empty())
        ImGui::TextWrapped("%s", overlap.c_str());
    bool& paused = viewer.animationPaused();
    if (ImGui::Button(paused ? "Play (space)" : "Pause (space)")) paused = !paused;
    ImGui::SameLine();
    ImGui::Checkbox("loop", &viewer.animationLoop());
    ImGui::SliderFloat("speed", &viewer.animationSpeed(), 0.0f, 4.0f, "%.2fx");
    const double duration = viewer.pose().duration();
    float time = float(viewer.animationLoop() ? animation::loopTime(viewer.animationTime(), duration) : viewer.animationTime());
    if (ImGui::SliderFloat("time", &time, 0.0f, float(std::max(duration, 1e-3)), "%.3f s")) viewer.setAnimationTime(time);
    if (!viewer.pose().deformedDraws().empty())
        ImGui::TextDisabled("%zu draws deformed by skin_morph", viewer.pose().deformedDraws().size());
}

}  // namespace candela::ui
