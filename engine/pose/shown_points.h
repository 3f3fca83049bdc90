#pragma once
// The points framing fits (scene/framing.h): the world-space positions of the vertices a scene
// shows, as it draws them — every draw not hidden, each vertex of its range placed by its node's
// world matrix (and by each of its instances), skinned and morphed vertices deformed as the
// skin_morph pass deforms them (positions only). Any function of these points is the same for every
// structure of a file that draws the same image. Pure CPU, no Vulkan.

#include "pose/scene_pose.h"
#include "scene/framing.h"

#include <span>
#include <vector>

namespace candela::pose {

// The vertices of `draw` in world space, in batches: the lowest to the highest vertex its indices
// name (a deformed draw: its deformation's range), morphed by `weights` (one per target; fewer:
// the rest 0), then skinned by `joints` (Skin order) when draw.skin >= 0, else placed by draw.world
// and each of its instances.
void visitDrawPoints(const scene::Scene& scene, const scene::Draw& draw, std::span<const float> weights,
                     std::span<const glm::dmat4> joints, const scene::PointBatch& visit);

// The points of the scene as loaded (the rest pose: the nodes' morph weights, the skins' joints
// where the nodes stand), of each draw not hidden, or of every draw with `includeHidden`.
void visitShownPoints(const scene::Scene& scene, const scene::PointBatch& visit, bool includeHidden = false);
// The points of `pose` as it stands (its draws not hidden).
void visitShownPoints(const ScenePose& pose, const scene::PointBatch& visit);

// The smallest box holding the scene's rest-pose points (visitShownPoints above).
scene::Aabb shownBounds(const scene::Scene& scene, bool includeHidden = false);

// What framing a render of `scene` fits: with a `pose` that moves nodes and `times`, the poses at
// each of the times (a copy of `pose` evaluated at each, each animation looping over its duration
// as a render plays it, or clamped at its ends without `loop`); with no times, `pose` as it stands;
// without a pose, or one that moves no node, the rest pose. `scene` and `pose` must outlive the
// source.
scene::PointSource shownPoints(const scene::Scene& scene, const ScenePose* pose, std::vector<double> times = {},
                               bool loop = true);

// Times that span the playing animations, for framing all of them (the viewer, which plays them;
// evaluated without looping, so that each animation's last key counts):
// 0, every key time of their node channels and a step of 1/30 s up to the longest one's end; at
// most `maxTimes` (evenly spread over the duration beyond that).
std::vector<double> animationTimes(const ScenePose& pose, size_t maxTimes);

}  // namespace candela::pose
