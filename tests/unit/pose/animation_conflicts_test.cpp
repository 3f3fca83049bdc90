// Animations that drive the same channels: which channels conflict (pose/animation_conflicts.h),
// the line that says so, and that the winner it names is the one ScenePose draws — on Fox's three
// clips and on small hand-built scenes (disjoint channels, weights against a single weight,
// material properties, different winners on different channels).
#include "gltf_test_util.h"

#include "pose/animation_conflicts.h"
#include "pose/scene_pose.h"
#include "scene/animated_properties.h"

#include <set>
#include <tuple>

namespace candela::pose::test {
namespace {

// A scene of `nodes` named root nodes and no draws.
scene::Scene nodesNamed(std::vector<std::string> names) {
    scene::Scene scene;
    for (std::string& name : names) scene.nodes.push_back({.name = std::move(name), .source = int32_t(scene.nodes.size())});
    return scene;
}

// Adds an animation named `name` whose channels move the given nodes' `property` to a constant
// `value` (one key at 0 s; the value's width is the property's).
void addAnimation(scene::Scene& scene, std::string name, std::vector<std::pair<uint32_t, animation::AnimatedProperty>> channels,
                  float value = 1.0f) {
    animation::Animation a{.name = std::move(name)};
    for (const auto& [node, property] : channels) {
        const uint32_t width = property == animation::AnimatedProperty::Rotation ? 4 : property == animation::AnimatedProperty::Weights
                                                                                ? uint32_t(scene.nodes[node].weights.size())
                                                                            : property == animation::AnimatedProperty::Weight ? 1 : 3;
        std::vector<float> values(width, value);
        if (property == animation::AnimatedProperty::Rotation) values = {0, 0, 0, 1};
        a.samplers.push_back({.times = {0.0f}, .values = values, .interpolation = animation::Interpolation::Linear, .width = width});
        a.channels.push_back({.sampler = uint32_t(a.samplers.size() - 1), .node = node, .property = property});
    }
    scene.animations.push_back(std::move(a));
}

std::vector<uint32_t> all(const scene::Scene& scene) { return selectAnimations(scene, std::vector<std::string>{"all"}); }

TEST(AnimationConflicts, FoxClipsDriveTheSameJointsAndTheLastWins) {
    REQUIRE_MODELS();
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "Fox/glTF-Binary/Fox.glb");
    ASSERT_EQ(scene.animations.size(), 3u);
    // The channels every clip drives, counted from the file: (node, property) in all three.
    std::set<std::pair<uint32_t, animation::AnimatedProperty>> common;
    for (const animation::AnimationChannel& c : scene.animations[0].channels) common.insert({c.node, c.property});
    for (uint32_t a = 1; a < 3; ++a) {
        std::set<std::pair<uint32_t, animation::AnimatedProperty>> here;
        for (const animation::AnimationChannel& c : scene.animations[a].channels)
            if (common.count({c.node, c.property})) here.insert({c.node, c.property});
        common = here;
    }
    ASSERT_FALSE(common.empty());

    const std::vector<AnimationConflict> conflicts = animationConflicts(scene, all(scene));
    EXPECT_EQ(conflicts.size(), common.size());
    for (const AnimationConflict& c : conflicts) EXPECT_EQ(c.animations, (std::vector<uint32_t>{0, 1, 2})) << c.channel;
    EXPECT_EQ(describeAnimationConflicts(scene, conflicts),
              "animations 'Survey', 'Walk' and 'Run' drive the same " + std::to_string(common.size()) + " channels (" +
                  conflicts.front().channel + ", ...); 'Run' wins (the last in the file; animations are applied in file order, "
                  "not blended)");

    // What the line says is what is drawn: all three clips give Run's pose, wherever Run drives.
    for (const double t : {0.0, 0.37, 0.91}) {
        ScenePose both(scene, all(scene)), run(scene, {2});
        both.evaluate(t);
        run.evaluate(t);
        for (const auto& [node, property] : common) {
            const animation::NodeTransform& a = both.nodes()[node].transform;
            const animation::NodeTransform& b = run.nodes()[node].transform;
            EXPECT_EQ(std::tie(a.translation, a.rotation, a.scale), std::tie(b.translation, b.rotation, b.scale))
                << "node " << scene.nodes[node].name << " at " << t << " s";
        }
    }

