#pragma once
// Framing resolved once for a run of frames — an image sequence, a bench run, the viewer playing
// its animations — so that the camera holds still over them and every frame keeps the margin
// (scene/framing.h). A still is a run of one frame at its time.

#include "pose/scene_pose.h"
#include "render/render_settings.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <span>

namespace candela {

// `camera` with the orbit camera's framing resolved: scene::frame over the vertices of the poses at
// `times` (a copy of `pose` evaluated at each, looping or clamped as `loop` says; the rest pose when
// the pose moves no node) seen from each of `directions` (θ°, φ°; empty: the orbit's own, or scene::defaultOrbitAngles). The result names
// the target, the orbit (directions[0], the framed distance) and the field of view wherever
// `camera` left them (a given distance keeps 45° without a given field of view), and
// CameraSettings::framing says what was framed and how. Nothing is framed when `camera` gives both
// a distance and a target. A glTF or placed camera it names is kept (it takes precedence where the
// view is resolved); an interactive one (CameraSettings::orbitCamera) returns it unchanged.
CameraSettings resolveFraming(const scene::Scene& scene, const CameraSettings& camera, float aspect, const pose::ScenePose* pose,
                              std::span<const double> times, std::span<const glm::vec2> directions = {}, bool loop = true);

}  // namespace candela
