#pragma once
// Picking: which draw of a scene a ray hits first (the material inspector's click on a mesh).
// CPU ray casting against the scene's triangles (bounding boxes first); pure, no GPU.

#include "pose/scene_pose.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <optional>

namespace candela::pose {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit
};

// The ray through pixel centre-relative position `ndc` ∈ [-1, 1]² (x right, y down, Vulkan's clip
// space) of `view` (perspective, reverse-Z).
Ray viewRay(const scene::ViewSetup& view, const glm::vec2& ndc);

struct Pick {
    uint32_t draw = 0;    // index into Scene::draws
    float distance = 0.0f;
};

// The nearest draw whose triangles (both faces) the ray hits, if any.
std::optional<Pick> pickDraw(const scene::Scene& scene, const Ray& ray);
// The same in a pose of `scene`: posed draws, skinned and morphed meshes as deformed this frame
// (on the CPU, pose/skinning.h); hidden draws are not hit. Pick::draw indexes pose.draws().
std::optional<Pick> pickDraw(const scene::Scene& scene, const ScenePose& pose, const Ray& ray);

}  // namespace candela::pose
