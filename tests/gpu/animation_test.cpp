// Animated scenes on the GPU (lavapipe, validation with synchronization checks on): the pose
// reaches the forward pass through the graph, a static scene's graph is exactly what it was
// before animation existed, and the posed path draws what the static path draws for the same
// matrices.
#include "gpu_test.h"
#include "test_paths.h"

#include "graph/graph_export.h"
#include "graph_runner.h"
#include "passes/deform/skin_morph_pass.h"
#include "pose/skinning.h"
#include "render/renderer.h"
#include "assets/gltf_loader.h"
#include "pose/scene_pose.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <tuple>

namespace candela::test::animation_test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 120;

std::filesystem::path model(const char* path) {
    return ::candela::test::sharedAssets() / "models" / path;
}

#define LOAD_OR_SKIP(var, path)                                                         \
    if (!std::filesystem::exists(model(path))) GTEST_SKIP() << "shared asset missing"; \
    const scene::Scene var = assets::loadGltf(model(path))

RenderSettings settingsFor(const scene::Scene& scene, const pose::ScenePose* pose) {
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
        const pose::ScenePose pose(*s, pose::selectAnimations(*s, none));
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
    pose::ScenePose pose(scene, pose::selectAnimations(scene, {}));
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
    pose::ScenePose pose(scene, pose::selectAnimations(scene, {}));
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
}  // namespace candela::test::animation_test

