#pragma once
// The node hierarchy of a glTF scene kept for animation: each node's local transform (TRS, or a
// fixed matrix) and its world transform, in depth-first order so that a parent always comes before
// its children. Updating after an animation step touches only the animated nodes and their
// descendants. Pure: no Vulkan; doubles, so deep hierarchies and large coordinates keep precision.
//
//   std::vector<SceneNode> nodes = …;                      // parents first
//   const std::vector<uint32_t> dirty = dependentNodes(nodes, animatedNodes);  // once per animation set
//   applyAnimation(animation, time, nodes);                // writes local TRS and weights
//   updateWorldTransforms(nodes, dirty);                   // every frame

#include "animation/animation_sampler.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace candela::animation {

// A node's transform relative to its parent: translation · rotation · scale, or a fixed matrix
// (glTF nodes with a "matrix" are never animation targets).
struct NodeTransform {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z (GLM's order); unit length
    glm::dvec3 scale{1.0};
    std::optional<glm::dmat4> matrix;
    glm::dmat4 local() const;
};

struct SceneNode {
    std::string name;
    int32_t source = -1;  // the glTF node it was loaded from (animation channels name those)
    int32_t parent = -1;  // index of the parent node, always smaller than this node's; -1 for a root
    NodeTransform transform;
    glm::dmat4 world{1.0};      // parent's world · local, kept current by updateWorldTransforms
    std::vector<float> weights;  // morph-target weights of the node's mesh (empty without targets)
    // KHR_node_visibility: the node's own flag, and whether it is shown — visible and every
    // ancestor shown (kept current by updateWorldTransforms, with `world`). What hangs from a node
    // that is not shown (its draws, its lights) is neither drawn nor lights anything.
    bool visible = true;
    bool shown = true;
};

// The nodes whose world transform depends on any node of `animated`: those nodes and all their
// descendants, ascending (parents first). Out-of-range indices in `animated` are ignored.
// Precondition: every node's parent index is smaller than its own.
std::vector<uint32_t> dependentNodes(const std::vector<SceneNode>& nodes, std::span<const uint32_t> animated);

// Recomputes the world transform and the shown flag of each node in `order` (ascending, e.g. from
// dependentNodes) from its parent's and its own local transform and visible flag. Call with every
// node index, ascending, to update the whole tree.
void updateWorldTransforms(std::vector<SceneNode>& nodes, std::span<const uint32_t> order);

// One glTF animation channel on a node: sampler `sampler` of its animation drives `property` of
// node `node` (a core channel, or a KHR_animation_pointer pointer to a node or a mesh's weights).
struct AnimationChannel {
    uint32_t sampler = 0;
    uint32_t node = 0;
    AnimatedProperty property = AnimatedProperty::Translation;
    uint32_t element = 0;  // AnimatedProperty::Weight: which morph-target weight
};

// One KHR_animation_pointer channel on anything but a node: sampler `sampler` (AnimatedProperty::
// Values) drives field `field` of object `index` of kind `object`. The kinds, the indices they
// count and the fields are the scene layer's (scene/animated_properties.h: AnimatedObject and its
// tables); this layer only stores and samples them.
struct PropertyChannel {
    uint32_t sampler = 0;
    uint8_t object = 0;
    uint32_t index = 0;
    uint16_t field = 0;
};

struct Animation {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
    std::vector<PropertyChannel> properties;
    double duration = 0.0;  // the last key time of any sampler, seconds
};

// Writes every node channel's value at `time` (seconds; clamped by the samplers at both ends) into
// its node's transform, weights or visible flag (property channels are the caller's: they write
// scene objects). Preconditions (the loader checks them): every sampler passes samplerProblem for
// the properties its channels drive, channels name existing samplers and nodes, animated nodes
// have no fixed matrix, a weights channel's width equals its node's weight count and a weight
// channel's element is below it.
void applyAnimation(const Animation& animation, double time, std::vector<SceneNode>& nodes);

}  // namespace candela::animation
