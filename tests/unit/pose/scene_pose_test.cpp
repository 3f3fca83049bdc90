// Animations read by the loader and played by ScenePose: the sample models' channels at known
// times against the keyframe values in their files, animation selection, looping, the rest pose
// of what no animation moves, and small hand-built files for what the samples do not cover.
#include "gltf_test_util.h"

#include "pose/scene_pose.h"
#include "pose/picking.h"
#include "pose/shown_points.h"
#include "pose/skinning.h"

#include <glm/gtc/matrix_transform.hpp>

namespace candela::pose::test::scene_pose_test {
namespace {

void expectVec(const glm::vec3& actual, const glm::vec3& expected, float eps = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, eps);
    EXPECT_NEAR(actual.y, expected.y, eps);
    EXPECT_NEAR(actual.z, expected.z, eps);
}

// The draw placed by glTF node `source`.
uint32_t drawOf(const scene::Scene& scene, int source) {
    for (uint32_t i = 0; i < scene.draws.size(); ++i)
        if (scene.nodes[size_t(scene.draws[i].node)].source == source) return i;
    ADD_FAILURE() << "no draw from node " << source;
    return 0;
}

TEST(ScenePose, BoxAnimatedFollowsItsKeys) {
    REQUIRE_MODELS();
    // Node 0 (root) translates: (0,0,0) at 0 s, (0,2.52,0) from 1.25 s to 2.5 s, back at 3.708 s.
    // Node 2 (a mesh, under node 1) rotates from the identity at 1.25 s to 180° about +X at 2.5 s.
    // Node 3 (the other mesh) is static.
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "BoxAnimated/glTF-Binary/BoxAnimated.glb");
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.animations.size(), 1u);
    EXPECT_EQ(scene.animations[0].channels.size(), 2u);
    EXPECT_NEAR(scene.animations[0].duration, 3.70833, 1e-5);
    const uint32_t moving = drawOf(scene, 2), still = drawOf(scene, 3);

    ScenePose pose(scene, selectAnimations(scene, {}));
    ASSERT_TRUE(pose.animated());
    EXPECT_EQ(pose.animatedDraws(), std::vector<uint32_t>{moving});
    pose.evaluate(0.625);  // halfway up, before the rotation's first key (clamped: identity)
    expectVec(pose.draws()[moving].world[3], {0, 1.26f, 0});
    expectVec(pose.draws()[moving].world[1], {0, 1, 0});
    pose.evaluate(1.875);  // at the top, halfway through the half turn: +Y turned onto +Z
    expectVec(pose.draws()[moving].world[3], {0, 2.52f, 0});
    expectVec(pose.draws()[moving].world[1], {0, 0, 1});
    expectVec(pose.draws()[moving].world[2], {0, -1, 0});
    EXPECT_EQ(pose.draws()[still].world, scene.draws[still].world);
    expectVec(pose.draws()[moving].bounds.max, {0.33504f, 2.52f + 0.33504f, 0.5f});  // the box is 1 tall, 0.67 deep

    // Looping wraps by the animation's duration; without it the last key holds.
    pose.evaluate(3.70833 + 0.625);
    expectVec(pose.draws()[moving].world[3], {0, 1.26f, 0}, 1e-4f);
    pose.evaluate(100.0, /*loop=*/false);
    expectVec(pose.draws()[moving].world[3], {0, 0, 0});
    // The points over the whole animation reach the top of the climb, where the box, turning, stands
    // highest at atan(0.335 / 0.5) = 34° between the keys (0° and 180°): 2.52 + √(0.5² + 0.335²);
    // those of one pose, only its own.
    scene::Aabb all;
    shownPoints(scene, &pose, animationTimes(pose, 1024), /*loop=*/false)([&](std::span<const glm::vec3> batch) {
        for (const glm::vec3& p : batch) all.extend(p);
    });
    EXPECT_NEAR(all.max.y, 2.52f + std::sqrt(0.25f + 0.33504f * 0.33504f), 2e-3f);
    EXPECT_NEAR(all.min.y, -0.5f, 1e-5f);
    pose.evaluate(0.0);
    scene::Aabb now;
    shownPoints(scene, &pose)([&](std::span<const glm::vec3> batch) {
        for (const glm::vec3& p : batch) now.extend(p);
    });
    EXPECT_NEAR(now.max.y, 0.5f, 1e-5f);
}

TEST(ScenePose, NoAnimationIsTheRestPose) {
    REQUIRE_MODELS();
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "BoxAnimated/glTF-Binary/BoxAnimated.glb");
    const std::vector<std::string> none{"none"};
    ScenePose pose(scene, selectAnimations(scene, none));
    EXPECT_FALSE(pose.animated());
    pose.evaluate(1.875);
    for (size_t i = 0; i < scene.draws.size(); ++i) EXPECT_EQ(pose.draws()[i].world, scene.draws[i].world);
}