    // One clip, or a clip and none: nothing to say.
    for (uint32_t a = 0; a < 3; ++a) EXPECT_TRUE(animationConflicts(scene, std::vector<uint32_t>{a}).empty());
    EXPECT_EQ(describeAnimationConflicts(scene, {}), "");
}

TEST(AnimationConflicts, DisjointChannelsDoNotConflict) {
    scene::Scene scene = nodesNamed({"a", "b"});
    addAnimation(scene, "moveA", {{0, animation::AnimatedProperty::Translation}, {0, animation::AnimatedProperty::Rotation}});
    addAnimation(scene, "moveB", {{1, animation::AnimatedProperty::Translation}});
    addAnimation(scene, "scaleA", {{0, animation::AnimatedProperty::Scale}});  // the same node, another property
    EXPECT_TRUE(animationConflicts(scene, all(scene)).empty());
}

TEST(AnimationConflicts, InterpolationTestClipsAreDisjoint) {
    REQUIRE_MODELS();
    const scene::Scene scene = assets::loadGltf(assets::test::sharedModels() / "InterpolationTest/glTF-Binary/InterpolationTest.glb");
    ASSERT_GT(scene.animations.size(), 1u);
    EXPECT_TRUE(animationConflicts(scene, all(scene)).empty());
}

TEST(AnimationConflicts, EachChannelNamesItsDriversAndTheLineItsWinners) {
    scene::Scene scene = nodesNamed({"hip", "", "tail"});
    addAnimation(scene, "Idle", {{0, animation::AnimatedProperty::Rotation}, {1, animation::AnimatedProperty::Translation}}, 1.0f);
    addAnimation(scene, "Wag", {{2, animation::AnimatedProperty::Rotation}}, 2.0f);
    addAnimation(scene, "Walk", {{0, animation::AnimatedProperty::Rotation}, {1, animation::AnimatedProperty::Translation}}, 3.0f);
    addAnimation(scene, "", {{2, animation::AnimatedProperty::Rotation}}, 4.0f);  // unnamed

    const std::vector<AnimationConflict> conflicts = animationConflicts(scene, all(scene));
    ASSERT_EQ(conflicts.size(), 3u);
    EXPECT_EQ(conflicts[0].channel, "rotation of 'hip'");
    EXPECT_EQ(conflicts[0].animations, (std::vector<uint32_t>{0, 2}));
    EXPECT_EQ(conflicts[1].channel, "translation of node 1");  // unnamed: its glTF index
    EXPECT_EQ(conflicts[2].channel, "rotation of 'tail'");
    EXPECT_EQ(conflicts[2].animations, (std::vector<uint32_t>{1, 3}));
    EXPECT_EQ(describeAnimationConflicts(scene, conflicts),
              "animations 'Idle', 'Wag', 'Walk' and animation 3 overlap on 3 channels (rotation of 'hip', ...); on each the "
              "last playing one wins: animation 3 on 1, 'Walk' on 2 (the last in the file; animations are applied in file "
              "order, not blended)");
    // The pose agrees: node 1 at Walk's translation, whatever order the animations are named in.
    ScenePose pose(scene, selectAnimations(scene, std::vector<std::string>{"Walk", "Idle"}));
    pose.evaluate(0.5);
    EXPECT_EQ(pose.nodes()[1].transform.translation, glm::dvec3(3.0));

    // Two of them on one channel: one channel, one winner.
    const std::vector<AnimationConflict> two = animationConflicts(scene, std::vector<uint32_t>{1, 3});
    EXPECT_EQ(describeAnimationConflicts(scene, two),
              "animations 'Wag' and animation 3 drive the same 1 channel (rotation of 'tail'); animation 3 wins (the last in "
              "the file; animations are applied in file order, not blended)");
}

TEST(AnimationConflicts, WeightsOverlapTheirSingleWeights) {
    scene::Scene scene = nodesNamed({"face"});
    scene.nodes[0].weights = {0, 0, 0};
    addAnimation(scene, "all", {{0, animation::AnimatedProperty::Weights}});
    animation::Animation one{.name = "blink"};
    one.samplers.push_back({.times = {0.0f}, .values = {1.0f}, .interpolation = animation::Interpolation::Step, .width = 1});
    one.channels.push_back({.sampler = 0, .node = 0, .property = animation::AnimatedProperty::Weight, .element = 2});
    scene.animations.push_back(one);
    scene.animations.push_back(one);
    scene.animations.back().name = "wink";
    scene.animations.back().channels[0].element = 1;

    // blink and wink touch different weights; each overlaps the whole-weights channel.
    const std::vector<AnimationConflict> conflicts = animationConflicts(scene, all(scene));
    ASSERT_EQ(conflicts.size(), 2u);
    EXPECT_EQ(conflicts[0].channel, "morph weight 2 of 'face'");
    EXPECT_EQ(conflicts[0].animations, (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(conflicts[1].channel, "morph weight 1 of 'face'");
    EXPECT_EQ(conflicts[1].animations, (std::vector<uint32_t>{0, 2}));
    EXPECT_TRUE(animationConflicts(scene, std::vector<uint32_t>{1, 2}).empty());
}

TEST(AnimationConflicts, PropertyChannelsConflictOnTheSameField) {
    scene::Scene scene;
    scene.materials.resize(2);
    const std::optional<scene::PointerTarget> emissive = scene::parsePointer("/materials/1/emissiveFactor");
    ASSERT_TRUE(emissive);
    for (const char* name : {"glow", "pulse"}) {
        animation::Animation a{.name = name};
        a.samplers.push_back({.times = {0.0f}, .values = {1, 1, 1}, .interpolation = animation::Interpolation::Linear, .width = 3});
        a.properties.push_back({.sampler = 0, .object = uint8_t(scene::AnimatedObject::Material), .index = 1, .field = emissive->field});
        scene.animations.push_back(std::move(a));
    }
    const std::vector<AnimationConflict> conflicts = animationConflicts(scene, all(scene));
    ASSERT_EQ(conflicts.size(), 1u);
    EXPECT_EQ(conflicts[0].channel, "/materials/1/emissiveFactor");
    EXPECT_EQ(conflicts[0].animations, (std::vector<uint32_t>{0, 1}));
    // Another material's field is another channel.
    scene.animations[1].properties[0].index = 0;
    EXPECT_TRUE(animationConflicts(scene, all(scene)).empty());
}

}  // namespace
}  // namespace candela::pose::test
