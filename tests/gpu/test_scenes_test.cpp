// Candela's own test scenes (assets/test-scenes, tools/make-test-scenes.py) load without a warning —
// every extension they use is read — and draw something; the animated ones change over time: the
// blinking sphere of NodeVisibility and its light are gone at 1.5 s, the pointer animations move.
#include "gpu_test.h"
#include "test_paths.h"

#include "assets/gltf_loader.h"
#include "pose/scene_pose.h"
#include "render/renderer.h"

#include <filesystem>

namespace candela::test {
namespace {

namespace fs = std::filesystem;

struct Frames {
    std::vector<uint8_t> early, late;
};

// The scene at `early` and `late` seconds (its first animation playing), 240 × 160 over a black background.
Frames render(vk::Context& context, const std::string& name, double early, double late) {
    const scene::Scene scene = assets::loadGltf(::candela::test::testScenes() / (name + ".glb"));
    EXPECT_TRUE(scene.report.warnings.empty()) << name << ": " << scene.report.warnings.front();
    pose::ScenePose pose(scene, pose::selectAnimations(scene, {}));
    Renderer renderer(context);
    RenderSettings settings{.width = 240, .height = 160, .scene = &scene, .pose = &pose};
    settings.tonemap.background = glm::vec3(0.0f);
    Frames frames;
    pose.evaluate(early);
    frames.early = renderer.capture(settings).rgba8;
    pose.evaluate(late);
    frames.late = renderer.capture(settings).rgba8;
    return frames;
}

// Pixels brighter than black in some channel.
size_t lit(const std::vector<uint8_t>& rgba) {
    size_t count = 0;
    for (size_t i = 0; i < rgba.size(); i += 4) count += (rgba[i] | rgba[i + 1] | rgba[i + 2]) > 8;
    return count;
}

size_t differing(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t count = 0;
    for (size_t i = 0; i < a.size(); i += 4) count += std::abs(int(a[i]) - int(b[i])) + std::abs(int(a[i + 1]) - int(b[i + 1])) +
                                                      std::abs(int(a[i + 2]) - int(b[i + 2])) > 6;
    return count;
}

class TestScene : public GpuTest, public testing::WithParamInterface<const char*> {};

TEST_P(TestScene, LoadsQuietlyAndDraws) {
    const Frames frames = render(context(), GetParam(), 0.5, 1.5);
    EXPECT_GT(lit(frames.early), frames.early.size() / 4 / 10) << "something covers a tenth of the frame";
}

INSTANTIATE_TEST_SUITE_P(Scenes, TestScene,
                         testing::Values("DispersionSweep", "DiffuseTransmissionSweep", "AnimationPointerSweep", "NodeVisibility"));

TEST_F(GpuTest, NodeVisibilitySceneHidesTheBlinkingSphereAndItsLight) {
    const Frames frames = render(context(), "NodeVisibility", 0.5, 1.5);
    // At 0.5 s the red sphere and its red light are there; at 1.5 s both are hidden: the sphere's
    // pixels and the red glow on the backdrop go.
    EXPECT_GT(differing(frames.early, frames.late), frames.early.size() / 4 / 50);
    EXPECT_GT(lit(frames.early), lit(frames.late));
}

TEST_F(GpuTest, AnimationPointerSceneChangesOverTime) {
    const Frames frames = render(context(), "AnimationPointerSweep", 0.0, 2.0);
    EXPECT_GT(differing(frames.early, frames.late), frames.early.size() / 4 / 50);
}

}  // namespace
}  // namespace candela::test
