#include "scene/scene_pose.h"

#include "core/check.h"
#include "scene/node_placement.h"

#include <algorithm>
#include <charconv>
#include <set>

namespace candela::scene {
namespace {

// Indices of the items whose node is marked in `moved` (one flag per node).
template <typename T>
std::vector<uint32_t> onMovedNodes(const std::vector<T>& items, const std::vector<uint8_t>& moved) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < items.size(); ++i)
        if (items[i].node >= 0 && size_t(items[i].node) < moved.size() && moved[size_t(items[i].node)]) out.push_back(i);
    return out;
}

std::string animationList(const Scene& scene) {
    if (scene.animations.empty()) return "the scene has no animations";
    std::string out = "its animations: ";
    for (size_t i = 0; i < scene.animations.size(); ++i)
        out += (i ? ", " : "") + std::to_string(i) + " '" + scene.animations[i].name + "'";
    return out;
}

}  // namespace

std::vector<uint32_t> selectAnimations(const Scene& scene, std::span<const std::string> names) {
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
                                     [&](const Animation& a) { return a.name == name; });
        if (it == scene.animations.end()) throw UserError("no animation named '" + name + "' (" + animationList(scene) + ")");
        chosen.insert(uint32_t(it - scene.animations.begin()));
    }
    return {chosen.begin(), chosen.end()};
}

ScenePose::ScenePose(const Scene& scene, std::vector<uint32_t> playing)
    : mScene(&scene), mPlaying(std::move(playing)), mNodes(scene.nodes), mDraws(scene.draws), mLights(scene.lights),
      mCameras(scene.cameras) {
    std::vector<uint32_t> targets;
    for (uint32_t a : mPlaying)
        for (const AnimationChannel& channel : scene.animations[a].channels) targets.push_back(channel.node);
    mDependent = dependentNodes(mNodes, targets);
    std::vector<uint8_t> moved(mNodes.size(), 0);
    for (uint32_t node : mDependent) moved[node] = 1;
    mAnimatedDraws = onMovedNodes(mDraws, moved);
    mAnimatedLights = onMovedNodes(mLights, moved);
    mAnimatedCameras = onMovedNodes(mCameras, moved);
    mAnimationBounds = animated() ? boundsOverAnimation(1024) : scene.bounds;
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
        const Animation& animation = mScene->animations[a];
        applyAnimation(animation, loop ? loopTime(time, animation.duration) : time, mNodes);
    }
    updateWorldTransforms(mNodes, mDependent);
    for (uint32_t d : mAnimatedDraws) placeDraw(mDraws[d], mNodes[size_t(mDraws[d].node)].world);
    for (uint32_t l : mAnimatedLights) placeLight(mLights[l], mNodes[size_t(mLights[l].node)].world);
    // A camera whose node is scaled to nothing keeps its last placement.
    for (uint32_t c : mAnimatedCameras) placeCamera(mCameras[c], mNodes[size_t(mCameras[c].node)].world);
}

Aabb ScenePose::bounds() const {
    Aabb out;
    for (const Draw& d : mDraws)
        if (!d.hidden) out.extend(d.bounds);
    return out;
}

Aabb ScenePose::boundsOverAnimation(size_t maxSamples) {
    std::vector<double> times{0.0};
    for (uint32_t a : mPlaying)
        for (const AnimationChannel& channel : mScene->animations[a].channels)
            for (float t : mScene->animations[a].samplers[channel.sampler].times) times.push_back(double(t));
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    if (times.size() > maxSamples && maxSamples >= 2) {
        const double last = times.back();
        times.clear();
        for (size_t i = 0; i < maxSamples; ++i) times.push_back(last * double(i) / double(maxSamples - 1));
    }
    Aabb out;
    for (double t : times) {
        evaluate(t, /*loop=*/false);
        out.extend(bounds());
    }
    return out;
}

}  // namespace candela::scene
