#include "ui/parameter_widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace candela::ui {

namespace {

// The label of a member: its name without the block's instance name ("push.ibl.intensity" →
// "ibl.intensity").
std::string labelOf(const shader::BlockMember& m) {
    const size_t dot = m.name.find('.');
    return dot == std::string::npos ? m.name : m.name.substr(dot + 1);
}

// Edits one member's bytes in place with the widget labelled `label` (ImGui label and ID);
// returns true when the user changed them.
bool memberWidget(const shader::BlockMember& m, std::byte* bytes, const char* label) {
    const int n = int(m.vectorSize);
    switch (m.type) {
        case shader::BaseType::Float: {
            auto* v = reinterpret_cast<float*>(bytes);
            if (m.annotation.color && n == 3) return ImGui::ColorEdit3(label, v, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
            if (m.annotation.color && n == 4) return ImGui::ColorEdit4(label, v, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
            if (m.annotation.min && m.annotation.max) {
                const float lo = *m.annotation.min, hi = *m.annotation.max;
                // Wide non-negative ranges (intensities) are easier to set on a logarithmic scale.
                const ImGuiSliderFlags flags = lo >= 0.0f && hi >= 100.0f ? ImGuiSliderFlags_Logarithmic : 0;
                return ImGui::SliderScalarN(label, ImGuiDataType_Float, v, n, &lo, &hi, "%.3f", flags);
            }
            return ImGui::DragScalarN(label, ImGuiDataType_Float, v, n, 0.01f);
        }
        case shader::BaseType::Int: return ImGui::DragScalarN(label, ImGuiDataType_S32, bytes, n, 0.1f);
        case shader::BaseType::UInt: return ImGui::DragScalarN(label, ImGuiDataType_U32, bytes, n, 0.1f);
        case shader::BaseType::Bool: {
            bool value = *reinterpret_cast<const uint32_t*>(bytes) != 0;
            if (!ImGui::Checkbox(label, &value)) return false;
            const uint32_t word = value ? 1u : 0u;
            std::memcpy(bytes, &word, 4);
            return true;
        }
        default: return false;
    }
}

}  // namespace

bool drawParameterBlock(shader::ParameterRegistry& registry, const shader::ParameterRegistry::Block& block,
                        std::span<const std::string_view> unseen) {
    bool edited = false;
    ImGui::PushID(block.pass.c_str());
    ImGui::PushID(block.name.c_str());
    for (const shader::BlockMember& m : block.members) {
        std::byte value[16];
        std::memcpy(value, block.values.data() + m.offset, m.size);
        ImGui::PushID(m.name.c_str());
        const bool disabled = std::find(unseen.begin(), unseen.end(), m.name) != unseen.end();
        if (disabled) ImGui::BeginDisabled();
        if (registry.isSet(block.pass, block.name, m.name)) {
            if (ImGui::SmallButton("x")) registry.reset(block.pass, block.name, m.name);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the value the renderer sets");
            ImGui::SameLine();
        }
        // The full name in the ImGui ID; a label wider than the room right of the widget goes on
        // its own line above it (a checkbox's follows the box).
        const std::string shown = labelOf(m);
        std::string label = shown + "##" + m.name;
        const float room = ImGui::GetContentRegionAvail().x - ImGui::CalcItemWidth() - ImGui::GetStyle().ItemInnerSpacing.x;
        if (m.type != shader::BaseType::Bool && ImGui::CalcTextSize(shown.c_str()).x > room) {
            ImGui::TextUnformatted(shown.c_str());
            label = "##" + m.name;
        }
        if (memberWidget(m, value, label.c_str())) {
            registry.set(block.pass, block.name, m, std::span(value, m.size));
            edited = true;
        }
        if (disabled) ImGui::EndDisabled();
        ImGui::PopID();
    }
    ImGui::PopID();
    ImGui::PopID();
    return edited;
}

}  // namespace candela::ui
