// KHR_node_visibility read by the loader and animated through KHR_animation_pointer: a hidden node
// and everything under it are neither drawn nor lit by its lights, the bounds follow what is
// visible, and a visibility channel switches them at its keys.
#include "animation_pointer_util.h"

#include "pose/scene_pose.h"
#include "pose/shown_points.h"

namespace candela::pose::test::node_visibility_test {
namespace {

// Two triangles side by side: node 0 at the origin (drawn), node 1 hidden at x = 5 with a child,
// node 2 (visible itself, at x = 10 under node 1), which has a triangle and a point light.
assets::test::GltfBuilder hiddenBranch() {
    assets::test::GltfBuilder b;
    b.addTriangle();
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = assets::test::Json::array({{{"type", "point"}, {"intensity", 5}}});
    assets::test::useExtension(b, "KHR_lights_punctual");
    const int child = b.addNode({{"mesh", 0}, {"translation", {5, 0, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    const int parent = b.addNode({{"mesh", 0}, {"translation", {5, 0, 0}}, {"children", {child}}});
    assets::test::setVisible(b, parent, false);
    setVisible(b, child, true);
    b.setScene({0, parent});
    return b;
}

TEST(NodeVisibility, AHiddenParentHidesItsVisibleChildsDrawsAndLights) {
    candela::test::TempDir dir;
    const scene::Scene scene = assets::loadGltf(hiddenBranch().writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.nodes.size(), 3u);
    EXPECT_TRUE(scene.nodes[0].shown);
    EXPECT_FALSE(scene.nodes[1].visible);
    EXPECT_FALSE(scene.nodes[1].shown);
    EXPECT_TRUE(scene.nodes[2].visible);
    EXPECT_FALSE(scene.nodes[2].shown);
    ASSERT_EQ(scene.draws.size(), 3u);
    EXPECT_FALSE(scene.draws[0].hidden);
    EXPECT_TRUE(scene.draws[1].hidden);
    EXPECT_TRUE(scene.draws[2].hidden);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_TRUE(scene.lights[0].hidden);
    // The bounds are the drawn triangle's alone.
    EXPECT_EQ(scene.bounds.min, glm::vec3(0, 0, 0));
    EXPECT_EQ(scene.bounds.max, glm::vec3(1, 1, 0));
    // The pose and its bounds agree, with no animation.
    const ScenePose pose(scene, {});
    EXPECT_EQ(pose.bounds().max, glm::vec3(1, 1, 0));
    EXPECT_EQ(shownBounds(scene).max, glm::vec3(1, 1, 0));
}

TEST(NodeVisibility, EveryNodeHiddenFramesTheHiddenGeometryWithAWarning) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b;
    b.addTriangle();
    assets::test::setVisible(b, 0, false);
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    ASSERT_EQ(scene.report.warnings.size(), 1u);
    EXPECT_EQ(scene.report.warnings[0], "every node is hidden (KHR_node_visibility): framing uses the hidden geometry");
    EXPECT_TRUE(scene.draws[0].hidden);
    EXPECT_EQ(scene.bounds.max, glm::vec3(1, 1, 0));
    // Visible by default, and when said so: no warning.
    assets::test::setVisible(b, 0, true);
    EXPECT_TRUE(assets::loadGltf(b.writeGltf(dir.path())).report.warnings.empty());
}

TEST(NodeVisibility, AnAnimatedVisibilityTogglesAtItsKey) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = hiddenBranch();
    // Node 2 (the hidden parent) shown from 1 s (unsigned bytes, as the specification asks), hidden again from 2 s.
    assets::test::addPointerAnimation(b, {{.pointer = "/nodes/2/extensions/KHR_node_visibility/visible", .times = {0, 1, 2}, .values = {0, 1, 0},
                             .interpolation = "STEP", .componentType = assets::test::kUnsignedByte}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.animations[0].channels.size(), 1u);
    EXPECT_EQ(scene.animations[0].channels[0].property, animation::AnimatedProperty::Visibility);
    ScenePose pose(scene, {0});
    EXPECT_TRUE(pose.movesNodes());
    EXPECT_EQ(pose.animatedDraws(), (std::vector<uint32_t>{1, 2}));
    EXPECT_EQ(pose.animatedLights(), std::vector<uint32_t>{0});
    pose.evaluate(0.999, false);
    EXPECT_TRUE(pose.draws()[1].hidden);
    EXPECT_TRUE(pose.draws()[2].hidden);
    EXPECT_TRUE(pose.lights()[0].hidden);
    EXPECT_EQ(pose.bounds().max, glm::vec3(1, 1, 0));
    pose.evaluate(1.0, false);
    EXPECT_FALSE(pose.draws()[1].hidden);
    EXPECT_FALSE(pose.draws()[2].hidden);
    EXPECT_FALSE(pose.lights()[0].hidden);
    EXPECT_EQ(pose.bounds().max, glm::vec3(11, 1, 0));
    EXPECT_EQ(pose.draws()[2].world[3], glm::vec4(10, 0, 0, 1));
    pose.evaluate(2.5, false);
    EXPECT_TRUE(pose.draws()[2].hidden);
    // Framing the whole animation covers what it ever shows; framing the pose at 2.5 s, what that shows.
    scene::Aabb all, now;
    shownPoints(scene, &pose, animationTimes(pose, 64), /*loop=*/false)([&](std::span<const glm::vec3> batch) {
        for (const glm::vec3& p : batch) all.extend(p);
    });
    shownPoints(scene, &pose)([&](std::span<const glm::vec3> batch) {
        for (const glm::vec3& p : batch) now.extend(p);
    });
    EXPECT_EQ(all.max, glm::vec3(11, 1, 0));
    EXPECT_EQ(now.max, glm::vec3(1, 1, 0));
}

TEST(NodeVisibility, AVisibilityChannelTakesStepInterpolationOnly) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = hiddenBranch();
    assets::test::addPointerAnimation(b, {{.pointer = "/nodes/2/extensions/KHR_node_visibility/visible", .times = {0, 1}, .values = {0, 1},
                             .interpolation = "LINEAR", .componentType = assets::test::kUnsignedByte}});
    const std::string message = assets::test::loadError(b.writeGltf(dir.path()));
    EXPECT_NE(message.find("animation 0 channel 0: pointer '/nodes/2/extensions/KHR_node_visibility/visible': a visibility is a "
                           "bool: sampler 0 must use STEP interpolation, not LINEAR"),
              std::string::npos)
        << message;
}

// The world transforms and shown flags of a partial update equal a full one's.
TEST(NodeVisibility, ShownFollowsEveryAncestor) {
    std::vector<animation::SceneNode> nodes(4);
    nodes[1].parent = 0;
    nodes[2].parent = 1;
    nodes[3].parent = 0;
    nodes[1].visible = false;
    const std::vector<uint32_t> all = {0, 1, 2, 3};
    animation::updateWorldTransforms(nodes, all);
    EXPECT_TRUE(nodes[0].shown);
    EXPECT_FALSE(nodes[1].shown);
    EXPECT_FALSE(nodes[2].shown);
    EXPECT_TRUE(nodes[3].shown);
    nodes[1].visible = true;
    nodes[0].visible = false;
    const std::vector<uint32_t> dirty = animation::dependentNodes(nodes, std::vector<uint32_t>{0});
    updateWorldTransforms(nodes, dirty);
    for (const animation::SceneNode& n : nodes) EXPECT_FALSE(n.shown);
}

}  // namespace
}  // namespace candela::pose::test::node_visibility_test