namespace candela::test::animation_test {
namespace {

// The skin_morph pass's vertices for `work`, read back; the pass split by `limits` when given.
std::vector<scene::Vertex> deformOnGpu(vk::Context& context, const gpu_scene::GpuScene& gpuScene,
                                       const passes::SkinMorphFrame& work,
                                       const std::optional<passes::SkinMorphLimits>& limits = std::nullopt) {
    GraphRunner runner(context);
    graph::RenderGraph graph;
    const size_t frameBytes = std::max<size_t>(work.frameData.size() * sizeof(uint32_t), 16);
    vk::Buffer frameData(context, vk::BufferDesc{.size = frameBytes, .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                 .memory = vk::MemoryUsage::Upload, .name = "skin_morph_frame"});
    std::memset(frameData.mapped(), 0, frameBytes);
    if (!work.frameData.empty()) std::memcpy(frameData.mapped(), work.frameData.data(), work.frameData.size() * sizeof(uint32_t));
    frameData.flush();
    const graph::BufferId frameId = graph.importBuffer("skin_morph_frame", {.size = frameBytes}, graph::ResourceState{});
    runner.bind(frameId, frameData.handle());
    passes::SkinMorphPass pass(context, limits);
    const graph::BufferId deformed =
        pass.add(graph, {.scene = &gpuScene, .jobs = work.jobs, .vertexCount = work.vertexCount, .frameData = frameId});
    const VkDeviceSize bytes = VkDeviceSize(work.vertexCount) * sizeof(scene::Vertex);
    const graph::BufferId readback = runner.readbackBuffer(graph, "readback", bytes);
    struct Copy {
        graph::BufferId from, to;
    };
    graph.addPass<Copy>(
        "copy", graph::PassType::Transfer,
        [&](graph::PassBuilder& b, Copy& c) {
            c.from = b.read(deformed, graph::Usage::TransferSrc);
            c.to = b.write(readback, graph::Usage::TransferDst, graph::WriteMode::Discard);
        },
        [bytes](const Copy& c, graph::PassContext& ctx) {
            const VkBufferCopy region{.size = bytes};
            vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(c.from), ctx.buffer(c.to), 1, &region);
        });
    runner.run(graph);
    return runner.read<scene::Vertex>(readback);
}

// The skin_morph pass's vertices read back, against the double-precision CPU reference
// (pose::deformVertices) of the same pose: within 1e-5 relative to the model's size.
void expectGpuDeformationMatchesReference(vk::Context& context, const char* path, const std::vector<std::string>& animations,
                                          double time) {
    if (!std::filesystem::exists(model(path))) GTEST_SKIP() << "shared asset missing";
    const scene::Scene scene = assets::loadGltf(model(path));
    pose::ScenePose pose(scene, pose::selectAnimations(scene, animations));
    pose.evaluate(time);
    const gpu_scene::GpuScene gpuScene(context, scene);
    const passes::SkinMorphFrame work = passes::skinMorphFrame(gpuScene, pose);
    ASSERT_FALSE(work.jobs.empty());
    const std::vector<scene::Vertex> gpu = deformOnGpu(context, gpuScene, work);

    const float size = glm::length(pose.bounds().max - pose.bounds().min);
    size_t compared = 0;
    double worstPosition = 0.0, worstNormal = 0.0, moved = 0.0;
    for (uint32_t d : pose.deformedDraws()) {
        const scene::Draw& draw = pose.draws()[d];
        static const std::vector<glm::dmat4> none;
        const std::vector<scene::Vertex> reference =
            pose::deformVertices(scene, draw, pose.weights(draw), draw.skin >= 0 ? pose.jointMatrices(uint32_t(draw.skin)) : none);
        const scene::Deformation& deformation = scene.deformations[size_t(draw.deformation)];
        for (uint32_t v = 0; v < reference.size(); ++v) {
            const scene::Vertex& g = gpu[size_t(int64_t(deformation.firstVertex) + work.vertexOffset[d] + v)];
            const scene::Vertex& r = reference[v];
            const glm::vec3 rest = glm::vec3(draw.world * glm::vec4(scene.vertices[deformation.firstVertex + v].position, 1.0f));
            moved = std::max(moved, double(glm::length(glm::vec3(draw.world * glm::vec4(g.position, 1.0f)) - rest)));
            worstPosition = std::max(worstPosition, double(glm::length(g.position - r.position)) / size);
            if (glm::length(r.normal) > 0.5f) worstNormal = std::max(worstNormal, double(glm::length(g.normal - r.normal)));
            ASSERT_NEAR(g.uv0.x, r.uv0.x, 1e-5f);
            ASSERT_NEAR(g.color.a, r.color.a, 1e-5f);
            ++compared;
        }
    }
    EXPECT_GT(compared, 0u);
    EXPECT_LT(worstPosition, 1e-5) << path;
    EXPECT_LT(worstNormal, 1e-5) << path;
    // The pose does move the vertices: the comparison is not of two copies of the rest pose.
    EXPECT_GT(moved / size, 1e-3) << path;
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worstPosition);
    ::testing::Test::RecordProperty(std::string("worstPositionError_") + path, text);
}

TEST_F(GpuTest, SkinnedVerticesMatchTheCpuReferenceFox) {
    expectGpuDeformationMatchesReference(context(), "Fox/glTF-Binary/Fox.glb", {"1"}, 0.37);
}
TEST_F(GpuTest, SkinnedVerticesMatchTheCpuReferenceCesiumMan) {
    expectGpuDeformationMatchesReference(context(), "CesiumMan/glTF-Binary/CesiumMan.glb", {}, 1.1);
}
TEST_F(GpuTest, MorphedVerticesMatchTheCpuReference) {
    expectGpuDeformationMatchesReference(context(), "MorphStressTest/glTF-Binary/MorphStressTest.glb", {"all"}, 0.6);
    expectGpuDeformationMatchesReference(context(), "AnimatedMorphCube/glTF-Binary/AnimatedMorphCube.glb", {}, 1.6);
}

