// The viewer under a private Xvfb on lavapipe, with validation (synchronization included): opens,
// renders with the UI, toggles a pass as the checkbox does, edits reflected parameters, survives
// resizes and a minimize, saves screenshots, opens dropped files, picks a material, exits 0.

#include "../unit/temp_dir.h"
#include "../unit/test_paths.h"
#include "assets/builtin_scenes.h"
#include "assets/procedural_sky.h"
#include "ui/viewer.h"
#include "xvfb.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <chrono>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <set>
#include <tuple>

namespace candela {
namespace {

const ::testing::Environment* const gXvfb = ::testing::AddGlobalTestEnvironment(new test::XvfbEnvironment);

// Pixels [x0, x1) × [y0, y1).
struct Box {
    int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
    // Mean of R+G+B (or of channel `channel`) over `box`.
    double mean(const Box& box, int channel = -1) const {
        double sum = 0.0;
        for (int y = box.y0; y < box.y1; ++y)
            for (int x = box.x0; x < box.x1; ++x)
                for (int c = 0; c < 3; ++c)
                    if (channel < 0 || c == channel) sum += rgba[(size_t(y) * width + x) * 4 + c];
        return sum / (double(box.y1 - box.y0) * (box.x1 - box.x0) * (channel < 0 ? 3.0 : 1.0));
    }
    // The same over the columns [x0, x1).
    double mean(int x0, int x1, int channel = -1) const { return mean(Box{x0, x1, 0, height}, channel); }
};

Image readPng(const std::filesystem::path& path) {
    Image image;
    int channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
    if (!pixels) return image;
    image.rgba.assign(pixels, pixels + size_t(image.width) * image.height * 4);
    stbi_image_free(pixels);
    return image;
}

class ViewerTest : public ::testing::Test {
protected:
    void open(bool ui = true, bool environment = true, const std::filesystem::path& shaderDir = {},
              options::ShadingPath shadingPath = options::ShadingPath::Auto) {
        ui::ViewerContent content;
        content.settings.shadingPath = shadingPath;
        content.scene = assets::makeSphereGrid();
        if (environment) content.environment = std::make_unique<assets::Environment>(assets::makeProceduralSky());
        content.settings.ibl.skybox = environment;
        content.settings.tonemap.background = environment ? std::nullopt : std::optional(glm::vec3(0.02f));
        content.settings.iblQuality.cubeSize = 64;  // keeps the precompute short; the maps are not under test
        content.settings.iblQuality.prefilterSamples = 8;
        // As `candela view` does: every debug view's variants built in the background, while the
        // tests draw, edit parameters, reload shaders and replace the scene.
        content.settings.precompile = options::Precompile::DebugViews;
        // As `candela view` does: the window system, then the device and renderer, then the viewer.
        mWindowSystem.emplace();
        vk::ContextDesc context{.validation = true};
        mWindowSystem->addTo(context);
        mContext.emplace(context);
        mRenderer.emplace(*mContext, ui::Viewer::kRendererOptions);
        mViewer = std::make_unique<ui::Viewer>(ui::ViewerDesc{.window = {.width = mWidth, .height = mHeight},
                                                              .ui = ui,
                                                              .shaderDir = shaderDir,
                                                              .openPanels = mPanels},
                                               std::move(content), *mContext, *mRenderer);
    }
    void TearDown() override {
        if (!mViewer) return;
        mViewer->renderer().waitIdle();
        for (const vk::ValidationMessage& m : mViewer->context().validationMessages()) ADD_FAILURE() << "validation: " << m.text;
    }
    void frames(int n) {
        for (int i = 0; i < n; ++i) ASSERT_TRUE(mViewer->frame());
    }
    Image screenshot(const std::string& name) {
        const std::filesystem::path path = mDir / name;
        mViewer->requestScreenshot(path);
        frames(1);
        EXPECT_EQ(mViewer->lastScreenshot(), path.string());
        return readPng(path);
    }
    const graph::PassInfo* passInfo(const std::string& name) {
        const graph::RenderGraph& graph = mViewer->renderer().lastGraph();
        const std::optional<uint32_t> pass = graph.findPass(name);
        return pass ? &graph.compiled().passes[*pass] : nullptr;
    }
    bool ran(const std::string& name) {
        const graph::PassInfo* info = passInfo(name);
        return info && info->cullReason == graph::CullReason::None;
    }
    // The columns [first, second) the scene is drawn in, between the panel columns (the last UI
    // frame's layout; the whole window without UI).
    std::pair<int, int> sceneColumns() const {
        if (mViewer->uiWindows().empty()) return {0, int(mViewer->swapchainExtent().width)};
        const ui::PanelLayout& layout = mViewer->panelLayout();
        return {int(std::ceil(layout.sceneLeft)), int(layout.sceneRight)};
    }
    // The middle of the scene between the panels (half its width, half the window's height): where
    // the sphere grid is.
    Box sceneMiddle() const {
        const auto [x0, x1] = sceneColumns();
        const int height = int(mViewer->swapchainExtent().height);
        return {x0 + (x1 - x0) / 4, x1 - (x1 - x0) / 4, height / 4, height - height / 4};
    }
    // The last frame drew the sky: composited by the tonemap, or by the skybox pass.
    bool skyDrawn() {
        const std::vector<std::string> lines = mViewer->renderer().explain();
        return ran("skybox") || std::any_of(lines.begin(), lines.end(), [](const std::string& line) {
                   return line.starts_with("sky: composited ") && line.find(" by the tonemap ") != std::string::npos;
               });
    }

