#include "assets/gltf_animations.h"

#include "assets/gltf_accessors.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <optional>

namespace candela::scene::gltf {
namespace {

std::optional<AnimatedProperty> propertyOf(const std::string& path) {
    if (path == "translation") return AnimatedProperty::Translation;
    if (path == "rotation") return AnimatedProperty::Rotation;
    if (path == "scale") return AnimatedProperty::Scale;
    if (path == "weights") return AnimatedProperty::Weights;
    return std::nullopt;
}

Interpolation interpolationOf(const LoadContext& ctx, const std::string& name, const std::string& what) {
    if (name == "LINEAR") return Interpolation::Linear;
    if (name == "STEP") return Interpolation::Step;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    ctx.fail(what + ": unknown interpolation '" + name.substr(0, 32) + "'");
}

// The glTF accessor type of a sampler output for `property`.
int outputType(AnimatedProperty property) {
    switch (property) {
        case AnimatedProperty::Rotation: return TINYGLTF_TYPE_VEC4;
        case AnimatedProperty::Weights: return TINYGLTF_TYPE_SCALAR;
        default: return TINYGLTF_TYPE_VEC3;
    }
}

// `source` read for `property` with `width` floats per value.
AnimationSampler readSampler(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::AnimationSampler& source,
                             AnimatedProperty property, uint32_t width, const std::string& what) {
    AnimationSampler sampler;
    sampler.interpolation = interpolationOf(ctx, source.interpolation, what);
    sampler.width = width;
    sampler.times = readFloats(ctx, model, source.input, TINYGLTF_TYPE_SCALAR, false, what + " input");
    // Rotations and weights may be normalized integers; translations and scales are floats.
    const bool integers = property == AnimatedProperty::Rotation || property == AnimatedProperty::Weights;
    sampler.values = readFloats(ctx, model, source.output, outputType(property), integers, what + " output");
    if (const std::string problem = samplerProblem(sampler, property); !problem.empty()) ctx.fail(what + ": " + problem);
    return sampler;
}

}  // namespace

void loadAnimations(const LoadContext& ctx, const tinygltf::Model& model, Scene& scene) {
    // glTF node → Scene::nodes index (-1: not in the loaded scene).
    std::vector<int32_t> sceneNode(model.nodes.size(), -1);
    for (size_t i = 0; i < scene.nodes.size(); ++i) sceneNode[size_t(scene.nodes[i].source)] = int32_t(i);

    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& source = model.animations[a];
        const std::string what = label("animation", int(a), source.name);
        Animation animation{.name = source.name.empty() ? "animation " + std::to_string(a) : source.name};
        animation.samplers.resize(source.samplers.size());
        // The output type and width each sampler was read for (a sampler shared by channels must fit each).
        std::vector<std::optional<std::pair<int, uint32_t>>> readAs(source.samplers.size());
        for (size_t c = 0; c < source.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = source.channels[c];
            const std::string channelWhat = what + " channel " + std::to_string(c);
            if (channel.sampler < 0 || size_t(channel.sampler) >= source.samplers.size())
                ctx.fail(channelWhat + ": sampler " + std::to_string(channel.sampler) + " does not exist");
            const std::optional<AnimatedProperty> property = propertyOf(channel.target_path);
            if (!property) {
                ctx.warn(channelWhat + ": target path '" + channel.target_path.substr(0, 32) + "' is not supported (ignored)");
                continue;
            }
            if (channel.target_node < 0) continue;  // no node: the target is an extension's
            if (size_t(channel.target_node) >= model.nodes.size())
                ctx.fail(channelWhat + ": node " + std::to_string(channel.target_node) + " does not exist");
            const int32_t node = sceneNode[size_t(channel.target_node)];
            const std::string nodeWhat = label("node", channel.target_node, model.nodes[size_t(channel.target_node)].name);
            if (!model.nodes[size_t(channel.target_node)].matrix.empty())
                ctx.fail(channelWhat + ": " + nodeWhat + " has a matrix, and only TRS nodes may be animated");
            uint32_t width = *property == AnimatedProperty::Rotation ? 4 : 3;
            if (*property == AnimatedProperty::Weights) {
                const tinygltf::Node& target = model.nodes[size_t(channel.target_node)];
                const bool hasTargets = target.mesh >= 0 && size_t(target.mesh) < model.meshes.size() &&
                                        !model.meshes[size_t(target.mesh)].primitives.empty() &&
                                        !model.meshes[size_t(target.mesh)].primitives[0].targets.empty();
                if (!hasTargets) ctx.fail(channelWhat + ": animates the weights of " + nodeWhat + ", whose mesh has no morph targets");
                width = uint32_t(model.meshes[size_t(target.mesh)].primitives[0].targets.size());
            }
            const size_t s = size_t(channel.sampler);
            const std::pair<int, uint32_t> as{outputType(*property), width};
            if (!readAs[s]) {
                animation.samplers[s] = readSampler(ctx, model, source.samplers[s], *property, width,
                                                    what + " sampler " + std::to_string(s));
                readAs[s] = as;
            } else if (*readAs[s] != as) {
                ctx.fail(channelWhat + ": sampler " + std::to_string(s) + " is shared with a channel of another value type");
            }
            if (node < 0) continue;  // a node outside the loaded scene: nothing drawn moves
            animation.channels.push_back({.sampler = uint32_t(s), .node = uint32_t(node), .property = *property});
        }
        for (const AnimationChannel& channel : animation.channels)
            animation.duration = std::max(animation.duration, double(animation.samplers[channel.sampler].times.back()));
        scene.animations.push_back(std::move(animation));
    }
}

}  // namespace candela::scene::gltf
