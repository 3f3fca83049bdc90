#pragma once
// ScenePose: a scene as its playing animations pose it at one time — the node tree with the
// animations applied and the draws, lights and cameras that hang from the moved nodes placed
// anew (hidden where KHR_node_visibility hides their node), and the materials, lights and cameras
// whose properties KHR_animation_pointer animates, with those properties written. Only animated
// nodes and their descendants are re-evaluated; everything else keeps the loaded rest pose. Pure
// CPU, no Vulkan: the renderer turns the posed draws, materials and lights into this frame's data.
//
//   ScenePose pose(scene, selectAnimations(scene, {"all"}));
//   pose.evaluate(12.5);                 // each animation loops over its own duration
//   for (const Draw& d : pose.draws()) … // d.world, d.flipWinding, d.bounds, d.hidden

#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace candela::pose {

// The animations named by `names` (each an index, a name, "all" or "none"; the empty list means
// animation 0 when the scene has any), ascending and without repeats. Throws UserError naming the
// scene's animations for a name or index that does not exist.
std::vector<uint32_t> selectAnimations(const scene::Scene& scene, std::span<const std::string> names);

class ScenePose {
public:
    // Poses `scene` (which must outlive the pose) with the animations `playing` (indices into
    // scene.animations, each valid), at time 0 until evaluate() is called.
    ScenePose(const scene::Scene& scene, std::vector<uint32_t> playing);

    // Applies every playing animation at `time` seconds — wrapped into each animation's own
    // duration when `loop` (as the Khronos sample viewer and three.js play them), else clamped at
    // its ends — re-places what hangs from the animated nodes and writes the animated properties.
    void evaluate(double time, bool loop = true);

    // True when some playing animation moves a node of the scene (its transform, weights or
    // visibility) or animates a property of a material, light or camera (else the pose is the rest
    // pose).
    bool animated() const { return movesNodes() || mAnimatesProperties; }
    // True when some playing animation moves a node (the draws then need this pose's matrices).
    bool movesNodes() const { return !mDependent.empty(); }
    const std::vector<uint32_t>& playing() const { return mPlaying; }
    double time() const { return mTime; }
    // The longest duration among the playing animations, seconds (0 without any).
    double duration() const;

    const scene::Scene& scene() const { return *mScene; }
    const std::vector<animation::SceneNode>& nodes() const { return mNodes; }
    const std::vector<scene::Draw>& draws() const { return mDraws; }
    const std::vector<scene::Light>& lights() const { return mLights; }
    const std::vector<scene::Camera>& cameras() const { return mCameras; }
    const std::vector<scene::Material>& materials() const { return mMaterials; }
    // Which draws / lights follow an animated node (indices, ascending): their placement and
    // their `hidden` (KHR_node_visibility) change with the pose.
    const std::vector<uint32_t>& animatedDraws() const { return mAnimatedDraws; }
    const std::vector<uint32_t>& animatedLights() const { return mAnimatedLights; }
    // Which materials, lights and cameras have a property some playing animation drives
    // (KHR_animation_pointer; indices into materials(), lights(), cameras(), ascending).
    const std::vector<uint32_t>& animatedMaterials() const { return mAnimatedMaterials; }
    const std::vector<uint32_t>& animatedLightProperties() const { return mPropertyLights; }
    const std::vector<uint32_t>& animatedCameraProperties() const { return mPropertyCameras; }
    // True when an animated material field lives in the layer data (shading::MaterialLayerData).
    bool animatesMaterialLayers() const { return mAnimatesLayers; }
    // The joint matrices (world · inverse bind) of Scene::skins[skin] in this pose.
    const std::vector<glm::dmat4>& jointMatrices(uint32_t skin) const { return mJoints[skin]; }
    // The morph weights of a draw's node in this pose (empty without morph targets).
    std::span<const float> weights(const scene::Draw& draw) const;
    // The visible draws whose vertices must be deformed in this pose: skinned ones, and those with
    // a non-zero morph weight (a morphed mesh at all-zero weights is its rest geometry).
    std::vector<uint32_t> deformedDraws() const;

    // The bounds of the visible draws in this pose (the union of their boxes: what culling uses;
    // framing fits the vertices themselves, pose/shown_points.h).
    scene::Aabb bounds() const;

private:
    // Places draw `d` from the current nodes (and joints, when skinned); hidden when its node is
    // not shown.
    void place(uint32_t d);
    // Writes the property channels of `animation` at `time` (already looped or clamped).
    void applyProperties(const animation::Animation& animation, double time);

    const scene::Scene* mScene;
    std::vector<uint32_t> mPlaying;
    std::vector<animation::SceneNode> mNodes;
    std::vector<uint32_t> mDependent;  // dependentNodes of the animated nodes
    std::vector<scene::Draw> mDraws;
    std::vector<scene::Light> mLights;
    std::vector<scene::Camera> mCameras;
    std::vector<scene::Material> mMaterials;
    std::vector<uint32_t> mAnimatedDraws, mAnimatedLights, mAnimatedCameras;
    // Property channels: whether the playing animations have any; per glTF light / camera
    // (PropertyChannel::index) the lights / cameras loaded from it; what they animate.
    bool mAnimatesProperties = false;
    std::vector<std::vector<uint32_t>> mLightsOf, mCamerasOf;
    std::vector<uint32_t> mAnimatedMaterials, mPropertyLights, mPropertyCameras;
    bool mAnimatesLayers = false;
    std::vector<std::vector<glm::dmat4>> mJoints;     // per skin
    std::vector<uint32_t> mMovedSkins;                // skins with a joint some playing animation moves
    std::vector<std::vector<scene::Aabb>> mJointBounds;  // per draw (empty unless skinned)
    double mTime = 0.0;
    bool mLoop = true;
};

}  // namespace candela::pose
