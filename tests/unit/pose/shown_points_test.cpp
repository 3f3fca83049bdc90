// The points framing fits (pose/shown_points.h): the same for a node's rotation and the vertices
// rotated in the file, every instance, no hidden draw, a pose at its time against the poses of a
// sequence, and the times that span an animation (skinned points against the skin_morph reference:
// scene_pose_test.cpp).
#include "gltf_test_util.h"

#include "pose/scene_pose.h"
#include "pose/shown_points.h"

#include <glm/gtc/matrix_transform.hpp>

namespace candela::pose::test::shown_points_test {
namespace {

// An irregular solid (a long thin tetrahedron), its vertices placed by `bake`, drawn at `world`.
scene::Scene tetrahedron(const glm::mat4& bake, const glm::mat4& world) {
    scene::Scene s;
    for (const glm::vec3 p : {glm::vec3(-3, 0, 0), glm::vec3(3, 0.2f, 0), glm::vec3(0, 0.5f, 0.4f), glm::vec3(0.5f, -0.3f, -0.6f)})
        s.vertices.push_back({.position = glm::vec3(bake * glm::vec4(p, 1.0f))});
    s.indices = {0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0};
    s.draws.push_back({.firstIndex = 0, .indexCount = 12, .world = world});
    return s;
}

scene::Aabb boxOf(const scene::PointSource& points) {
    scene::Aabb box;
    points([&](std::span<const glm::vec3> batch) {
        for (const glm::vec3& p : batch) box.extend(p);
    });
    return box;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(ShownPoints, ARotatedNodeFramesAsTheVerticesRotatedInTheFile) {
    const glm::mat4 turn = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) *
                           glm::rotate(glm::mat4(1.0f), glm::radians(17.0f), glm::normalize(glm::vec3(1, 2, 0.5f)));
    const scene::Scene node = tetrahedron(glm::mat4(1.0f), turn), baked = tetrahedron(turn, glm::mat4(1.0f));
    const scene::Aabb a = shownBounds(node), b = shownBounds(baked);
    expectNear(a.min, b.min, 1e-5f);
    expectNear(a.max, b.max, 1e-5f);
    const scene::FramingRequest request{.aspect = 1.5f, .directions = {{0.0f, 75.0f}}};
    const scene::OrbitCamera c = scene::frame(shownPoints(node, nullptr), request), d = scene::frame(shownPoints(baked, nullptr), request);
    expectNear(c.target, d.target, 1e-5f);
    EXPECT_NEAR(c.radius, d.radius, 1e-4f);
    EXPECT_NEAR(c.fovYDegrees, d.fovYDegrees, 1e-3f);
    // The mesh's own box pushed through the node's rotation (the bounds before) is larger.
    scene::Aabb corners;
    for (int i = 0; i < 8; ++i) {
        const scene::Aabb local = shownBounds(tetrahedron(glm::mat4(1.0f), glm::mat4(1.0f)));
        const glm::vec3 corner((i & 1) ? local.max.x : local.min.x, (i & 2) ? local.max.y : local.min.y, (i & 4) ? local.max.z : local.min.z);
        corners.extend(glm::vec3(turn * glm::vec4(corner, 1.0f)));
    }
    EXPECT_GT(corners.max.y - corners.min.y, 1.1f * (a.max.y - a.min.y));
}

TEST(ShownPoints, EveryInstanceAndNoHiddenDraw) {
    scene::Scene s = tetrahedron(glm::mat4(1.0f), glm::mat4(1.0f));
    s.instances = {glm::translate(glm::mat4(1.0f), glm::vec3(0, 10, 0)), glm::translate(glm::mat4(1.0f), glm::vec3(0, -10, 0))};
    s.draws[0].firstInstance = 0;
    s.draws[0].instanceCount = 2;
    scene::Aabb box = shownBounds(s);
    EXPECT_FLOAT_EQ(box.max.y, 10.5f);
    EXPECT_FLOAT_EQ(box.min.y, -10.3f);
    // A second draw, hidden (KHR_node_visibility), far away: left out unless asked for.
    s.draws.push_back({.firstIndex = 0, .indexCount = 12, .world = glm::translate(glm::mat4(1.0f), glm::vec3(100, 0, 0)), .hidden = true});
    EXPECT_FLOAT_EQ(shownBounds(s).max.x, 3.0f);
    EXPECT_FLOAT_EQ(shownBounds(s, /*includeHidden=*/true).max.x, 103.0f);
}

TEST(ShownPoints, AStillFitsItsPoseAndASequenceEveryFrame) {
    REQUIRE_MODELS();
    // BoxAnimated: the box climbs to y = 2.52 at 1.25 s and turns there.
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "BoxAnimated/glTF-Binary/BoxAnimated.glb");
    ScenePose pose(scene, selectAnimations(scene, {}));
    pose.evaluate(0.0);
    const scene::Aabb atZero = boxOf(shownPoints(scene, &pose));
    EXPECT_NEAR(atZero.max.y, 0.5f, 1e-5f);
    EXPECT_NEAR(boxOf(shownPoints(scene, &pose, {1.25})).max.y, 3.02f, 1e-4f);
    // The sequence's frames at 0, 0.5, 1 and 1.5 s: the highest is the one at 1.5 s, turned a little.
    const scene::Aabb sequence = boxOf(shownPoints(scene, &pose, {0.0, 0.5, 1.0, 1.5}));
    EXPECT_GT(sequence.max.y, 2.9f);
    EXPECT_NEAR(sequence.min.y, -0.5f, 1e-5f);
    // (The source evaluates a copy: the pose stays at 0 s.)
    EXPECT_NEAR(boxOf(shownPoints(scene, &pose)).max.y, 0.5f, 1e-5f);
    // A pose that moves nothing frames the rest pose, whatever the times.
    const ScenePose still(scene, selectAnimations(scene, std::vector<std::string>{"none"}));
    EXPECT_NEAR(boxOf(shownPoints(scene, &still, {1.25})).max.y, scene.bounds.max.y, 1e-6f);
}

TEST(ShownPoints, AnimationTimesSpanTheAnimationBetweenItsKeys) {
    REQUIRE_MODELS();
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "BoxAnimated/glTF-Binary/BoxAnimated.glb");
    const ScenePose pose(scene, selectAnimations(scene, {}));
    const std::vector<double> times = animationTimes(pose, 1024);
    EXPECT_EQ(times.front(), 0.0);
    EXPECT_NEAR(times.back(), pose.duration(), 1e-9);
    EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
    for (size_t i = 1; i < times.size(); ++i) EXPECT_LE(times[i] - times[i - 1], 1.0 / 30.0 + 1e-9);
    for (const animation::AnimationChannel& channel : scene.animations[0].channels)
        for (float key : scene.animations[0].samplers[channel.sampler].times)
            EXPECT_TRUE(std::binary_search(times.begin(), times.end(), double(key))) << key;
    const std::vector<double> few = animationTimes(pose, 5);
    ASSERT_EQ(few.size(), 5u);
    EXPECT_NEAR(few[4], pose.duration(), 1e-9);
}

}  // namespace
}  // namespace candela::pose::test::shown_points_test
