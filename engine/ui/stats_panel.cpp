// The frame-statistics panel: CPU frame time (wall time between frames), the GPU time of each
// pass of the latest completed frame, the draws and triangles submitted against the scene's
// (frustum culling, levels of detail) and the state changes recorded.

#include "ui/panels.h"
#include "ui/viewer.h"

#include <imgui.h>

namespace candela::ui {

void drawStatsPanel(Viewer& viewer) {
    const double cpuMs = viewer.cpuFrameMs();
    ImGui::Text("frame: %.1f ms (%.1f fps)", cpuMs, cpuMs > 0.0 ? 1000.0 / cpuMs : 0.0);
    double gpuTotal = 0.0;
    for (const PassTime& t : viewer.renderer().completedPassTimes())
        if (t.gpuMs >= 0.0) gpuTotal += t.gpuMs;
    ImGui::Text("GPU, all passes: %.2f ms", gpuTotal);
    for (const PassTime& t : viewer.renderer().completedPassTimes())
        if (t.gpuMs >= 0.0) ImGui::BulletText("%s: %.2f ms", t.name.c_str(), t.gpuMs);
    const passes::DrawStats& draws = viewer.renderer().drawStats();
    ImGui::Text("draws: %u of %u (%u culled, %u at a coarser level)", draws.submittedDraws, draws.sceneDraws,
                draws.culledDraws, draws.coarserDraws);
    ImGui::Text("triangles: %llu of %llu", static_cast<unsigned long long>(draws.submittedTriangles),
                static_cast<unsigned long long>(draws.sceneTriangles));
    ImGui::Text("state changes: %u (%u pipeline, %u descriptor-set binds)", draws.stateChanges(), draws.pipelineBinds,
                draws.descriptorBinds);
    const VkExtent2D extent = viewer.swapchainExtent();
    ImGui::Text("%ux%u, %s, swapchain recreated %u times", extent.width, extent.height,
                viewer.vsync() ? "vsync" : "no vsync", viewer.swapchainRecreations());
    bool vsync = viewer.vsync();
    if (ImGui::Checkbox("vsync", &vsync)) viewer.setVsync(vsync);
}

}  // namespace candela::ui
