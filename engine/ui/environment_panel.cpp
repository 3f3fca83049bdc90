// The environment / IBL panel: which environment lights the scene (a dropped .hdr/.exr, the
// built-in sky, or none) and whether the file's own punctual lights join it, how it is looked up (rotation, intensity, skybox, blur, multiscatter),
// and the precompute quality — each setting `candela ibl-report` measured listed with the time
// (× the calibration pass) and the errors it measured, applied with the recompute button.

#include "ui/panels.h"
#include "ui/viewer.h"

#include <imgui.h>

#include <string>

namespace candela::ui {

namespace {

// The quality the panel edits before it is applied (one panel per process).
ibl::IblQuality gPending;
bool gPendingSet = false;

}  // namespace

void drawEnvironmentPanel(Viewer& viewer) {
    RenderSettings& settings = viewer.settings();
    const assets::Environment* environment = viewer.environment();
    textPathWrapped("environment: " + (environment ? environment->source : std::string("none (no image-based lighting)")));
    if (ImGui::Button("Procedural sky")) viewer.useProceduralSky();
    ImGui::SameLine();
    if (ImGui::Button("None")) viewer.useNoEnvironment();
    ImGui::SameLine();
    ImGui::TextDisabled("or drop an .hdr/.exr");
    if (settings.scene && !settings.scene->lights.empty()) {
        // Off: the file's KHR_lights_punctual lights are left out (image-based lighting alone).
        ImGui::Checkbox("scene lights", &settings.sceneLights);
        ImGui::SameLine();
        ImGui::TextDisabled("(%zu in the file)", settings.scene->lights.size());
    }
    if (!environment) return;

    ibl::IblLook& look = settings.ibl;
    ImGui::SliderFloat("rotation", &look.rotationDegrees, -180.0f, 180.0f, "%.0f deg");
    ImGui::SliderFloat("intensity", &look.intensity, 0.0f, 16.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    ImGui::Checkbox("skybox", &look.skybox);
    ImGui::SameLine();
    ImGui::Checkbox("multiscatter", &look.multiscatter);
    ImGui::SliderFloat("skybox blur", &look.skyboxBlur, 0.0f, 1.0f, "%.2f");
    if (const PrecomputeTime& last = viewer.renderer().lastPrecompute(); last.frameMs >= 0.0)
        ImGui::TextWrapped("last precompute: %.0f ms (frame with it), %.0f ms GPU in its passes", last.frameMs, last.gpuMs);

    if (!gPendingSet) {
        gPending = settings.iblQuality;
        gPendingSet = true;
    }
    const std::vector<IblReportTable>& reports = viewer.iblReports();
    int& selected = viewer.selectedIblReport();
    if (reports.empty()) return;
    selected = std::clamp(selected, 0, int(reports.size()) - 1);
    // A table is named by what it was measured on (a CSV of the user's, which does not say, by its path).
    const auto tableName = [](const IblReportTable& table) {
        return table.environment.empty() ? table.name.c_str() : table.environment.c_str();
    };
    if (ImGui::BeginCombo("measured on", tableName(reports[size_t(selected)]))) {
        for (int i = 0; i < int(reports.size()); ++i)
            if (ImGui::Selectable(tableName(reports[size_t(i)]), i == selected)) selected = i;
        ImGui::EndCombo();
    }
    const IblReportTable& report = reports[size_t(selected)];
    if (const std::string note = iblReportNote(reports, size_t(selected), environment->source); !note.empty())
        textDisabledWrapped(note);
    textDisabledWrapped("x cal.: precompute time / calibration pass; errors: mean relative");
    // Every column as wide as its header and cells; the setting's takes what is left.
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
    if (ImGui::BeginTable("quality", 5, flags, ImVec2(0.0f, ImGui::GetTextLineHeightWithSpacing() * 13.0f))) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("setting", ImGuiTableColumnFlags_WidthStretch);
        for (const char* name : {"x cal.", "specular", "irrad.", "image"})
            ImGui::TableSetupColumn(name, ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableHeadersRow();
        std::string group;
        for (const IblReportRow& row : report.rows) {
            if (row.group != group) {
                group = row.group;
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextDisabled("%s", group.c_str());
            }
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const bool current = report.find(settings.iblQuality) == &row;
            const bool pending = report.find(gPending) == &row;
            const std::string label = "  " + row.setting + (current ? "  (in use)" : "") + "##" + group + row.setting;
            if (ImGui::Selectable(label.c_str(), pending, ImGuiSelectableFlags_SpanAllColumns)) gPending = row.quality;
            ImGui::TableNextColumn();
            ImGui::Text("%.1f", row.ratioToCalibration);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", row.specularMeanRelative);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", row.irradianceMeanRelative);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", row.imageMeanRelative);
        }
        ImGui::EndTable();
    }
    const IblReportRow* chosen = report.find(gPending);
    ImGui::TextWrapped("selected: %s", gPending.canonical().c_str());
    if (chosen) {
        // Two short lines: wrapped text may break after a number's decimal point.
        ImGui::Text("measured: %.0f ms = %.1fx calibration", chosen->precomputeMs, chosen->ratioToCalibration);
        ImGui::Text("specular error %.3f, image error %.3f", chosen->specularMeanRelative, chosen->imageMeanRelative);
    }
    if (ImGui::Button("Recompute with the selected settings")) {
        gPending.lodBias = settings.iblQuality.lodBias;
        if (gPending == settings.iblQuality)
            viewer.recomputeIbl();
        else
            settings.iblQuality = gPending;  // a changed quality reruns the precompute in the next frame
    }
}

}  // namespace candela::ui
