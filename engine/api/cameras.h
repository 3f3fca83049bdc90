#pragma once
// Internal to the API (not installed): the public Camera and SequenceOptions turned into what the
// renderer takes, and the camera of a view as CameraInfo (api/cameras.cpp).

#include "candela/image.h"
#include "candela/render.h"
#include "pose/scene_pose.h"
#include "render/render_settings.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace candela {

// The renderer's camera settings for `options` (intrinsics as fractions of the image). Throws
// UserError for a matrix or intrinsics that are not finite, a singular matrix, focal lengths ≤ 0.
CameraSettings cameraSettings(const RenderOptions& options);

// The camera of `view` for an image of width × height, as the API reports it.
CameraInfo cameraInfo(const scene::ViewSetup& view, uint32_t width, uint32_t height);

// UserError for a sequence that makes no frame: 0 frames, fps ≤ 0 (without views), or a view
// direction that is not finite.
void checkSequence(const SequenceOptions& sequence);

// The camera of every frame of `sequence` (a still is a sequence of one frame). When the orbit
// camera frames the scene (no glTF or placed camera, and no distance and target given), framing is
// resolved once, over every frame's direction and every frame's pose (scene/framing.h over
// pose/shown_points.h at frameTime of each frame): the camera holds still over the sequence, at
// one distance, and every frame keeps the margin. `camera` comes back with the target, the
// distance (orbit's r) and the field of view filled in where it left them, and `framing` saying
// what was framed; as it was for a glTF or placed camera. UserError for views of a glTF or placed
// camera.
struct SequenceCamera {
    CameraSettings camera;          // frame 0's
    // Each frame's (θ°, φ°, r) for a turntable or views (it replaces camera.orbit); empty otherwise,
    // and for a turntable of a glTF or placed camera (which does not turn).
    std::vector<glm::vec3> orbits;
};
SequenceCamera sequenceCamera(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                              const pose::ScenePose& pose, const RenderOptions& options, const SequenceOptions& sequence);

// The time of frame i (views are all of one pose), and its environment's rotation (jittered with
// SequenceOptions::lightingSeed).
double frameTime(const RenderOptions& options, const SequenceOptions& sequence, uint32_t i);
float frameEnvironmentRotation(const RenderOptions& options, const SequenceOptions& sequence, uint32_t i);

}  // namespace candela
