// The frame-statistics panel: CPU frame time (wall time between frames), the GPU time of the
// latest completed frame (each pass's in a tree node), the draws and triangles submitted against the scene's
// (frustum culling, levels of detail) and the state changes recorded.

#include "graph/graph_export.h"
#include "ui/panels.h"
#include "ui/viewer.h"
#include "vk/timestamps.h"

#include <imgui.h>

#include <cstdio>

namespace candela::ui {

void drawStatsPanel(Viewer& viewer) {
    const double cpuMs = viewer.cpuFrameMs();
    ImGui::Text("frame: %.1f ms (%.1f fps)", cpuMs, cpuMs > 0.0 ? 1000.0 / cpuMs : 0.0);
    double gpuTotal = 0.0;
    for (const PassTime& t : viewer.renderer().completedPassTimes())
        if (t.gpuMs >= 0.0) gpuTotal += t.gpuMs;
    // Each pass's time (the render-graph panel has them too) one click away: the stats stay short.
    // On CPU devices the timestamps miss deferred work: marked "*", the reason on hover.
    const bool unreliable = !vk::timestampsMeasurePasses(viewer.context().caps().driver);
    const char* mark = unreliable ? "*" : "";
    char total[64];
    std::snprintf(total, sizeof total, "GPU, all passes: %.2f ms%s###gpu", gpuTotal, mark);
    const bool open = ImGui::TreeNode(total);
    if (unreliable && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", graph::kUnreliableGpuTimes);
    if (open) {
        for (const PassTime& t : viewer.renderer().completedPassTimes())
            if (t.gpuMs >= 0.0) ImGui::BulletText("%s: %.2f ms%s", t.name.c_str(), t.gpuMs, mark);
        ImGui::TreePop();
    }
    const passes::DrawStats& draws = viewer.renderer().drawStats();
    ImGui::TextWrapped("draws: %u of %u (%u culled, %u at a coarser level)", draws.submittedDraws, draws.sceneDraws,
                       draws.culledDraws, draws.coarserDraws);
    ImGui::TextWrapped("triangles: %llu of %llu", static_cast<unsigned long long>(draws.submittedTriangles),
                       static_cast<unsigned long long>(draws.sceneTriangles));
    ImGui::TextWrapped("state changes: %u (%u pipeline, %u descriptor-set binds)", draws.stateChanges(),
                       draws.pipelineBinds, draws.descriptorBinds);
    const VkExtent2D extent = viewer.swapchainExtent();
    ImGui::TextWrapped("%ux%u, %s, swapchain recreated %u times", extent.width, extent.height,
                       viewer.vsync() ? "vsync" : "no vsync", viewer.swapchainRecreations());
    bool vsync = viewer.vsync();
    if (ImGui::Checkbox("vsync", &vsync)) viewer.setVsync(vsync);
}

}  // namespace candela::ui
