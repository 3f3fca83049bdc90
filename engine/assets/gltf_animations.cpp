#include "assets/gltf_animations.h"

#include "assets/gltf_accessors.h"
#include "scene/animated_properties.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <optional>
#include <tuple>

namespace candela::assets::gltf {
namespace {

std::optional<animation::AnimatedProperty> propertyOf(const std::string& path) {
    if (path == "translation") return animation::AnimatedProperty::Translation;
    if (path == "rotation") return animation::AnimatedProperty::Rotation;
    if (path == "scale") return animation::AnimatedProperty::Scale;
    if (path == "weights") return animation::AnimatedProperty::Weights;
    return std::nullopt;
}

animation::Interpolation interpolationOf(const LoadContext& ctx, const std::string& name, const std::string& what) {
    if (name == "LINEAR") return animation::Interpolation::Linear;
    if (name == "STEP") return animation::Interpolation::Step;
    if (name == "CUBICSPLINE") return animation::Interpolation::CubicSpline;
    ctx.fail(what + ": unknown interpolation '" + name.substr(0, 32) + "'");
}

// The glTF accessor type of a sampler output for `property`, `width` floats per value.
int outputType(animation::AnimatedProperty property, uint32_t width) {
    switch (property) {
        case animation::AnimatedProperty::Translation:
        case animation::AnimatedProperty::Scale: return TINYGLTF_TYPE_VEC3;
        case animation::AnimatedProperty::Rotation: return TINYGLTF_TYPE_VEC4;
        case animation::AnimatedProperty::Values:
            return width == 4 ? TINYGLTF_TYPE_VEC4 : width == 3 ? TINYGLTF_TYPE_VEC3 : width == 2 ? TINYGLTF_TYPE_VEC2
                                                                                                 : TINYGLTF_TYPE_SCALAR;
        default: return TINYGLTF_TYPE_SCALAR;  // weights, a weight, a visibility
    }
}

// Pointer channels (Values, Visibility) take any component type, as KHR_animation_pointer allows
// (integers converted, normalized ones as the core specification maps them); core ones FLOAT, or
// for rotations and weights normalized integers.
bool anyComponentType(animation::AnimatedProperty property) {
    return property == animation::AnimatedProperty::Values || property == animation::AnimatedProperty::Visibility;
}

// `source` read for `property` with `width` floats per value.
animation::AnimationSampler readSampler(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::AnimationSampler& source,
                             animation::AnimatedProperty property, uint32_t width, const std::string& what) {
    animation::AnimationSampler sampler;
    sampler.interpolation = interpolationOf(ctx, source.interpolation, what);
    sampler.width = width;
    sampler.times = readFloats(ctx, model, source.input, TINYGLTF_TYPE_SCALAR, false, what + " input");
    const int type = outputType(property, width);
    if (anyComponentType(property)) {
        for (const glm::vec4& v : readVectors(ctx, model, source.output, {type}, what + " output"))
            sampler.values.insert(sampler.values.end(), &v[0], &v[0] + std::min<uint32_t>(width, 4));
    } else {
        // Rotations and weights may be normalized integers; translations and scales are floats.
        const bool integers = property != animation::AnimatedProperty::Translation && property != animation::AnimatedProperty::Scale;
        sampler.values = readFloats(ctx, model, source.output, type, integers, what + " output");
    }
    if (const std::string problem = animation::samplerProblem(sampler, property); !problem.empty()) ctx.fail(what + ": " + problem);
    return sampler;
}

// The pointer of a KHR_animation_pointer channel; null when the channel has none.
const std::string* pointerOf(const tinygltf::AnimationChannel& channel) {
    if (channel.target_path != "pointer") return nullptr;
    const auto it = channel.target_extensions.find("KHR_animation_pointer");
    if (it == channel.target_extensions.end() || !it->second.Get("pointer").IsString()) return nullptr;
    return &it->second.Get("pointer").Get<std::string>();
}

// The pointer of `channel` parsed, when it has one Candela animates.
std::optional<scene::PointerTarget> parsedPointer(const tinygltf::AnimationChannel& channel) {
    const std::string* pointer = pointerOf(channel);
    return pointer ? scene::parsePointer(*pointer) : std::nullopt;
}

// The morph-target count of glTF mesh `mesh` (its first primitive's; loadNodes checks they agree).
size_t targetCount(const tinygltf::Model& model, int mesh) {
    if (mesh < 0 || size_t(mesh) >= model.meshes.size() || model.meshes[size_t(mesh)].primitives.empty()) return 0;
    return model.meshes[size_t(mesh)].primitives[0].targets.size();
}

// One animation being read: the checks and remapping of each channel.
class AnimationReader {
public:
    AnimationReader(const LoadContext& ctx, const tinygltf::Model& model, const std::vector<int32_t>& sceneNode,
                    const tinygltf::Animation& source, std::string what, animation::Animation& out)
        : mCtx(ctx), mModel(model), mSceneNode(sceneNode), mSource(source), mWhat(std::move(what)), mOut(out),
          mReadAs(source.samplers.size()) {
        out.samplers.resize(source.samplers.size());
    }

