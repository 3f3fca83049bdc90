// The node hierarchy kept for animation: TRS composition, which nodes an animation step must
// update (the animated ones and their descendants, nothing else), partial updates equal to a full
// one, and channels writing translation, rotation, scale and morph weights.

#include "animation/node_tree.h"

#include "core/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace candela::animation::node_tree_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dquat aboutZ(double degrees) { return glm::angleAxis(degrees * kPi / 180.0, glm::dvec3(0.0, 0.0, 1.0)); }

// 0 ─┬─ 1 ── 2      3 ── 4
//    └─ 5
std::vector<SceneNode> forest() {
    std::vector<SceneNode> nodes(6);
    const int32_t parents[] = {-1, 0, 1, -1, 3, 0};
    for (size_t i = 0; i < nodes.size(); ++i) {
        nodes[i].name = "n" + std::to_string(i);
        nodes[i].parent = parents[i];
        nodes[i].transform.translation = glm::dvec3(double(i), 0.0, 0.0);
    }
    return nodes;
}

std::vector<uint32_t> all(const std::vector<SceneNode>& nodes) {
    std::vector<uint32_t> order(nodes.size());
    std::iota(order.begin(), order.end(), 0u);
    return order;
}

void expectNear(const glm::dvec3& got, const glm::dvec3& expected) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-12) << "component " << c;
}

TEST(NodeTree, LocalTransformIsTranslationRotationScale) {
    NodeTransform t{.translation = {0, 0, 5}, .rotation = aboutZ(90), .scale = {2, 2, 2}};
    // Scale first, then rotate, then translate: x̂ → 2x̂ → 2ŷ → (0, 2, 5).
    expectNear(glm::dvec3(t.local() * glm::dvec4(1, 0, 0, 1)), {0, 2, 5});
    t.matrix = glm::dmat4(3.0);
    EXPECT_EQ(t.local(), glm::dmat4(3.0));
}

TEST(NodeTree, DependentsAreTheAnimatedNodesAndTheirDescendants) {
    const std::vector<SceneNode> nodes = forest();
    const std::vector<uint32_t> one{1}, root{0}, other{4, 3}, outOfRange{17};
    EXPECT_EQ(dependentNodes(nodes, one), (std::vector<uint32_t>{1, 2}));
    EXPECT_EQ(dependentNodes(nodes, root), (std::vector<uint32_t>{0, 1, 2, 5}));
    EXPECT_EQ(dependentNodes(nodes, other), (std::vector<uint32_t>{3, 4}));
    EXPECT_TRUE(dependentNodes(nodes, outOfRange).empty());
}

TEST(NodeTree, UpdatingTheDependentsEqualsUpdatingEverything) {
    std::vector<SceneNode> partial = forest();
    updateWorldTransforms(partial, all(partial));
    expectNear(glm::dvec3(partial[2].world[3]), {3, 0, 0});  // 0 + 1 + 2
    // Animate node 1; node 3's subtree must not be touched at all.
    const glm::dmat4 untouched(7.0);
    partial[3].world = untouched;
    partial[1].transform.rotation = aboutZ(90);
    const std::vector<uint32_t> animated{1};
    updateWorldTransforms(partial, dependentNodes(partial, animated));
    EXPECT_EQ(partial[3].world, untouched);

    std::vector<SceneNode> full = forest();
    full[1].transform.rotation = aboutZ(90);
    updateWorldTransforms(full, all(full));
    for (uint32_t i : {0u, 1u, 2u, 5u})
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(partial[i].world[c][r], full[i].world[c][r], 1e-12) << i;
    // Node 2 sits 2 units along node 1's rotated x axis: (1, 2, 0).
    expectNear(glm::dvec3(full[2].world[3]), {1, 2, 0});
}

TEST(NodeTree, ChannelsWriteTransformsAndWeights) {
    std::vector<SceneNode> nodes = forest();
    nodes[4].weights = {0.0f, 0.0f};
    Animation animation{.name = "walk"};
    animation.samplers = {
        {.times = {0, 2}, .values = {0, 0, 0, 4, 6, 8}, .interpolation = Interpolation::Linear, .width = 3},
        {.times = {0, 2}, .values = {0, 0, 0, 1, 0, 0, float(std::sin(kPi / 4)), float(std::cos(kPi / 4))},
         .interpolation = Interpolation::Linear, .width = 4},
        {.times = {0, 2}, .values = {0, 1, 1, 0}, .interpolation = Interpolation::Linear, .width = 2},
        {.times = {0}, .values = {3, 3, 3}, .interpolation = Interpolation::Step, .width = 3},
    };
    animation.channels = {{0, 1, AnimatedProperty::Translation},
                          {1, 1, AnimatedProperty::Rotation},
                          {2, 4, AnimatedProperty::Weights},
                          {3, 5, AnimatedProperty::Scale}};
    applyAnimation(animation, 1.0, nodes);
    expectNear(nodes[1].transform.translation, {2, 3, 4});
    const glm::dquat q = nodes[1].transform.rotation;
    EXPECT_NEAR(std::fabs(glm::dot(q, aboutZ(45))), 1.0, 1e-6);
    EXPECT_EQ(nodes[4].weights, (std::vector<float>{0.5f, 0.5f}));
    expectNear(nodes[5].transform.scale, {3, 3, 3});
    // Past the end the last keys hold.
    applyAnimation(animation, 50.0, nodes);
    expectNear(nodes[1].transform.translation, {4, 6, 8});
    EXPECT_EQ(nodes[4].weights, (std::vector<float>{1.0f, 0.0f}));
    // A weights channel that does not fit its node is a broken precondition, not a buffer overrun.
    nodes[4].weights = {0.0f};
    EXPECT_THROW(applyAnimation(animation, 1.0, nodes), InternalError);
}

}  // namespace
}  // namespace candela::animation::node_tree_test