    // Every panel's window lies inside the window and overlaps no other; each is as wide as its
    // content (a path, a reason or a table column cut off at its edge makes the content wider),
    // and the frame stats are as tall as theirs; a column taller than the window scrolls.
    void expectPanelsReadable() {
        const std::vector<ui::UiWindow>& windows = mViewer->uiWindows();
        ASSERT_EQ(windows.size(), 3u);
        const float width = float(mViewer->swapchainExtent().width), height = float(mViewer->swapchainExtent().height);
        for (const ui::UiWindow& w : windows) {
            EXPECT_GE(w.rect.x, 0.0f) << w.name;
            EXPECT_GE(w.rect.y, 0.0f) << w.name;
            EXPECT_LE(w.rect.right(), width) << w.name;
            EXPECT_LE(w.rect.bottom(), height) << w.name;
            EXPECT_LE(w.contentWidth, w.roomWidth) << w.name << ": content wider than the window";
            if (w.contentHeight > w.roomHeight) {
                EXPECT_TRUE(w.scrollsY) << w.name << ": content below the window's edge";
            }
            if (w.name == "Frame stats") {
                EXPECT_LE(w.contentHeight, w.roomHeight) << "the frame stats are cut";
                EXPECT_FALSE(w.scrollsY);
            }
        }
        for (size_t a = 0; a < windows.size(); ++a)
            for (size_t b = a + 1; b < windows.size(); ++b) {
                const ui::PanelRect &p = windows[a].rect, &q = windows[b].rect;
                const bool apart = p.right() <= q.x || q.right() <= p.x || p.bottom() <= q.y || q.bottom() <= p.y;
                EXPECT_TRUE(apart) << windows[a].name << " overlaps " << windows[b].name;
            }
        // The scene keeps the part between the columns.
        const ui::PanelLayout& layout = mViewer->panelLayout();
        EXPECT_GE(layout.sceneRight - layout.sceneLeft, width / 3.0f);
    }

