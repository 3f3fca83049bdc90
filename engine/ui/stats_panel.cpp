// The frame-statistics panel: CPU frame time (wall time between frames), the GPU time of each
// pass of the latest completed frame, and the scene's draw and triangle counts.

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
    const scene::Scene& scene = viewer.scene();
    uint64_t triangles = 0;
    for (const scene::Draw& draw : scene.draws) triangles += draw.indexCount / 3;
    ImGui::Text("draws: %zu, triangles: %llu", scene.draws.size(), static_cast<unsigned long long>(triangles));
    const VkExtent2D extent = viewer.swapchainExtent();
    ImGui::Text("%ux%u, %s, swapchain recreated %u times", extent.width, extent.height,
                viewer.vsync() ? "vsync" : "no vsync", viewer.swapchainRecreations());
    bool vsync = viewer.vsync();
    if (ImGui::Checkbox("vsync", &vsync)) viewer.setVsync(vsync);
}

}  // namespace candela::ui
