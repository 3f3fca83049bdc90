#include "pose/animation_conflicts.h"

#include "scene/animated_properties.h"

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>

namespace candela::pose {
namespace {

constexpr uint32_t kAllWeights = std::numeric_limits<uint32_t>::max();

// What one channel drives, as the pointer parser describes it (scene/animated_properties.h). Node
// channels: kind Node, index = Scene::nodes index, element = the weight (kAllWeights for a whole
// weights channel, 0 otherwise). Property channels: the object's kind and glTF index, `field` its row.
using Target = scene::PointerTarget;

// The drivers map's order.
struct TargetOrder {
    static auto tie(const Target& t) { return std::tie(t.kind, t.index, t.property, t.element, t.field); }
    bool operator()(const Target& a, const Target& b) const { return tie(a) < tie(b); }
};

Target targetOf(const animation::AnimationChannel& channel) {
    Target t{.kind = scene::PointerKind::Node, .index = channel.node, .property = channel.property};
    // Weights and Weight share one property so that a node's weight channels sort together.
    if (channel.property == animation::AnimatedProperty::Weights) t.element = kAllWeights;
    if (channel.property == animation::AnimatedProperty::Weight) {
        t.property = animation::AnimatedProperty::Weights;
        t.element = channel.element;
    }
    return t;
}

Target targetOf(const animation::PropertyChannel& channel) {
    scene::PointerKind kind = scene::PointerKind::Material;
    if (scene::AnimatedObject(channel.object) == scene::AnimatedObject::Light) kind = scene::PointerKind::Light;
    if (scene::AnimatedObject(channel.object) == scene::AnimatedObject::Camera) kind = scene::PointerKind::Camera;
    return {.kind = kind, .index = channel.index, .field = channel.field};
}

std::string nodeName(const scene::Scene& scene, uint32_t node) {
    const animation::SceneNode& n = scene.nodes[node];
    return n.name.empty() ? "node " + std::to_string(n.source) : "'" + n.name + "'";
}

std::string describe(const scene::Scene& scene, const Target& t) {
    if (t.kind != scene::PointerKind::Node)
        return scene::pointerOf({.kind = t.kind, .index = t.index, .property = animation::AnimatedProperty::Values, .field = t.field});
    const std::string of = " of " + nodeName(scene, t.index);
    switch (t.property) {
        case animation::AnimatedProperty::Translation: return "translation" + of;
        case animation::AnimatedProperty::Rotation: return "rotation" + of;
        case animation::AnimatedProperty::Scale: return "scale" + of;
        case animation::AnimatedProperty::Visibility: return "visibility" + of;
        default: return (t.element == kAllWeights ? std::string("morph weights") : "morph weight " + std::to_string(t.element)) + of;
    }
}

void addDriver(std::vector<uint32_t>& drivers, uint32_t animation) {
    if (std::find(drivers.begin(), drivers.end(), animation) == drivers.end()) drivers.push_back(animation);
}

std::string animationName(const scene::Scene& scene, uint32_t a) {
    const std::string& name = scene.animations[a].name;
    return name.empty() ? "animation " + std::to_string(a) : "'" + name + "'";
}

// "'A'", "'A' and 'B'", "'A', 'B' and 'C'".
std::string listOf(const scene::Scene& scene, const std::vector<uint32_t>& animations) {
    std::string out;
    for (size_t i = 0; i < animations.size(); ++i)
        out += (i == 0 ? "" : i + 1 == animations.size() ? " and " : ", ") + animationName(scene, animations[i]);
    return out;
}

}  // namespace

std::vector<AnimationConflict> animationConflicts(const scene::Scene& scene, std::span<const uint32_t> playing) {
    std::map<Target, std::vector<uint32_t>, TargetOrder> drivers;
    std::vector<Target> order;  // first appearance
    const auto add = [&](const Target& t, uint32_t a) {
        auto [it, added] = drivers.try_emplace(t);
        if (added) order.push_back(t);
        addDriver(it->second, a);
    };
    for (uint32_t a : playing) {
        for (const animation::AnimationChannel& channel : scene.animations[a].channels) add(targetOf(channel), a);
        for (const animation::PropertyChannel& channel : scene.animations[a].properties) add(targetOf(channel), a);
    }
    // A whole-weights channel also writes each single weight of its node.
    for (auto& [target, animations] : drivers) {
        if (target.kind != scene::PointerKind::Node || target.property != animation::AnimatedProperty::Weights || target.element == kAllWeights)
            continue;
        const auto all = drivers.find(Target{.kind = scene::PointerKind::Node, .index = target.index,
                                             .property = animation::AnimatedProperty::Weights, .element = kAllWeights});
        if (all != drivers.end())
            for (uint32_t a : all->second) addDriver(animations, a);
    }
    std::vector<AnimationConflict> out;
    for (const Target& t : order) {
        std::vector<uint32_t> animations = drivers[t];
        if (animations.size() < 2) continue;
        std::sort(animations.begin(), animations.end());
        out.push_back({describe(scene, t), std::move(animations)});
    }
    return out;
}

std::string describeAnimationConflicts(const scene::Scene& scene, std::span<const AnimationConflict> conflicts) {
    if (conflicts.empty()) return {};
    std::vector<uint32_t> involved;
    std::map<uint32_t, size_t> wins;  // per winning animation, on how many channels
    bool sameSet = true;
    for (const AnimationConflict& c : conflicts) {
        for (uint32_t a : c.animations) addDriver(involved, a);
        ++wins[c.animations.back()];
        sameSet = sameSet && c.animations == conflicts.front().animations;
    }
    std::sort(involved.begin(), involved.end());
    const size_t n = conflicts.size();
    std::string line = "animations " + listOf(scene, involved) + (sameSet ? " drive the same " : " overlap on ") +
                       std::to_string(n) + (n == 1 ? " channel (" : " channels (") + conflicts.front().channel +
                       (n == 1 ? ")" : ", ...)") + "; ";
    if (wins.size() == 1) {
        line += animationName(scene, wins.begin()->first) + " wins";
    } else {
        line += "on each the last playing one wins:";
        for (auto it = wins.rbegin(); it != wins.rend(); ++it)
            line += std::string(it == wins.rbegin() ? " " : ", ") + animationName(scene, it->first) + " on " + std::to_string(it->second);
    }
    return line + " (the last in the file; animations are applied in file order, not blended)";
}

}  // namespace candela::pose
