#include "pose/scene_pose.h"

#include "core/errors.h"
#include "pose/node_placement.h"
#include "pose/skinning.h"
#include "scene/animated_properties.h"

#include <algorithm>
#include <charconv>
#include <set>

namespace candela::pose {
namespace {

// Indices of the items whose node is marked in `moved` (one flag per node).
template <typename T>
std::vector<uint32_t> onMovedNodes(const std::vector<T>& items, const std::vector<uint8_t>& moved) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < items.size(); ++i)
        if (items[i].node >= 0 && size_t(items[i].node) < moved.size() && moved[size_t(items[i].node)]) out.push_back(i);
    return out;
}

// Per source index (Light::source, Camera::source) the items loaded from it.
template <typename T>
std::vector<std::vector<uint32_t>> bySource(const std::vector<T>& items) {
    std::vector<std::vector<uint32_t>> out;
    for (uint32_t i = 0; i < items.size(); ++i) {
        if (items[i].source < 0) continue;
        if (size_t(items[i].source) >= out.size()) out.resize(size_t(items[i].source) + 1);
        out[size_t(items[i].source)].push_back(i);
    }
    return out;
}

// `list` sorted, without repeats.
std::vector<uint32_t> sortedSet(std::vector<uint32_t> list) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    return list;
}

std::string animationList(const scene::Scene& scene) {
    if (scene.animations.empty()) return "the scene has no animations";
    std::string out = "its animations: ";
    for (size_t i = 0; i < scene.animations.size(); ++i)
        out += (i ? ", " : "") + std::to_string(i) + " '" + scene.animations[i].name + "'";
    return out;
}

}  // namespace

std::vector<uint32_t> selectAnimations(const scene::Scene& scene, std::span<const std::string> names) {
    std::set<uint32_t> chosen;
    if (names.empty()) {
        if (!scene.animations.empty()) chosen.insert(0);
        return {chosen.begin(), chosen.end()};
    }
    for (const std::string& name : names) {
        if (name == "none") continue;
        if (name == "all") {
            for (uint32_t i = 0; i < scene.animations.size(); ++i) chosen.insert(i);
            continue;
        }
        uint32_t index = 0;
        const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), index);
        if (error == std::errc() && end == name.data() + name.size()) {
            if (index >= scene.animations.size())
                throw UserError("no animation " + name + " (" + animationList(scene) + ")");
            chosen.insert(index);
            continue;
        }
        const auto it = std::find_if(scene.animations.begin(), scene.animations.end(),
                                     [&](const animation::Animation& a) { return a.name == name; });
        if (it == scene.animations.end()) throw UserError("no animation named '" + name + "' (" + animationList(scene) + ")");
        chosen.insert(uint32_t(it - scene.animations.begin()));
    }
    return {chosen.begin(), chosen.end()};
}

ScenePose::ScenePose(const scene::Scene& scene, std::vector<uint32_t> playing)
    : mScene(&scene), mPlaying(std::move(playing)), mNodes(scene.nodes), mDraws(scene.draws), mLights(scene.lights),
      mCameras(scene.cameras), mMaterials(scene.materials), mLightsOf(bySource(scene.lights)), mCamerasOf(bySource(scene.cameras)) {
    std::vector<uint32_t> targets;
    for (uint32_t a : mPlaying) {
        for (const animation::AnimationChannel& channel : scene.animations[a].channels) targets.push_back(channel.node);
        for (const animation::PropertyChannel& p : scene.animations[a].properties) {
            mAnimatesProperties = true;
            const auto of = [&](const std::vector<std::vector<uint32_t>>& bySource) {
                return p.index < bySource.size() ? bySource[p.index] : std::vector<uint32_t>{};
            };
            switch (scene::AnimatedObject(p.object)) {
                case scene::AnimatedObject::Material:
                    if (p.index >= mMaterials.size() || p.field >= scene::materialFields().size()) break;  // (the loader's are valid)
                    mAnimatedMaterials.push_back(p.index);
                    mAnimatesLayers = mAnimatesLayers || scene::materialFields()[p.field].layerData;
                    break;
                case scene::AnimatedObject::Light:
                    for (uint32_t l : of(mLightsOf)) mPropertyLights.push_back(l);
                    break;
                case scene::AnimatedObject::Camera:
                    for (uint32_t c : of(mCamerasOf)) mPropertyCameras.push_back(c);
                    break;
            }
        }
    }
    mAnimatedMaterials = sortedSet(std::move(mAnimatedMaterials));
    mPropertyLights = sortedSet(std::move(mPropertyLights));
    mPropertyCameras = sortedSet(std::move(mPropertyCameras));
    mDependent = animation::dependentNodes(mNodes, targets);
    std::vector<uint8_t> moved(mNodes.size(), 0);
    for (uint32_t node : mDependent) moved[node] = 1;
    mAnimatedDraws = onMovedNodes(mDraws, moved);
    // A skinned draw moves with its joints, wherever its own node is.
    mJoints.resize(scene.skins.size());
    mJointBounds.resize(mDraws.size());
    std::vector<uint8_t> skinMoved(scene.skins.size(), 0);
    for (size_t s = 0; s < scene.skins.size(); ++s) {
        pose::jointMatrices(scene.skins[s], mNodes, mJoints[s]);
        for (uint32_t joint : scene.skins[s].joints) skinMoved[s] |= moved[joint];
        if (skinMoved[s]) mMovedSkins.push_back(uint32_t(s));
    }
    for (uint32_t d = 0; d < mDraws.size(); ++d) {
        const scene::Draw& draw = mDraws[d];
        if (draw.skin < 0) continue;
        mJointBounds[d] = jointMeshBounds(scene.deformations[size_t(draw.deformation)], scene.skins[size_t(draw.skin)], scene.vertices);
        if (skinMoved[size_t(draw.skin)] && !std::binary_search(mAnimatedDraws.begin(), mAnimatedDraws.end(), d))
            mAnimatedDraws.insert(std::upper_bound(mAnimatedDraws.begin(), mAnimatedDraws.end(), d), d);
    }
    mAnimatedLights = onMovedNodes(mLights, moved);
    mAnimatedCameras = onMovedNodes(mCameras, moved);
    evaluate(0.0);
}

