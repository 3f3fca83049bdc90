// Animated scenes on the GPU (lavapipe, validation with synchronization checks on): the pose
// reaches the forward pass through the graph, a static scene's graph is exactly what it was
// before animation existed, and the posed path draws what the static path draws for the same
// matrices.
#include "gpu_test.h"

#include "graph/graph_export.h"
#include "renderer.h"
#include "scene/gltf_loader.h"
#include "scene/scene_pose.h"

#include <filesystem>

namespace candela::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 120;

std::filesystem::path model(const char* path) {
    return std::filesystem::path(CANDELA_SHARED_ASSETS) / "models" / path;
}

#define LOAD_OR_SKIP(var, path)                                                         \
    if (!std::filesystem::exists(model(path))) GTEST_SKIP() << "shared asset missing"; \
    const scene::Scene var = scene::loadGltf(model(path))

RenderSettings settingsFor(const scene::Scene& scene, const scene::ScenePose* pose) {
    RenderSettings settings{.width = kWidth, .height = kHeight, .scene = &scene, .pose = pose};
    // A fixed camera: framing would follow the animation's bounds, which the static scene has not.
    settings.camera.orbit = glm::vec3(30.0f, 70.0f, 5.0f);
    settings.camera.target = glm::vec3(0.0f, 1.3f, 0.0f);
    return settings;
}

std::string graphJson(const Renderer& renderer) {
    return graph::exportJson(renderer.lastGraph().declaration(), renderer.lastGraph().compiled(), nullptr);
}

size_t differingPixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); i += 4)
        n += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2] || a[i + 3] != b[i + 3];
    return n;
}

TEST_F(GpuTest, StaticSceneGraphIsTheSameWithOrWithoutAPose) {
    LOAD_OR_SKIP(box, "Box/glTF-Binary/Box.glb");
    LOAD_OR_SKIP(animated, "BoxAnimated/glTF-Binary/BoxAnimated.glb");
    for (const scene::Scene* s : {&box, &animated}) {
        // Box has no animations; BoxAnimated is asked for none: both draw the rest pose, through
        // the static draw buffer, with the very graph (passes, resources, barriers) of no pose.
        const std::vector<std::string> none{"none"};
        const scene::ScenePose pose(*s, scene::selectAnimations(*s, none));
        Renderer renderer(context());
        const CapturedFrame without = renderer.capture(settingsFor(*s, nullptr));
        const std::string withoutGraph = graphJson(renderer);
        const CapturedFrame with = renderer.capture(settingsFor(*s, &pose));
        EXPECT_EQ(graphJson(renderer), withoutGraph) << s->source;
        EXPECT_EQ(with.rgba8, without.rgba8) << s->source;
        EXPECT_EQ(withoutGraph.find("posed_draws"), std::string::npos);
        for (const std::string& line : renderer.explain()) EXPECT_EQ(line.find("animated"), std::string::npos) << line;
    }
}

TEST_F(GpuTest, PoseReachesTheForwardPassThroughTheGraph) {
    LOAD_OR_SKIP(scene, "BoxAnimated/glTF-Binary/BoxAnimated.glb");
    scene::ScenePose pose(scene, scene::selectAnimations(scene, {}));
    Renderer renderer(context());
    pose.evaluate(0.0);
    const CapturedFrame start = renderer.capture(settingsFor(scene, &pose));
    // The forward pass reads the imported per-frame draw buffer in its vertex and fragment stages.
    const graph::GraphDecl& decl = renderer.lastGraph().declaration();
    const auto posed = std::find_if(decl.resources.begin(), decl.resources.end(),
                                    [](const graph::ResourceDecl& r) { return r.name == "posed_draws"; });
    ASSERT_NE(posed, decl.resources.end());
    EXPECT_TRUE(posed->imported);
    const graph::PassDecl& forward = decl.passes[*renderer.lastGraph().findPass("forward")];
    EXPECT_TRUE(std::any_of(forward.reads.begin(), forward.reads.end(), [&](const graph::AccessDecl& a) {
        return a.resource == uint32_t(posed - decl.resources.begin()) && a.usage == graph::Usage::StorageRead;
    }));
    bool explained = false;
    for (const std::string& line : renderer.explain()) explained |= line.rfind("animated:", 0) == 0;
    EXPECT_TRUE(explained);

    // Another time gives another image; going back gives the first again, frames in flight or not.
    pose.evaluate(1.875);
    const CapturedFrame later = renderer.capture(settingsFor(scene, &pose));
    EXPECT_GT(differingPixels(start.rgba8, later.rgba8), size_t(kWidth * kHeight / 50));
    pose.evaluate(1.0);
    renderer.renderFrame(settingsFor(scene, &pose));
    pose.evaluate(0.0);
    EXPECT_EQ(renderer.capture(settingsFor(scene, &pose)).rgba8, start.rgba8);
}

TEST_F(GpuTest, PosedDrawsMatchTheStaticPathWithTheSameMatrices) {
    LOAD_OR_SKIP(scene, "BoxAnimated/glTF-Binary/BoxAnimated.glb");
    scene::ScenePose pose(scene, scene::selectAnimations(scene, {}));
    pose.evaluate(1.875);
    // The same scene with the pose's draws baked in as its rest pose.
    scene::Scene frozen = scene;
    frozen.draws = pose.draws();
    frozen.animations.clear();
    Renderer renderer(context());
    const CapturedFrame animated = renderer.capture(settingsFor(scene, &pose));
    Renderer other(context());
    const CapturedFrame baked = other.capture(settingsFor(frozen, nullptr));
    EXPECT_EQ(animated.rgba8, baked.rgba8);
}

}  // namespace
}  // namespace candela::test