// A device with a small maxStorageBufferRange, the largest offset alignment and few groups in X:
// every draw is split into runs whose bound ranges start mid-element, dispatched as 2-D grids with a
// partial last row. The result is bit for bit the one of a single dispatch per draw: every vertex
// is written, with the values of its own source and records.
TEST_F(GpuTest, SkinMorphSplitIntoSmallRangesAndTwoDimensionalGridsIsExact) {
    // The ranges: Fox's records are 32 bytes (227 vertices a run, 4 groups), MorphStressTest's 640 (409 a run, 7 groups).
    for (const auto& [path, animations, time, range] :
         {std::tuple<const char*, std::vector<std::string>, double, uint64_t>{"Fox/glTF-Binary/Fox.glb", {"1"}, 0.37, 16 * 1024},
          {"MorphStressTest/glTF-Binary/MorphStressTest.glb", {"all"}, 0.6, 256 * 1024}}) {
        if (!std::filesystem::exists(model(path))) GTEST_SKIP() << "shared asset missing";
        const scene::Scene scene = assets::loadGltf(model(path));
        pose::ScenePose pose(scene, pose::selectAnimations(scene, animations));
        pose.evaluate(time);
        const gpu_scene::GpuScene gpuScene(context(), scene);
        const passes::SkinMorphFrame work = passes::skinMorphFrame(gpuScene, pose);
        const passes::SkinMorphLimits small{.maxStorageBufferRange = range, .storageOffsetAlignment = 256, .maxGroups = {3, 65535}};
        size_t dispatches = 0, grids = 0;
        for (const passes::SkinMorphJob& job : work.jobs)
            for (const passes::SkinMorphDispatch& d : passes::skinMorphDispatches(job, small)) {
                ++dispatches;
                grids += d.groups.y > 1;
            }
        EXPECT_GT(dispatches, work.jobs.size()) << path;
        EXPECT_GT(grids, 0u) << path;
        const std::vector<scene::Vertex> whole = deformOnGpu(context(), gpuScene, work);
        const std::vector<scene::Vertex> split = deformOnGpu(context(), gpuScene, work, small);
        ASSERT_EQ(whole.size(), split.size());
        EXPECT_EQ(std::memcmp(whole.data(), split.data(), whole.size() * sizeof(scene::Vertex)), 0) << path;
    }
}

}  // namespace
}  // namespace candela::test::animation_test

namespace candela::test::animation_test {
namespace {

TEST_F(GpuTest, LightsOnAnimatedNodesMoveWithThePose) {
    LOAD_OR_SKIP(box, "Box/glTF-Binary/Box.glb");
    // A point light on a node of its own, carried from left to right in one second.
    scene::Scene scene = box;
    scene.nodes.push_back({.name = "lamp", .source = -1, .parent = -1});
    scene.lights.push_back({.type = scene::LightType::Point, .intensity = 20.0f, .node = int32_t(scene.nodes.size() - 1)});
    animation::Animation carry{.name = "carry", .duration = 1.0};
    carry.samplers.push_back({.times = {0, 1}, .values = {-2, 1, 2, 2, 1, 2}, .width = 3});
    carry.channels.push_back({.sampler = 0, .node = uint32_t(scene.nodes.size() - 1), .property = animation::AnimatedProperty::Translation});
    scene.animations.push_back(carry);
    pose::ScenePose pose(scene, {0});
    Renderer renderer(context());
    pose.evaluate(0.0);
    const CapturedFrame left = renderer.capture(settingsFor(scene, &pose));
    pose.evaluate(0.999, /*loop=*/false);
    const CapturedFrame right = renderer.capture(settingsFor(scene, &pose));
    EXPECT_GT(differingPixels(left.rgba8, right.rgba8), size_t(kWidth * kHeight / 100));
    EXPECT_NE(renderer.lastGraph().declaration().resources.end(),
              std::find_if(renderer.lastGraph().declaration().resources.begin(), renderer.lastGraph().declaration().resources.end(),
                           [](const graph::ResourceDecl& r) { return r.name == "posed_lights"; }));
    // The same light placed there in a static scene draws the same image.
    scene::Scene frozen = scene;
    frozen.animations.clear();
    frozen.lights.back().position = pose.lights().back().position;
    Renderer other(context());
    EXPECT_EQ(other.capture(settingsFor(frozen, nullptr)).rgba8, right.rgba8);
}

}  // namespace
}  // namespace candela::test::animation_test
