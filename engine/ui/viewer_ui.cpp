// The viewer's UI frame (Viewer::drawUi): the panels in two columns docked to the window's edges
// (ui/panel_layout.h). Left: the file, its scenes, the status line and shader errors, then the
// render graph, shader parameters and materials. Right: the frame statistics on top, as tall as
// their lines, then the environment, camera, animation and debug view. Each column scrolls on its
// own; what each window's content needs is recorded for the tests (Viewer::uiWindows).

#include "ui/panels.h"
#include "ui/viewer.h"

#include <imgui.h>
#include <imgui_internal.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <algorithm>

namespace candela::ui {

namespace {

struct PanelEntry {
    options::Panel key;
    const char* title;
    void (*draw)(Viewer&);
};

constexpr PanelEntry kLeftPanels[] = {{options::Panel::Graph, "Render graph", drawGraphPanel},
                                      {options::Panel::Parameters, "Shader parameters", drawParameterPanel},
                                      {options::Panel::Materials, "Materials", drawMaterialPanel}};
constexpr PanelEntry kRightPanels[] = {{options::Panel::Environment, "Environment / IBL", drawEnvironmentPanel},
                                       {options::Panel::Camera, "Camera", drawCameraPanel},
                                       {options::Panel::Animation, "Animation", drawAnimationPanel},
                                       {options::Panel::Debug, "Debug view", drawDebugViewPanel}};

constexpr ImGuiWindowFlags kDocked = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoSavedSettings;
// Room for a widget's label right of it, in font sizes (sliders and fields take the rest).
constexpr float kLabelEms = 10.0f;
constexpr float kBackgroundAlpha = 0.85f;
const ImVec4 kErrorColour(1.0f, 0.45f, 0.4f, 1.0f);
const ImVec4 kStatusColour(0.6f, 0.9f, 0.6f, 1.0f);

void textWrappedColoured(const ImVec4& colour, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

}  // namespace

void textDisabledWrapped(const std::string& text) {
    textWrappedColoured(ImGui::GetStyle().Colors[ImGuiCol_TextDisabled], text);
}

void textPathWrapped(const std::string& text, bool disabled) {
    // ImGui's wrapping breaks at spaces and after full stops ("../" would become ".", ".", "/…"):
    // lines end after a '/' or a space instead, and a part longer than a line is cut where it
    // reaches the edge.
    const float width = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize());
    const auto fits = [&](std::string_view line) {
        return ImGui::CalcTextSize(line.data(), line.data() + line.size()).x <= width;
    };
    if (disabled) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    std::string_view rest = text;
    while (!rest.empty()) {
        size_t end = 0;  // the longest prefix that fits and ends after a break, else fits at all
        for (size_t i = 0; i < rest.size(); ++i)
            if ((rest[i] == '/' || rest[i] == ' ' || i + 1 == rest.size()) && fits(rest.substr(0, i + 1))) end = i + 1;
        if (end == 0)
            while (end < rest.size() && (end == 0 || fits(rest.substr(0, end + 1)))) ++end;
        const std::string_view line = rest.substr(0, end);
        ImGui::TextUnformatted(line.data(), line.data() + line.size());
        rest.remove_prefix(end);
    }
    if (disabled) ImGui::PopStyleColor();
}

void Viewer::recordUiWindow(const char* name) {
    const ImGuiWindow* window = ImGui::GetCurrentWindow();
    const ImVec2 start = window->DC.CursorStartPos;
    const ImVec2 origin = ImGui::GetMainViewport()->WorkPos;
    UiWindow record{.name = name,
                    .rect = {window->Pos.x - origin.x, window->Pos.y - origin.y, window->Size.x, window->Size.y}};
    // As ImGui measures a window's content for scrolling and auto-resize (its "ideal" size counts
    // a table at the width that fits every column's header and cells).
    record.contentWidth = std::max(window->DC.CursorMaxPos.x, window->DC.IdealMaxPos.x) - start.x;
    record.contentHeight = std::max(window->DC.CursorMaxPos.y, window->DC.IdealMaxPos.y) - start.y;
    record.roomWidth = window->InnerRect.GetWidth() - 2.0f * window->WindowPadding.x;
    record.roomHeight = window->InnerRect.GetHeight() - 2.0f * window->WindowPadding.y;
    record.scrollsY = window->ScrollbarY;
    mUiWindows.push_back(std::move(record));
}

void Viewer::drawUi() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    mFontSize = ImGui::GetFontSize();
    mLayout = layoutPanels(viewport->WorkSize.x, viewport->WorkSize.y, mFontSize);
    mUiWindows.clear();
    const auto place = [&](const PanelRect& rect) {
        ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + rect.x, viewport->WorkPos.y + rect.y), ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(rect.width, rect.height), ImGuiCond_Always);
        ImGui::SetNextWindowBgAlpha(kBackgroundAlpha);
    };
    const auto drawPanels = [&](const auto& panels) {
        for (const PanelEntry& panel : panels) {
            ImGui::SetNextItemOpen(mOpenPanels.count(panel.key) > 0, ImGuiCond_Once);
            if (ImGui::CollapsingHeader(panel.title)) panel.draw(*this);
        }
    };

    place(mLayout.left);
    ImGui::Begin("Candela", nullptr, kDocked);
    ImGui::PushItemWidth(-kLabelEms * mFontSize);
    // The file's name, and its folder below it (wrapped: paths are long).
    const std::filesystem::path source(mScene.source);
    ImGui::TextUnformatted(source.has_filename() ? source.filename().c_str() : mScene.source.c_str());
    if (source.has_parent_path()) textPathWrapped("in " + source.parent_path().string(), /*disabled=*/true);
    if (mScene.sceneNames.size() > 1) {
        // The file's scenes: choosing one reloads the file with it.
        int chosen = int(mScene.sceneIndex);
        const auto name = [](void* data, int i, const char** out) {
            *out = static_cast<const scene::Scene*>(data)->sceneNames[size_t(i)].c_str();
            return true;
        };
        if (ImGui::Combo("scene", &chosen, name, &mScene, int(mScene.sceneNames.size())) && chosen != int(mScene.sceneIndex))
            openFile(mScene.source, uint32_t(chosen));
    }
    if (!mStatus.empty()) textWrappedColoured(mStatusIsError ? kErrorColour : kStatusColour, mStatus);
    for (const std::string& error : mHotReload->errors()) textWrappedColoured(kErrorColour, error);
    drawPanels(kLeftPanels);
    ImGui::PopItemWidth();
    recordUiWindow("Candela");
    ImGui::End();

    // The frame stats: as tall as their lines (at most half the column; more scrolls).
    const PanelRect& right = mLayout.right;
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + right.x, viewport->WorkPos.y + right.y), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(right.width, 0.0f), ImVec2(right.width, right.height * 0.5f));
    ImGui::SetNextWindowBgAlpha(kBackgroundAlpha);
    ImGui::Begin("Frame stats", nullptr, kDocked | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushItemWidth(-kLabelEms * mFontSize);
    ImGui::SetNextItemOpen(mOpenPanels.count(options::Panel::Stats) > 0, ImGuiCond_Once);
    if (ImGui::CollapsingHeader("Frame stats")) drawStatsPanel(*this);
    ImGui::PopItemWidth();
    const float statsHeight = ImGui::GetWindowHeight();
    recordUiWindow("Frame stats");
    ImGui::End();

    place({right.x, right.y + statsHeight, right.width, std::max(right.height - statsHeight, 0.0f)});
    ImGui::Begin("Panels", nullptr, kDocked);
    ImGui::PushItemWidth(-kLabelEms * mFontSize);
    drawPanels(kRightPanels);
    ImGui::PopItemWidth();
    recordUiWindow("Panels");
    ImGui::End();
    ImGui::Render();
}

}  // namespace candela::ui