    void channel(size_t c) {
        const tinygltf::AnimationChannel& channel = mSource.channels[c];
        mChannelWhat = mWhat + " channel " + std::to_string(c);
        if (channel.sampler < 0 || size_t(channel.sampler) >= mSource.samplers.size())
            mCtx.fail(mChannelWhat + ": sampler " + std::to_string(channel.sampler) + " does not exist");
        mPointer = pointerOf(channel);
        if (mPointer) return pointerChannel(size_t(channel.sampler));
        if (channel.target_path == "pointer")
            return mCtx.warn(mChannelWhat + ": target path 'pointer' is not supported (ignored): the channel names no "
                                            "KHR_animation_pointer pointer");
        const std::optional<animation::AnimatedProperty> property = propertyOf(channel.target_path);
        if (!property) {
            mCtx.warn(mChannelWhat + ": target path '" + channel.target_path.substr(0, 32) + "' is not supported (ignored)");
            return;
        }
        if (channel.target_node < 0) return;  // no node: the target is an extension's
        nodeChannel(size_t(channel.sampler), uint32_t(channel.target_node), *property, 0);
    }

private:
    // "PREFIX: " for messages about the channel: its label, and its pointer when it has one.
    std::string prefix() const { return mChannelWhat + ": " + (mPointer ? "pointer '" + *mPointer + "': " : ""); }
    [[noreturn]] void missing(const char* kind, uint32_t index) const {
        mCtx.fail(prefix() + kind + " " + std::to_string(index) + " does not exist");
    }

    void pointerChannel(size_t sampler) {
        const std::optional<scene::PointerTarget> target = scene::parsePointer(*mPointer);
        if (!target) return mCtx.warn(mWhat + ": pointer '" + *mPointer + "' is not supported (ignored)");
        switch (target->kind) {
            case scene::PointerKind::Node: return nodeChannel(sampler, target->index, target->property, target->element);
            case scene::PointerKind::Mesh: return meshChannel(sampler, *target);
            case scene::PointerKind::Material:
                if (target->index >= mModel.materials.size()) missing("material", target->index);
                return propertyChannel(sampler, scene::AnimatedObject::Material, *target);
            case scene::PointerKind::Light:
                if (target->index >= mModel.lights.size()) missing("KHR_lights_punctual light", target->index);
                return propertyChannel(sampler, scene::AnimatedObject::Light, *target);
            case scene::PointerKind::Camera: {
                if (target->index >= mModel.cameras.size()) missing("camera", target->index);
                // A perspective camera has no orthographic properties, and the other way round.
                const std::string& type = mModel.cameras[target->index].type;
                if (scene::cameraFields()[target->field].suffix.rfind("/" + type + "/", 0) != 0)
                    return mCtx.warn(prefix() + "camera " + std::to_string(target->index) + " is " +
                                     (type.empty() ? "of no type" : type) + " (ignored)");
                return propertyChannel(sampler, scene::AnimatedObject::Camera, *target);
            }
        }
    }

