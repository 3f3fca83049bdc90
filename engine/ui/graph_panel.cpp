// The render-graph panel: every declared pass of the last frame in execution order (culled ones
// after, greyed, with the reason), an enabled checkbox per pass (effective next frame), its GPU
// time (marked, with the reason as a tooltip, on devices whose timestamps miss deferred work), the resources it reads and writes (sample counts, resolves, results nothing reads), the
// MSAA sample count (a choice), the transient memory before and after aliasing, and export of the
// graph as dot and JSON.

#include "graph/graph_export.h"
#include "ui/panels.h"
#include "ui/viewer.h"
#include "vk/timestamps.h"

#include <imgui.h>

#include <bit>
#include <string>

namespace candela::ui {

namespace {

// `writer`: for writes, the pass's PassInfo (whose unreadWrites are marked); null for reads.
std::string accessText(const graph::GraphDecl& decl, const graph::AccessDecl& access, const graph::PassInfo* writer) {
    const graph::ResourceDecl& resource = decl.resources[access.resource];
    std::string text = resource.name + " v" + std::to_string(access.version) + " (" + graph::usageName(access.usage);
    if (resource.texture.samples > 1) text += ", " + std::to_string(resource.texture.samples) + " samples";
    if (access.usage == graph::Usage::ResolveAttachment) text += " of " + decl.resources[access.resolveSource].name;
    text += ")";
    if (writer && writer->writeUnread(access.resource))
        text += access.usage == graph::Usage::ResolveAttachment ? " - skipped: resolved over later" : " - not stored: nothing reads it";
    return text;
}

double mib(VkDeviceSize bytes) { return double(bytes) / (1024.0 * 1024.0); }

}  // namespace

void drawGraphPanel(Viewer& viewer) {
    const graph::RenderGraph& graph = viewer.renderer().lastGraph();
    if (!graph.isCompiled()) return;
    const graph::GraphDecl& decl = graph.declaration();
    const graph::CompiledGraph& compiled = graph.compiled();

    // MSAA: the choice applies from the next frame; the device may clamp it.
    RenderSettings& settings = viewer.settings();
    static constexpr const char* kCounts[] = {"device default", "1", "2", "4", "8"};
    int current = settings.msaa ? 1 + std::countr_zero(*settings.msaa) : 0;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    if (ImGui::Combo("MSAA", &current, kCounts, IM_ARRAYSIZE(kCounts)))
        settings.msaa = current == 0 ? std::nullopt : std::optional<uint32_t>(1u << (current - 1));
    textDisabledWrapped(viewer.renderer().msaa(settings.msaa).reason);

    std::vector<uint32_t> rows = compiled.order;
    for (uint32_t p = 0; p < decl.passes.size(); ++p)
        if (compiled.passes[p].cullReason != graph::CullReason::None) rows.push_back(p);

    // The times' column as wide as its widest cell or header (a culled pass shows the reason). On CPU
    // devices the times are marked "GPU ms*" and say why on hover (graph::kUnreliableGpuTimes).
    const bool unreliable = !vk::timestampsMeasurePasses(viewer.context().caps().driver);
    if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn(unreliable ? "GPU ms*" : "GPU ms", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
        for (int column = 0; column < 2; ++column) {
            ImGui::TableSetColumnIndex(column);
            ImGui::TableHeader(ImGui::TableGetColumnName(column));
            if (column == 1 && unreliable && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", graph::kUnreliableGpuTimes);
        }
        for (uint32_t p : rows) {
            const graph::PassDecl& pass = decl.passes[p];
            const graph::PassInfo& info = compiled.passes[p];
            const bool culled = info.cullReason != graph::CullReason::None;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::PushID(int(p));
            bool enabled = viewer.passEnabled(pass.name);
            // The UI's own pass cannot be switched off from the UI (--no-ui leaves it out), nor a
            // pass the frame cannot do without (PassDecl::cannotBeDisabled: the reason on hover).
            const bool self = pass.name == "imgui";
            const bool fixed = self || !pass.cannotBeDisabled.empty();
            if (fixed) ImGui::BeginDisabled();
            if (ImGui::Checkbox("##enabled", &enabled)) viewer.setPassEnabled(pass.name, enabled);
            if (fixed) ImGui::EndDisabled();
            if (!pass.cannotBeDisabled.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
                ImGui::SetTooltip("cannot be switched off: %s", pass.cannotBeDisabled.c_str());
            ImGui::SameLine();
            if (culled) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
            const bool open = ImGui::TreeNodeEx(pass.name.c_str(), ImGuiTreeNodeFlags_SpanAvailWidth);
            if (culled) {
                ImGui::PopStyleColor();
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("culled: %s", info.cullDetail.c_str());
            }
            if (open) {
                if (culled) textDisabledWrapped("culled: " + info.cullDetail);
                const auto bullet = [](const std::string& text) {
                    ImGui::Bullet();
                    ImGui::TextWrapped("%s", text.c_str());
                };
                for (const graph::AccessDecl& a : pass.reads) bullet("reads " + accessText(decl, a, nullptr));
                for (const graph::AccessDecl& a : pass.writes) bullet("writes " + accessText(decl, a, &info));
                ImGui::TreePop();
            }
            ImGui::PopID();
            ImGui::TableNextColumn();
            const double ms = viewer.renderer().completedPassMs(pass.name);
            if (culled)
                ImGui::TextDisabled("%s", graph::cullReasonName(info.cullReason));
            else if (ms >= 0.0) {
                ImGui::Text("%.2f%s", ms, unreliable ? "*" : "");
                if (unreliable && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", graph::kUnreliableGpuTimes);
            }
            else
                ImGui::TextDisabled("-");
        }
        ImGui::EndTable();
    }
    ImGui::TextWrapped("transient memory: %.1f MiB requested, %.1f MiB allocated after aliasing (%zu heaps)",
                mib(compiled.bytesRequested), mib(compiled.bytesAllocated), compiled.heaps.size());
    if (ImGui::Button("Export dot")) viewer.exportGraph("candela-graph.dot", false);
    ImGui::SameLine();
    if (ImGui::Button("Export JSON")) viewer.exportGraph("candela-graph.json", true);
}

}  // namespace candela::ui