TEST(ScenePose, SelectionByIndexNameAllAndNone) {
    REQUIRE_MODELS();
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "InterpolationTest/glTF-Binary/InterpolationTest.glb");
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.animations.size(), 9u);
    EXPECT_EQ(scene.animations[0].name, "Step Scale");
    const auto select = [&](std::vector<std::string> names) { return selectAnimations(scene, names); };
    EXPECT_EQ(select({}), std::vector<uint32_t>{0});
    EXPECT_EQ(select({"none"}), std::vector<uint32_t>{});
    EXPECT_EQ(select({"all"}).size(), 9u);
    EXPECT_EQ(select({"Linear Translation", "2", "2"}), (std::vector<uint32_t>{2, 8}));
    try {
        select({"Bounce"});
        FAIL() << "no error";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("no animation named 'Bounce' (its animations: 0 'Step Scale', 1 'Linear Scale'"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(select({"9"}), UserError);
}

TEST(ScenePose, InterpolationTestModesDifferBetweenKeys) {
    REQUIRE_MODELS();
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "InterpolationTest/glTF-Binary/InterpolationTest.glb");
    ScenePose pose(scene, selectAnimations(scene, std::vector<std::string>{"all"}));
    // Each cube is moved by exactly one animation, its own.
    EXPECT_EQ(pose.animatedDraws().size(), 9u);
    // Translation cubes (nodes 8 STEP, 9 CUBICSPLINE, 10 LINEAR) between two keys: each mode
    // reproduces its own sampler, and the three differ.
    pose.evaluate(0.3);
    float y[3];
    for (int i = 0; i < 3; ++i) {
        const int node = 8 + i;
        const animation::Animation& animation = scene.animations[size_t(6 + i)];
        ASSERT_EQ(scene.nodes[animation.channels[0].node].source, node);
        float value[3];
        animation::evaluateSampler(animation.samplers[0], animation::AnimatedProperty::Translation, 0.3, value);
        y[i] = pose.draws()[drawOf(scene, node)].world[3].y;
        EXPECT_NEAR(y[i], value[1], 1e-5f);
    }
    EXPECT_NE(y[0], y[1]);
    EXPECT_NE(y[1], y[2]);
}

TEST(ScenePose, ZeroScaleAnimatedNodeIsKeptHiddenUntilScaledUp) {
    // A node at scale 0 that an animation grows: the loader keeps its draw (a static one it would
    // drop with a warning); the pose hides it at 0 and shows it at 1.
    candela::test::TempDir dir;
    assets::test::GltfBuilder b;
    b.addTriangle();
    b.doc["nodes"][0]["scale"] = {0, 0, 0};
    const int times = b.addFloats({0, 1}, "SCALAR", 1);
    const int scales = b.addFloats({0, 0, 0, 1, 1, 1}, "VEC3", 3);
    b.doc["animations"] = assets::test::Json::array({{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "scale"}}}}}},
                                        {"samplers", {{{"input", times}, {"output", scales}}}}}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.draws.size(), 1u);
    EXPECT_TRUE(scene.draws[0].hidden);
    ScenePose pose(scene, selectAnimations(scene, {}));
    EXPECT_TRUE(pose.draws()[0].hidden);
    pose.evaluate(1.0, /*loop=*/false);
    EXPECT_FALSE(pose.draws()[0].hidden);
    expectVec(pose.bounds().max, {1, 1, 0});
    pose.evaluate(0.5, false);
    expectVec(pose.draws()[0].world[0], {0.5f, 0, 0});
}

TEST(ScenePose, ChannelsOnNodesOutsideTheSceneAndWithoutTargetAreDropped) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b;
    b.addTriangle();
    const int other = b.addNode({{"translation", {1, 2, 3}}});  // not in the scene
    const int times = b.addFloats({0, 1}, "SCALAR", 1);
    const int moves = b.addFloats({0, 0, 0, 1, 0, 0}, "VEC3", 3);
    b.doc["animations"] = assets::test::Json::array({{{"channels", {{{"sampler", 0}, {"target", {{"node", other}, {"path", "translation"}}}},
                                                       {{"sampler", 0}, {"target", {{"path", "translation"}}}}}},
                                        {"samplers", {{{"input", times}, {"output", moves}}}}}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.animations.size(), 1u);
    EXPECT_TRUE(scene.animations[0].channels.empty());
    EXPECT_FALSE(ScenePose(scene, {0}).animated());
}

}  // namespace
}  // namespace candela::pose::test::scene_pose_test