    // A channel on glTF node `node`: a core channel, or a pointer to the node.
    void nodeChannel(size_t sampler, uint32_t node, animation::AnimatedProperty property, uint32_t element) {
        if (node >= mModel.nodes.size()) missing("node", node);
        const tinygltf::Node& target = mModel.nodes[node];
        const std::string nodeWhat = label("node", int(node), target.name);
        // The specification forbids a matrix on a node a core channel targets; a pointer to its
        // visibility or weights does not move it.
        const bool moves = property == animation::AnimatedProperty::Translation || property == animation::AnimatedProperty::Rotation ||
                           property == animation::AnimatedProperty::Scale;
        if (!target.matrix.empty() && (moves || !mPointer))
            mCtx.fail(prefix() + nodeWhat + " has a matrix, and only TRS nodes may be animated");
        uint32_t width = scene::pointerWidth({.kind = scene::PointerKind::Node, .property = property});
        if (property == animation::AnimatedProperty::Weights || property == animation::AnimatedProperty::Weight) {
            const size_t targets = targetCount(mModel, target.mesh);
            if (targets == 0) mCtx.fail(prefix() + "animates the weights of " + nodeWhat + ", whose mesh has no morph targets");
            if (property == animation::AnimatedProperty::Weights) width = uint32_t(targets);
            else if (element >= targets)
                mCtx.fail(prefix() + "animates weight " + std::to_string(element) + " of " + nodeWhat + ", whose mesh has " +
                          std::to_string(targets) + " morph targets");
        }
        read(sampler, property, width);
        const int32_t sceneNode = mSceneNode[node];
        if (sceneNode < 0) return;  // a node outside the loaded scene: nothing drawn moves
        mOut.channels.push_back({.sampler = uint32_t(sampler), .node = uint32_t(sceneNode), .property = property, .element = element});
    }

    // A pointer to a mesh's weights: the default weights of every node using the mesh without
    // weights of its own.
    void meshChannel(size_t sampler, const scene::PointerTarget& target) {
        if (target.index >= mModel.meshes.size()) missing("mesh", target.index);
        const size_t targets = targetCount(mModel, int(target.index));
        const std::string meshWhat = label("mesh", int(target.index), mModel.meshes[target.index].name);
        if (targets == 0) mCtx.fail(prefix() + meshWhat + " has no morph targets");
        if (target.property == animation::AnimatedProperty::Weight && target.element >= targets)
            mCtx.fail(prefix() + meshWhat + " has " + std::to_string(targets) + " morph targets");
        read(sampler, target.property, target.property == animation::AnimatedProperty::Weights ? uint32_t(targets) : 1);
        for (size_t n = 0; n < mModel.nodes.size(); ++n) {
            const tinygltf::Node& node = mModel.nodes[n];
            if (node.mesh != int(target.index) || !node.weights.empty() || mSceneNode[n] < 0) continue;
            mOut.channels.push_back({.sampler = uint32_t(sampler), .node = uint32_t(mSceneNode[n]), .property = target.property,
                                     .element = target.element});
        }
    }

    void propertyChannel(size_t sampler, scene::AnimatedObject object, const scene::PointerTarget& target) {
        read(sampler, animation::AnimatedProperty::Values, scene::pointerWidth(target));
        mOut.properties.push_back({.sampler = uint32_t(sampler), .object = uint8_t(object), .index = target.index, .field = target.field});
    }

    // Reads sampler `s` for `property` with `width` values, once: a sampler shared by channels
    // must suit each.
    void read(size_t s, animation::AnimatedProperty property, uint32_t width) {
        const tinygltf::AnimationSampler& source = mSource.samplers[s];
        const std::string samplerWhat = mWhat + " sampler " + std::to_string(s);
        // KHR_animation_pointer: a bool property takes STEP interpolation.
        if (property == animation::AnimatedProperty::Visibility && source.interpolation != "STEP")
            mCtx.fail(prefix() + "a visibility is a bool: sampler " + std::to_string(s) + " must use STEP interpolation, not " +
                      source.interpolation.substr(0, 32));
        const int type = outputType(property, width);
        if (mPointer && anyComponentType(property)) {
            const tinygltf::Accessor& output = checkedAccessor(mCtx, mModel, source.output, samplerWhat + " output");
            if (output.type != type)
                mCtx.fail(prefix() + "takes " + typeName(type) + " values, but sampler " + std::to_string(s) + "'s output accessor " +
                          std::to_string(source.output) + " is " + typeName(output.type));
        }
        const auto as = std::tuple(type, width, anyComponentType(property));
        if (!mReadAs[s]) {
            mOut.samplers[s] = readSampler(mCtx, mModel, source, property, width, samplerWhat);
            mReadAs[s] = as;
        } else if (*mReadAs[s] != as) {
            mCtx.fail(mChannelWhat + ": sampler " + std::to_string(s) + " is shared with a channel of another value type");
        } else if (const std::string problem = animation::samplerProblem(mOut.samplers[s], property); !problem.empty()) {
            mCtx.fail(samplerWhat + ": " + problem);
        }
    }