double ScenePose::duration() const {
    double longest = 0.0;
    for (uint32_t a : mPlaying) longest = std::max(longest, mScene->animations[a].duration);
    return longest;
}

void ScenePose::evaluate(double time, bool loop) {
    mTime = time;
    mLoop = loop;
    if (!animated()) return;
    for (uint32_t a : mPlaying) {
        const animation::Animation& animation = mScene->animations[a];
        const double at = loop ? animation::loopTime(time, animation.duration) : time;
        animation::applyAnimation(animation, at, mNodes);
        applyProperties(animation, at);
    }
    if (!movesNodes()) return;
    animation::updateWorldTransforms(mNodes, mDependent);
    for (uint32_t s : mMovedSkins) pose::jointMatrices(mScene->skins[s], mNodes, mJoints[s]);
    for (uint32_t d : mAnimatedDraws) place(d);
    for (uint32_t l : mAnimatedLights) {
        const animation::SceneNode& node = mNodes[size_t(mLights[l].node)];
        placeLight(mLights[l], node.world);
        mLights[l].hidden = !node.shown;
    }
    // A camera whose node is scaled to nothing keeps its last placement (visibility does not
    // affect cameras).
    for (uint32_t c : mAnimatedCameras) placeCamera(mCameras[c], mNodes[size_t(mCameras[c].node)].world);
}

void ScenePose::applyProperties(const animation::Animation& animation, double time) {
    float value[4];
    for (const animation::PropertyChannel& p : animation.properties) {
        const animation::AnimationSampler& sampler = animation.samplers[p.sampler];
        const std::span<const float> values(value, sampler.width);
        animation::evaluateSampler(sampler, animation::AnimatedProperty::Values, time, std::span<float>(value, sampler.width));
        switch (scene::AnimatedObject(p.object)) {
            case scene::AnimatedObject::Material:
                if (p.index < mMaterials.size()) writeMaterial(mMaterials[p.index], p.field, values);
                break;
            case scene::AnimatedObject::Light:
                if (p.index < mLightsOf.size())
                    for (uint32_t l : mLightsOf[p.index]) writeLight(mLights[l], p.field, values);
                break;
            case scene::AnimatedObject::Camera:
                if (p.index < mCamerasOf.size())
                    for (uint32_t c : mCamerasOf[p.index]) writeCamera(mCameras[c], p.field, values);
                break;
        }
    }
}

void ScenePose::place(uint32_t d) {
    scene::Draw& draw = mDraws[d];
    const glm::vec3 reach =
        draw.deformation >= 0 ? morphReach(mScene->deformations[size_t(draw.deformation)], weights(draw)) : glm::vec3(0.0f);
    if (draw.skin >= 0) placeSkinnedDraw(draw, skinnedBounds(mJointBounds[d], mJoints[size_t(draw.skin)], reach));
    else placeDraw(draw, mNodes[size_t(draw.node)].world, reach,
                   std::span(mScene->instances).subspan(draw.firstInstance, draw.instanceCount));
    // KHR_node_visibility: the mesh's own node decides, skinned or not.
    if (draw.node >= 0 && !mNodes[size_t(draw.node)].shown) draw.hidden = true;
}

std::span<const float> ScenePose::weights(const scene::Draw& draw) const {
    if (draw.node < 0) return {};
    return mNodes[size_t(draw.node)].weights;
}

std::vector<uint32_t> ScenePose::deformedDraws() const {
    std::vector<uint32_t> out;
    for (uint32_t d = 0; d < mDraws.size(); ++d) {
        const scene::Draw& draw = mDraws[d];
        if (draw.hidden || draw.deformation < 0) continue;
        const std::span<const float> w = weights(draw);
        const bool morphed = mScene->deformations[size_t(draw.deformation)].targetCount > 0 &&
                             std::any_of(w.begin(), w.end(), [](float x) { return x != 0.0f; });
        if (draw.skin >= 0 || morphed) out.push_back(d);
    }
    return out;
}

scene::Aabb ScenePose::bounds() const {
    scene::Aabb out;
    for (const scene::Draw& d : mDraws)
        if (!d.hidden) out.extend(d.bounds);
    return out;
}

}  // namespace candela::pose
