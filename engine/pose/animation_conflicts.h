#pragma once
// Which channels several playing animations drive at once, and which of them wins. The glTF
// specification leaves playing more than one animation to the application; Candela applies the
// playing animations in the order they come in the file (ScenePose::evaluate), each writing its
// channels in full — no blending — so on a channel that several drive, the one that comes last in
// the file wins (its value is the one drawn). Fox's three clips (Survey, Walk, Run) all drive the
// same 24 joints: `--animation all` shows Run. Pure CPU, no Vulkan.
//
//   const auto conflicts = animationConflicts(scene, pose.playing());
//   if (!conflicts.empty()) log::warn(describeAnimationConflicts(scene, conflicts));

#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace candela::pose {

// One channel driven by more than one playing animation.
struct AnimationConflict {
    std::string channel;               // what it drives: "rotation of 'b_Hip_01'", "/materials/0/emissiveFactor"
    std::vector<uint32_t> animations;  // the playing animations that drive it, ascending: the last one wins
};

// The channels of `scene` that more than one of the animations `playing` (indices into
// scene.animations, each valid) drive, in the order of the first animation's channels (node
// channels, then KHR_animation_pointer property channels). A channel is a node's translation,
// rotation, scale, visibility or morph weights (a weights channel overlaps every single-weight
// channel of the same node), or a material, light or camera field. Empty when every channel has
// at most one driver (one animation, or animations on disjoint channels).
std::vector<AnimationConflict> animationConflicts(const scene::Scene& scene, std::span<const uint32_t> playing);

// One line for the user ("" when `conflicts` is empty): which animations overlap, on how many
// channels (the first named), and which wins — e.g. "animations 'Survey', 'Walk' and 'Run' drive
// the same 24 channels (rotation of 'b_Hip_01', ...); 'Run' wins (the last in the file; animations
// are applied in file order, not blended)".
std::string describeAnimationConflicts(const scene::Scene& scene, std::span<const AnimationConflict> conflicts);

}  // namespace candela::pose