    const LoadContext& mCtx;
    const tinygltf::Model& mModel;
    const std::vector<int32_t>& mSceneNode;  // glTF node → Scene::nodes index (-1: not in the loaded scene)
    const tinygltf::Animation& mSource;
    const std::string mWhat;
    animation::Animation& mOut;
    // The output type, width and reader each sampler was read with.
    std::vector<std::optional<std::tuple<int, uint32_t, bool>>> mReadAs;
    std::string mChannelWhat;               // the channel being read
    const std::string* mPointer = nullptr;  // its pointer, if it has one
};

}  // namespace

std::vector<uint8_t> animatedNodes(const tinygltf::Model& model) {
    std::vector<uint8_t> out(model.nodes.size(), 0);
    const auto mark = [&](int node) {
        if (node >= 0 && size_t(node) < out.size()) out[size_t(node)] = 1;
    };
    for (const tinygltf::Animation& animation : model.animations)
        for (const tinygltf::AnimationChannel& channel : animation.channels) {
            if (!pointerOf(channel)) {
                mark(channel.target_node);
                continue;
            }
            const std::optional<scene::PointerTarget> target = parsedPointer(channel);
            if (target && target->kind == scene::PointerKind::Node) mark(int(target->index));
            if (target && target->kind == scene::PointerKind::Mesh)
                for (size_t n = 0; n < model.nodes.size(); ++n)
                    if (model.nodes[n].mesh == int(target->index)) out[n] = 1;
        }
    return out;
}

void noteAnimatedMaterials(const tinygltf::Model& model, scene::Scene& scene) {
    std::vector<std::vector<uint16_t>> fields(std::min(model.materials.size(), scene.materials.size()));
    for (const tinygltf::Animation& animation : model.animations)
        for (const tinygltf::AnimationChannel& channel : animation.channels)
            if (const std::optional<scene::PointerTarget> target = parsedPointer(channel);
                target && target->kind == scene::PointerKind::Material && target->index < fields.size())
                fields[target->index].push_back(target->field);
    for (size_t m = 0; m < fields.size(); ++m) {
        if (fields[m].empty()) continue;
        scene::Material& material = scene.materials[m];
        material.animatedLayers = scene::layersAnimationMayNeed(material, fields[m]) & ~material.layers();
    }
}

void loadAnimations(const LoadContext& ctx, const tinygltf::Model& model, scene::Scene& scene) {
    // glTF node → Scene::nodes index (-1: not in the loaded scene).
    std::vector<int32_t> sceneNode(model.nodes.size(), -1);
    for (size_t i = 0; i < scene.nodes.size(); ++i) sceneNode[size_t(scene.nodes[i].source)] = int32_t(i);

    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& source = model.animations[a];
        animation::Animation animation{.name = source.name.empty() ? "animation " + std::to_string(a) : source.name};
        AnimationReader reader(ctx, model, sceneNode, source, label("animation", int(a), source.name), animation);
        for (size_t c = 0; c < source.channels.size(); ++c) reader.channel(c);
        for (const animation::AnimationChannel& channel : animation.channels)
            animation.duration = std::max(animation.duration, double(animation.samplers[channel.sampler].times.back()));
        for (const animation::PropertyChannel& channel : animation.properties)
            animation.duration = std::max(animation.duration, double(animation.samplers[channel.sampler].times.back()));
        scene.animations.push_back(std::move(animation));
    }
}

}  // namespace candela::assets::gltf
