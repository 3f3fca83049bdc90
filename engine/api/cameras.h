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

// The orbit camera's (θ°, φ°, r) for each frame of a turntable or of views, r fixed at the largest
// distance any frame's framing needs (framing from each direction would move the camera in and
// out) unless the orbit gives one; empty when the sequence is neither, or a turntable of a glTF or
// placed camera (which does not turn). UserError for views of a glTF or placed camera.
std::vector<glm::vec3> sequenceOrbits(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                      const pose::ScenePose& pose, const SequenceOptions& sequence);

// The time of frame i (views are all of one pose), and its environment's rotation (jittered with
// SequenceOptions::lightingSeed).
double frameTime(const RenderOptions& options, const SequenceOptions& sequence, uint32_t i);
float frameEnvironmentRotation(const RenderOptions& options, const SequenceOptions& sequence, uint32_t i);

}  // namespace candela
