// The shader-parameter panel: for each pass of the last frame's graph that ran, the editable
// members of the parameter blocks it filled (push constants, and the forward pass's lights),
// generated from the SPIR-V reflection and its annotations. Materials are in the material
// inspector.

#include "ui/panels.h"
#include "ui/parameter_widgets.h"
#include "ui/viewer.h"

#include <imgui.h>

#include <algorithm>

namespace candela::ui {

void drawParameterPanel(Viewer& viewer) {
    shader::ParameterRegistry& registry = viewer.renderer().parameters();
    const graph::RenderGraph& graph = viewer.renderer().lastGraph();
    if (!graph.isCompiled()) return;
    if (ImGui::Button("Reset all")) registry.resetAll();
    for (uint32_t p : graph.compiled().order) {
        const std::string& pass = graph.declaration().passes[p].name;
        const auto inPass = [&](const shader::ParameterRegistry::Block& b, bool lights) {
            return b.pass == pass && b.frame == registry.frame() && !b.members.empty() &&
                   (b.name.rfind("Lights[", 0) == 0) == lights && b.name.rfind("Materials[", 0) != 0 &&
                   b.name.rfind("MaterialLayers[", 0) != 0;  // the material inspector's
        };
        const auto& blocks = registry.blocks();
        const bool any = std::any_of(blocks.begin(), blocks.end(), [&](const auto& b) { return inPass(b, false) || inPass(b, true); });
        if (!any || !ImGui::TreeNodeEx(pass.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
        // The tonemap's background colour shows only where nothing else is behind the scene.
        std::vector<std::string_view> unseen;
        if (pass == "tonemap") {
            textDisabledWrapped("behind the scene: " + viewer.behindScene());
            if (viewer.renderer().lastBackdrop() != Renderer::Backdrop::Color) unseen.push_back("params.background");
        }
        for (const auto& block : blocks)
            if (inPass(block, false)) drawParameterBlock(registry, block, unseen);
        for (const auto& block : blocks)
            if (inPass(block, true) && ImGui::TreeNode(block.name.c_str())) {
                drawParameterBlock(registry, block);
                ImGui::TreePop();
            }
        ImGui::TreePop();
    }
}

}  // namespace candela::ui
