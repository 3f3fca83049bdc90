#include "animation/node_tree.h"

#include "core/errors.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace candela::animation {

glm::dmat4 NodeTransform::local() const {
    if (matrix) return *matrix;
    // T · R · S written out: the rotation's columns scaled, the translation last. The same numbers
    // as the three matrix products (every term those add is an exact 0 or 1 product), for a
    // fraction of the work — deep animated hierarchies call this for every node every frame.
    const glm::dmat3 r = glm::mat3_cast(rotation);
    return glm::dmat4(glm::dvec4(r[0] * scale.x, 0.0), glm::dvec4(r[1] * scale.y, 0.0), glm::dvec4(r[2] * scale.z, 0.0),
                      glm::dvec4(translation, 1.0));
}

std::vector<uint32_t> dependentNodes(const std::vector<SceneNode>& nodes, std::span<const uint32_t> animated) {
    std::vector<uint8_t> dirty(nodes.size(), 0);
    for (uint32_t node : animated)
        if (node < nodes.size()) dirty[node] = 1;
    std::vector<uint32_t> order;
    // Parents come first, so one ascending pass sees a parent's mark before its children.
    for (uint32_t i = 0; i < nodes.size(); ++i) {
        const int32_t parent = nodes[i].parent;
        if (parent >= 0 && dirty[size_t(parent)]) dirty[i] = 1;
        if (dirty[i]) order.push_back(i);
    }
    return order;
}

void updateWorldTransforms(std::vector<SceneNode>& nodes, std::span<const uint32_t> order) {
    for (uint32_t i : order) {
        SceneNode& node = nodes[i];
        const glm::dmat4 local = node.transform.local();
        node.world = node.parent >= 0 ? nodes[size_t(node.parent)].world * local : local;
        node.shown = node.visible && (node.parent < 0 || nodes[size_t(node.parent)].shown);
    }
}

void applyAnimation(const Animation& animation, double time, std::vector<SceneNode>& nodes) {
    float value[4];
    for (const AnimationChannel& channel : animation.channels) {
        const AnimationSampler& sampler = animation.samplers[channel.sampler];
        SceneNode& node = nodes[channel.node];
        const bool fits = channel.property == AnimatedProperty::Weights  ? sampler.width == node.weights.size()
                          : channel.property == AnimatedProperty::Weight ? sampler.width == 1 && channel.element < node.weights.size()
                                                                         : sampler.width <= 4;
        if (!fits)
            throw InternalError("animation '" + animation.name + "': a channel's " + std::to_string(sampler.width) +
                                " values do not fit node '" + node.name + "'");
        if (channel.property == AnimatedProperty::Weights) {
            evaluateSampler(sampler, channel.property, time, node.weights);
            continue;
        }
        evaluateSampler(sampler, channel.property, time, std::span<float>(value, sampler.width));
        NodeTransform& t = node.transform;
        switch (channel.property) {
            case AnimatedProperty::Translation: t.translation = glm::dvec3(value[0], value[1], value[2]); break;
            case AnimatedProperty::Rotation: t.rotation = glm::dquat(value[3], value[0], value[1], value[2]); break;
            case AnimatedProperty::Scale: t.scale = glm::dvec3(value[0], value[1], value[2]); break;
            case AnimatedProperty::Weight: node.weights[channel.element] = value[0]; break;
            case AnimatedProperty::Visibility: node.visible = value[0] != 0.0f; break;
            case AnimatedProperty::Weights:
            case AnimatedProperty::Values: break;  // Values: property channels, not a node's
        }
    }
}

}  // namespace candela::animation