namespace candela::pose::test::scene_pose_test {
namespace {

// Every deformed vertex (the CPU reference of the skin_morph pass) lies in its draw's posed bounds,
// at keys and between them, and is one of the points framing fits for that pose (in float).
void expectBoundsContainDeformedVertices(const char* path, const std::vector<std::string>& animations) {
    if (assets::test::sharedModels().empty()) GTEST_SKIP() << "../shared/assets not present";
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / path);
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ScenePose pose(scene, selectAnimations(scene, animations));
    const auto inside = [](const scene::Aabb& box, const glm::vec3& p) {
        const glm::vec3 slack = 1e-4f * (glm::abs(box.max) + glm::abs(box.min) + 1.0f);
        return glm::all(glm::greaterThanEqual(p, box.min - slack)) && glm::all(glm::lessThanEqual(p, box.max + slack));
    };
    size_t checked = 0;
    for (double t : {0.0, 0.37, 0.8, 1.3, 2.9}) {
        pose.evaluate(t);
        std::vector<glm::vec3> points;
        visitShownPoints(pose, [&](std::span<const glm::vec3> batch) { points.insert(points.end(), batch.begin(), batch.end()); });
        scene::Aabb shown;
        for (const glm::vec3& p : points) shown.extend(p);
        for (uint32_t d : pose.deformedDraws()) {
            const scene::Draw& draw = pose.draws()[d];
            static const std::vector<glm::dmat4> none;
            const std::vector<scene::Vertex> vertices =
                deformVertices(scene, draw, pose.weights(draw), draw.skin >= 0 ? pose.jointMatrices(uint32_t(draw.skin)) : none);
            for (const scene::Vertex& v : vertices) {
                const glm::vec3 world = glm::vec3(draw.world * glm::vec4(v.position, 1.0f));
                ASSERT_TRUE(inside(draw.bounds, world)) << path << " t=" << t << " draw " << d;
                ASSERT_TRUE(inside(shown, world)) << path << " t=" << t << " draw " << d;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 0u);
}

TEST(ScenePose, SkinnedBoundsContainTheDeformedVerticesFox) { expectBoundsContainDeformedVertices("Fox/glTF-Binary/Fox.glb", {"all"}); }
TEST(ScenePose, SkinnedBoundsContainTheDeformedVerticesCesiumMan) {
    expectBoundsContainDeformedVertices("CesiumMan/glTF-Binary/CesiumMan.glb", {});
}
TEST(ScenePose, MorphedBoundsContainTheDeformedVertices) {
    expectBoundsContainDeformedVertices("MorphStressTest/glTF-Binary/MorphStressTest.glb", {"all"});
    expectBoundsContainDeformedVertices("AnimatedMorphCube/glTF-Binary/AnimatedMorphCube.glb", {});
}

}  // namespace
}  // namespace candela::pose::test::scene_pose_test

namespace candela::pose::test::scene_pose_test {
namespace {

// Fox running, at 0.4 s: its skinned draw and the CPU reference of its deformed vertices.
struct RunningFox {
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "Fox/glTF-Binary/Fox.glb");
    ScenePose pose{scene, selectAnimations(scene, std::vector<std::string>{"Run"})};
    const uint32_t d = (pose.evaluate(0.4), pose.deformedDraws().at(0));
    const scene::Draw& draw = pose.draws()[d];
    const std::vector<scene::Vertex> posed = deformVertices(scene, draw, pose.weights(draw), pose.jointMatrices(uint32_t(draw.skin)));
};

// The points framing fits for a skinned draw are the skin_morph reference's positions.
TEST(ScenePose, FramingFitsTheSkinMorphReference) {
    REQUIRE_MODELS();
    const RunningFox fox;
    std::vector<glm::vec3> points;
    visitDrawPoints(fox.scene, fox.draw, fox.pose.weights(fox.draw), fox.pose.jointMatrices(uint32_t(fox.draw.skin)),
                    [&](std::span<const glm::vec3> batch) { points.insert(points.end(), batch.begin(), batch.end()); });
    ASSERT_EQ(points.size(), fox.posed.size());
    for (size_t i = 0; i < points.size(); ++i) ASSERT_LT(glm::length(points[i] - fox.posed[i].position), 1e-3f) << i;  // (the fox is ~100 units long)
}

TEST(ScenePose, PickingHitsThePosedMesh) {
    REQUIRE_MODELS();
    const RunningFox fox;
    const scene::Scene& scene = fox.scene;
    const ScenePose& pose = fox.pose;
    const scene::Draw& draw = fox.draw;
    const std::vector<scene::Vertex>& posed = fox.posed;
    const uint32_t base = scene.deformations[size_t(draw.deformation)].firstVertex;
    // A ray from far above onto the posed centroid of some triangle hits the fox no further than it;
    // the same ray against the rest pose (bind pose) hits elsewhere or not at all.
    size_t differing = 0;
    for (uint32_t i = 0; i + 2 < draw.indexCount; i += 300) {
        const uint32_t* tri = scene.indices.data() + draw.firstIndex + i;
        const glm::vec3 centroid = (posed[tri[0] - base].position + posed[tri[1] - base].position + posed[tri[2] - base].position) / 3.0f;
        const Ray ray{centroid + glm::vec3(0.0f, 1000.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f)};
        const std::optional<Pick> hit = pickDraw(scene, pose, ray);
        ASSERT_TRUE(hit) << "triangle " << i / 3;
        EXPECT_LE(hit->distance, 1000.0f + 1e-2f);
        const std::optional<Pick> rest = pickDraw(scene, ray);
        differing += !rest || std::abs(rest->distance - hit->distance) > 1.0f;
    }
    EXPECT_GT(differing, 0u);
}

}  // namespace
}  // namespace candela::pose::test::scene_pose_test