    test::TempDir mDir{"candela_viewer"};
    std::optional<ui::WindowSystem> mWindowSystem;  // outlives the device, which outlives the viewer
    std::optional<vk::Context> mContext;
    std::optional<Renderer> mRenderer;
    std::unique_ptr<ui::Viewer> mViewer;
    uint32_t mWidth = 480, mHeight = 300;
    std::set<options::Panel> mPanels = options::kPanelsOpenByDefault;
};

TEST_F(ViewerTest, RendersFramesWithTheUiAsAGraphPass) {
    open();
    frames(3);
    EXPECT_EQ(mViewer->framesRendered(), 3u);
    EXPECT_TRUE(ran("forward"));
    EXPECT_TRUE(skyDrawn());
    EXPECT_TRUE(ran("tonemap"));
    EXPECT_TRUE(ran("imgui"));
    // The imgui pass draws last, over the tonemapped image, into the swapchain image.
    const graph::RenderGraph& graph = mViewer->renderer().lastGraph();
    EXPECT_EQ(graph.declaration().passes[graph.compiled().order.back()].name, "imgui");
    // GPU times of completed frames reach the panels.
    EXPECT_FALSE(mViewer->renderer().completedPassTimes().empty());
}

TEST_F(ViewerTest, WithoutUiThereIsNoImGuiPass) {
    open(/*ui=*/false);
    frames(2);
    EXPECT_FALSE(mViewer->renderer().lastGraph().findPass("imgui").has_value());
}

TEST_F(ViewerTest, TogglingAPassCullsItInTheCompiledGraph) {
    open();
    frames(1);
    const Image before = screenshot("before.png");
    mViewer->setPassEnabled("skybox", false);  // what the render-graph panel's checkbox calls
    frames(1);
    ASSERT_NE(passInfo("skybox"), nullptr);
    EXPECT_EQ(passInfo("skybox")->cullReason, graph::CullReason::Disabled);
    EXPECT_TRUE(ran("forward"));
    const Image after = screenshot("after.png");
    // Without the skybox the background is black: the scene part of the window gets darker.
    ASSERT_EQ(before.width, after.width);
    const auto [x0, x1] = sceneColumns();
    EXPECT_LT(after.mean(x0, x1), before.mean(x0, x1) - 20.0);
    mViewer->setPassEnabled("skybox", true);
    frames(1);
    EXPECT_TRUE(skyDrawn());
}

TEST_F(ViewerTest, EditingAReflectedParameterChangesThePixels) {
    open(/*ui=*/true, /*environment=*/false);
    frames(2);
    shader::ParameterRegistry& registry = mViewer->renderer().parameters();
    const shader::ParameterRegistry::Block* tonemap = registry.find("tonemap", "Push");
    ASSERT_NE(tonemap, nullptr);
    const auto exposure = std::find_if(tonemap->members.begin(), tonemap->members.end(),
                                       [](const shader::BlockMember& m) { return m.name == "params.exposureEv"; });
    ASSERT_NE(exposure, tonemap->members.end()) << "the panel would not show the exposure";
    EXPECT_EQ(exposure->annotation.min, -10.0f);
    const Image before = screenshot("before.png");
    const float ev = 2.0f;
    registry.set("tonemap", "Push", *exposure, std::as_bytes(std::span(&ev, 1)));  // what the slider calls
    frames(1);
    const Image brighter = screenshot("brighter.png");
    const Box spheres = sceneMiddle();
    EXPECT_GT(brighter.mean(spheres), before.mean(spheres) + 5.0);

    // A light's intensity (a storage-buffer element) and a material's base colour go the same way.
    registry.reset("tonemap", "Push", "params.exposureEv");
    for (int i = 0; i < 4; ++i) {
        const std::string light = "Lights[" + std::to_string(i) + "]";
        const shader::ParameterRegistry::Block* block = registry.find("forward", light);
        ASSERT_NE(block, nullptr) << light;
        for (const shader::BlockMember& m : block->members)
            if (m.name == "intensity") {
                const float zero = 0.0f;
                registry.set("forward", light, m, std::as_bytes(std::span(&zero, 1)));
            }
    }
    frames(1);
    const Image unlit = screenshot("unlit.png");
    EXPECT_LT(unlit.mean(spheres), before.mean(spheres) - 5.0);
}

TEST_F(ViewerTest, SurvivesResizesAndAMinimize) {
    open();
    frames(1);
    for (int i = 0; i < 20; ++i) {
        const uint32_t width = 200 + 37 * uint32_t(i % 7), height = 150 + 23 * uint32_t(i % 5);
        mViewer->window().setSize(width, height);
        frames(2);  // the first may still see the old size: X delivers the resize asynchronously
        EXPECT_EQ(mViewer->swapchainExtent().width, mViewer->window().framebufferSize().width);
        EXPECT_EQ(mViewer->swapchainExtent().height, mViewer->window().framebufferSize().height);
    }
    EXPECT_GE(mViewer->swapchainRecreations(), 10u);
    // Once the size has settled, frames reuse the swapchain (recreation only on a change or an
    // out-of-date report: vk::swapchainNeedsRecreate).
    const uint32_t settled = mViewer->swapchainRecreations();
    frames(5);
    EXPECT_EQ(mViewer->swapchainRecreations(), settled);
    // Minimize: nothing is rendered, and frame() blocks on events rather than spinning.
    mViewer->window().iconify();
    mViewer->simulateMinimized(true);  // Xvfb has no window manager to honour the iconify
    const uint64_t rendered = mViewer->framesRendered();
    frames(3);
    EXPECT_EQ(mViewer->framesRendered(), rendered);
    EXPECT_EQ(mViewer->framesSkipped(), 3u);
    mViewer->simulateMinimized(false);
    mViewer->window().restore();
    frames(2);
    EXPECT_EQ(mViewer->framesRendered(), rendered + 2);
}

TEST_F(ViewerTest, ScreenshotHasTheSceneAndThePanel) {
    open();
    frames(1);
    const Image shot = screenshot("shot.png");
    ASSERT_EQ(shot.width, int(mViewer->swapchainExtent().width));
    ASSERT_EQ(shot.height, int(mViewer->swapchainExtent().height));
    // The panel columns (left and right) are the dark ImGui theme; the scene between them has the
    // bright sky.
    const auto [x0, x1] = sceneColumns();
    ASSERT_LT(x0, x1);
    EXPECT_LT(shot.mean(0, x0), 90.0);
    EXPECT_LT(shot.mean(x1, shot.width), 90.0);
    EXPECT_GT(shot.mean(x0, x1), 100.0);
}

// The panels at the window sizes people use, every panel open, with venice_sunset: readable (see
// expectPanelsReadable); the IBL table shown is the one measured on venice_sunset, and the
// tonemap's parameters say the sky is behind the scene.
class ViewerPanelsTest : public ViewerTest, public ::testing::WithParamInterface<std::pair<uint32_t, uint32_t>> {};

TEST_P(ViewerPanelsTest, EveryPanelIsReadable) {
    std::tie(mWidth, mHeight) = GetParam();
    for (const auto& [panel, name] : options::kPanelNames) mPanels.insert(panel);
    open();
    const std::filesystem::path hdr = ::candela::test::sharedAssets() / "environments" / "venice_sunset_1k.hdr";
    const bool venice = std::filesystem::exists(hdr);
    if (venice) {
        ASSERT_TRUE(mViewer->openFile(hdr)) << mViewer->status();
    }
    frames(4);  // ImGui sizes the frame stats from the previous frame's content
    ASSERT_EQ(mViewer->swapchainExtent().width, mWidth);
    ASSERT_EQ(mViewer->swapchainExtent().height, mHeight);
    expectPanelsReadable();
    EXPECT_EQ(mViewer->behindScene().rfind("the sky (", 0), 0u) << mViewer->behindScene();
    const std::vector<ui::IblReportTable>& reports = mViewer->iblReports();
    const size_t shown = size_t(mViewer->selectedIblReport());
    ASSERT_LT(shown, reports.size());
    const std::string environment = mViewer->environment()->source;
    EXPECT_EQ(ui::iblReportNote(reports, shown, environment), "");
    EXPECT_EQ(reports[shown].environment, venice ? "venice_sunset_1k" : "procedural sky");
    // A material with layers (long parameter names: iridescenceThicknessMaximum), a scene with
    // three animations, and one with transmission (the longest pass names in the render graph).
    for (const char* model : {"IridescenceSuzanne/glTF-Binary/IridescenceSuzanne.glb", "Fox/glTF-Binary/Fox.glb",
                              "TransmissionTest/glTF-Binary/TransmissionTest.glb"}) {
        const std::filesystem::path file = ::candela::test::sharedAssets() / "models" / model;
        if (!std::filesystem::exists(file)) continue;
        ASSERT_TRUE(mViewer->openFile(file)) << mViewer->status();
        frames(3);
        SCOPED_TRACE(model);
        expectPanelsReadable();
    }
    mViewer->useNoEnvironment();
    frames(2);
    EXPECT_EQ(mViewer->behindScene(), "the background colour");
    expectPanelsReadable();
}

INSTANTIATE_TEST_SUITE_P(WindowSizes, ViewerPanelsTest,
                         ::testing::Values(std::pair(1280u, 720u), std::pair(1920u, 1080u)),
                         [](const auto& size) { return std::to_string(size.param.first) + "x" + std::to_string(size.param.second); });

TEST_F(ViewerTest, DroppedFilesReplaceTheSceneOrTheEnvironment) {
    open(/*ui=*/true, /*environment=*/false);
    frames(1);
    EXPECT_FALSE(skyDrawn());
    // A bad file is reported in the UI and changes nothing.
    const std::filesystem::path bad = mDir / "broken.glb";
    { std::ofstream(bad) << "not a glb"; }
    EXPECT_FALSE(mViewer->openFile(bad));
    EXPECT_NE(mViewer->status().find("broken.glb"), std::string::npos);
    EXPECT_FALSE(mViewer->openFile(mDir / "notes.txt"));
    frames(1);

    const std::filesystem::path assets = ::candela::test::sharedAssets();
    const std::filesystem::path hdr = assets / "environments" / "venice_sunset_1k.hdr";
    const std::filesystem::path glb = assets / "models" / "BoxTextured" / "glTF-Binary" / "BoxTextured.glb";
    if (!std::filesystem::exists(hdr) || !std::filesystem::exists(glb)) GTEST_SKIP() << "shared assets not found";
    ASSERT_TRUE(mViewer->openFile(hdr)) << mViewer->status();
    frames(1);
    EXPECT_TRUE(mViewer->renderer().lastGraph().findPass("ibl_cubemap").has_value()) << "the precompute ran";
    EXPECT_TRUE(skyDrawn());
    frames(1);
    EXPECT_FALSE(mViewer->renderer().lastGraph().findPass("ibl_cubemap").has_value()) << "and only once";
    ASSERT_TRUE(mViewer->openFile(glb)) << mViewer->status();
    frames(1);
    EXPECT_EQ(mViewer->scene().source, glb.string());
    // The new scene was uploaded and is what the forward pass drew (not the old buffers).
    const std::vector<std::string> explained = mViewer->renderer().explain();
    EXPECT_TRUE(std::any_of(explained.begin(), explained.end(),
                            [](const std::string& line) { return line.rfind("forward: 1 draws;", 0) == 0; }));
}

TEST_F(ViewerTest, EnvironmentPanelActions) {
    open(/*ui=*/true, /*environment=*/false);
    frames(1);
    mViewer->useProceduralSky();
    frames(1);
    EXPECT_TRUE(mViewer->renderer().lastGraph().findPass("ibl_cubemap").has_value());
    EXPECT_GT(mViewer->renderer().lastPrecompute().frameMs, 0.0);
    EXPECT_GT(mViewer->renderer().lastPrecompute().gpuMs, 0.0);
    EXPECT_TRUE(skyDrawn());
    frames(1);
    EXPECT_FALSE(mViewer->renderer().lastGraph().findPass("ibl_cubemap").has_value());
    // A pass that cannot be switched off (its box is greyed out) runs whatever the toggle says.
    mViewer->setPassEnabled("ibl_prefilter", false);
    mViewer->recomputeIbl();  // the recompute button, same settings
    frames(1);
    EXPECT_TRUE(mViewer->renderer().lastGraph().findPass("ibl_cubemap").has_value());
    EXPECT_TRUE(ran("ibl_prefilter"));
    mViewer->setPassEnabled("ibl_prefilter", true);
    mViewer->settings().iblQuality.prefilterSamples = 16;  // a setting picked from the table
    frames(1);
    EXPECT_TRUE(mViewer->renderer().lastGraph().findPass("ibl_prefilter").has_value());
    EXPECT_FALSE(mViewer->iblReports().empty());
    mViewer->useNoEnvironment();
    frames(1);
    EXPECT_FALSE(skyDrawn());
    EXPECT_FALSE(mViewer->renderer().lastGraph().findPass("ibl_prefilter").has_value());
}

TEST_F(ViewerTest, ChoosingAMaterialVariantChangesTheDrawnMaterial) {
    // KHR_materials_variants: the shoe with its three variants; a choice re-uploads the scene and
    // the frame draws the variant's material (the picked mesh's material says which).
    open(/*ui=*/true, /*environment=*/false);
    const std::filesystem::path shoe =
        ::candela::test::sharedAssets() / "models/MaterialsVariantsShoe/glTF/MaterialsVariantsShoe.gltf";
    if (!std::filesystem::exists(shoe)) GTEST_SKIP() << "shared assets not found";
    ASSERT_TRUE(mViewer->openFile(shoe)) << mViewer->status();
    frames(1);
    ASSERT_EQ(mViewer->scene().variants.size(), 3u);
    const VkExtent2D extent = mViewer->swapchainExtent();
    const auto [x0, x1] = sceneColumns();
    const glm::vec2 centre((x0 + x1) / 2.0f, extent.height / 2.0f);  // between the panels, on the shoe
    ASSERT_TRUE(mViewer->pickMaterial(centre));
    EXPECT_EQ(mViewer->selectedMaterial(), 0u);  // the file's default
    const Image before = screenshot("default.png");
    mViewer->selectVariant(2u);  // "street": material 2
    frames(1);
    EXPECT_EQ(mViewer->variant(), std::optional<uint32_t>(2u));
    ASSERT_TRUE(mViewer->pickMaterial(centre));
    EXPECT_EQ(mViewer->selectedMaterial(), 2u);
    const Image after = screenshot("street.png");
    EXPECT_NE(before.rgba, after.rgba);
    mViewer->selectVariant(std::nullopt);
    frames(1);
    ASSERT_TRUE(mViewer->pickMaterial(centre));
    EXPECT_EQ(mViewer->selectedMaterial(), 0u);
}

TEST_F(ViewerTest, ClickingAMeshSelectsItsMaterial) {
    open(/*ui=*/false);
    frames(1);
    const VkExtent2D extent = mViewer->swapchainExtent();
    // The middle sphere of the 7×7 grid is under the centre of the window.
    ASSERT_TRUE(mViewer->pickMaterial({extent.width / 2.0f, extent.height / 2.0f}));
    EXPECT_EQ(mViewer->selectedMaterial(), 24u);
    EXPECT_FALSE(mViewer->pickMaterial({2.0f, 2.0f}));  // the corner shows the background
}

// Rewrites `file` with `from` replaced by `to`; its modification time changes (on file systems
// whose clock is too coarse to show it, it is moved 1 ms on).
void editFile(const std::filesystem::path& file, const std::string& from, const std::string& to) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    const auto before = std::filesystem::last_write_time(file);
    std::ofstream(file, std::ios::trunc) << text;
    if (std::filesystem::last_write_time(file) == before)
        std::filesystem::last_write_time(file, before + std::chrono::milliseconds(1));
}

TEST_F(ViewerTest, HotReloadRebuildsPipelinesAndKeepsTheOldOnesOnErrors) {
    // A copy of the shaders, so the test never touches the source tree.
    const std::filesystem::path shaders = mDir / "shaders";
    std::filesystem::copy(CANDELA_SHADER_SOURCE_DIR, shaders, std::filesystem::copy_options::recursive);
    open(/*ui=*/true, /*environment=*/false, shaders);
    ASSERT_TRUE(mViewer->hotReload().enabled());
    frames(1);
    const Image before = screenshot("before.png");
    const Box spheres = sceneMiddle();
    const int middle = (spheres.x0 + spheres.x1) / 2;

    // The tonemap writes pure red: the scene between the panels turns red.
    editFile(shaders / "tonemap.frag.glsl", "outColor = vec4(display, alpha);", "outColor = vec4(1.0, 0.0, 0.0, 1.0);");
    frames(1);
    EXPECT_TRUE(mViewer->hotReload().errors().empty());
    EXPECT_GT(mViewer->lastReloadLatencyMs(), -1.0);  // from the save to the GPU finishing the frame
    const Image red = screenshot("red.png");
    const size_t centre = (size_t(red.height / 2) * red.width + middle) * 4;
    EXPECT_EQ(red.rgba[centre + 0], 255);
    EXPECT_EQ(red.rgba[centre + 1], 0);

    // A compile error is reported with file and line, by each shader made from the file
    // (tonemap.frag and tonemap_sky.frag); the red pipeline keeps running.
    editFile(shaders / "tonemap.frag.glsl", "outColor = vec4(1.0, 0.0, 0.0, 1.0);", "outColor = vec4(1.0, 0.0, 0.0, 1.0) + undefinedThing;");
    frames(1);
    ASSERT_EQ(mViewer->hotReload().errors().size(), 2u);
    const std::string error = mViewer->hotReload().errors()[0];
    EXPECT_NE(error.find("tonemap.frag.glsl:"), std::string::npos) << error;
    EXPECT_NE(error.find("undefinedThing"), std::string::npos) << error;
    const Image stillRed = screenshot("still_red.png");
    EXPECT_EQ(stillRed.rgba[centre + 0], 255);
    EXPECT_EQ(stillRed.rgba[centre + 1], 0);

    // A changed descriptor layout is refused too (the sets would not match).
    editFile(shaders / "tonemap.frag.glsl", " + undefinedThing;", ";");
    editFile(shaders / "tonemap.frag.glsl", "layout(set = 0, binding = 0) uniform sampler2D hdrImage;",
             "layout(set = 0, binding = 0) uniform sampler2D hdrImage;\nlayout(set = 0, binding = 5) uniform sampler2D extra;");
    frames(1);
    ASSERT_EQ(mViewer->hotReload().errors().size(), 2u);  // tonemap.frag and tonemap_sky.frag
    for (const std::string& e : mViewer->hotReload().errors()) EXPECT_NE(e.find("descriptor bindings changed"), std::string::npos) << e;

    // A header edit reaches every shader that includes it.
    editFile(shaders / "tonemap.frag.glsl", "\nlayout(set = 0, binding = 5) uniform sampler2D extra;", "");
    editFile(shaders / "tonemap.frag.glsl", "outColor = vec4(1.0, 0.0, 0.0, 1.0);", "outColor = vec4(display, alpha);");
    frames(1);
    EXPECT_TRUE(mViewer->hotReload().errors().empty());
    const Image restored = screenshot("restored.png");
    EXPECT_NEAR(restored.mean(spheres), before.mean(spheres), 1.0);
    editFile(shaders / "shared" / "tonemap.h", "CANDELA_FN vec3 applyTonemap(vec3 color, uint op) {",
             "CANDELA_FN vec3 applyTonemap(vec3 color, uint op) {\n    return vec3(0.0f, 1.0f, 0.0f);");
    frames(1);
    EXPECT_TRUE(mViewer->hotReload().errors().empty());
    const Image green = screenshot("green.png");  // spheres green on the grey background
    EXPECT_GT(green.mean(spheres, 1), before.mean(spheres, 1) + 30.0);
    EXPECT_LT(green.mean(spheres, 0), before.mean(spheres, 0) - 10.0);
}

// The visibility path's compute shading reloads as the fragment programs do: an edit of
// visibility_shade.comp.glsl rebuilds its pipelines, and a compile error keeps the running ones.
TEST_F(ViewerTest, HotReloadRebuildsTheComputeShadingOfTheVisibilityPath) {
    const std::filesystem::path shaders = mDir / "shaders";
    std::filesystem::copy(CANDELA_SHADER_SOURCE_DIR, shaders, std::filesystem::copy_options::recursive);
    open(/*ui=*/false, /*environment=*/false, shaders, options::ShadingPath::Visibility);
    if (!mViewer->context().choices().visibilityUnsupported.empty())
        GTEST_SKIP() << mViewer->context().choices().visibilityUnsupported;
    ASSERT_TRUE(mViewer->hotReload().enabled());
    frames(1);
    ASSERT_TRUE(ran("visibility_shade"));
    const Image before = screenshot("before.png");
    // The middle sphere of the 7×7 grid is under the centre of the window.
    const size_t centre = (size_t(before.height / 2) * before.width + before.width / 2) * 4;
    ASSERT_LT(before.rgba[centre + 2], 200);

    const std::string store = "imageStore(shaded, pixel, shadeVisible(id.x - 1u, id.y, pixel, size));";
    // Blue, dark enough that the tone mapping keeps it saturated; the shading still runs (its
    // alpha is kept), so the edit changes the colour and nothing else.
    const std::string blue =
        "imageStore(shaded, pixel, shadeVisible(id.x - 1u, id.y, pixel, size) * vec4(0.0, 0.0, 0.0, 1.0) + vec4(0.0, 0.0, 0.5, 0.0));";
    editFile(shaders / "visibility_shade.comp.glsl", store, blue);
    frames(1);
    EXPECT_TRUE(mViewer->hotReload().errors().empty());
    const Image shadedBlue = screenshot("blue.png");
    EXPECT_LT(shadedBlue.rgba[centre + 0], 10);
    EXPECT_LT(shadedBlue.rgba[centre + 1], 10);
    EXPECT_GT(shadedBlue.rgba[centre + 2], 150);
    EXPECT_EQ(shadedBlue.rgba[2 * 4 + 2], before.rgba[2 * 4 + 2]);  // the background is not shaded

    // Every shading function dead (a constant stored): the module the validation layer
    // specializes stays valid (its spec-constant folding once made it invalid: VUID 06719,
    // docs/shading-paths.md).
    const std::string green = "imageStore(shaded, pixel, vec4(0.0, 0.5, 0.0, 1.0));";
    editFile(shaders / "visibility_shade.comp.glsl", blue, green);
    frames(1);
    EXPECT_TRUE(mViewer->hotReload().errors().empty());
    const Image shadedGreen = screenshot("green.png");
    EXPECT_LT(shadedGreen.rgba[centre + 0], 10);
    EXPECT_GT(shadedGreen.rgba[centre + 1], 100);
    EXPECT_LT(shadedGreen.rgba[centre + 2], 10);

    // A compile error names the file and line in every shader made from it; green stays.
    editFile(shaders / "visibility_shade.comp.glsl", green, "imageStore(shaded, pixel, undefinedThing);");
    frames(1);
    ASSERT_FALSE(mViewer->hotReload().errors().empty());
    const std::string error = mViewer->hotReload().errors()[0];
    EXPECT_NE(error.find("visibility_shade.comp.glsl:"), std::string::npos) << error;
    EXPECT_NE(error.find("undefinedThing"), std::string::npos) << error;
    EXPECT_EQ(screenshot("still_green.png").rgba, shadedGreen.rgba);

    editFile(shaders / "visibility_shade.comp.glsl", "imageStore(shaded, pixel, undefinedThing);", store);
    frames(1);
    EXPECT_TRUE(mViewer->hotReload().errors().empty());
    EXPECT_EQ(screenshot("restored.png").rgba, before.rgba);
}

}  // namespace
}  // namespace candela
