#pragma once
// Where a draw, a light or a camera is once its node's world transform is known. Shared by the
// glTF loader (the rest pose) and ScenePose (every animated frame), so both place things alike.
// Pure: no Vulkan.

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <span>

namespace candela::pose {

enum class Placement : uint8_t {
    Placed,
    Singular,     // a zero scale on some axis (here or inherited): nothing to see, no normal matrix
    BeyondFloat,  // the world matrix or a corner of the mesh does not fit a float
};

// Sets draw.world, draw.flipWinding and draw.bounds (from draw.localBounds grown by `reach`, how
// far morph targets move its vertices) for `world`, and draw.hidden unless the result is Placed.
// The determinant and the box are computed in double.
// For an instanced draw `instances` are its instance matrices (Scene::instances slice): the bounds
// hold every instance and the winding follows world · instance 0 (the loader keeps a draw's
// instances alike).
Placement placeDraw(scene::Draw& draw, const glm::dmat4& world, const glm::vec3& reach = glm::vec3(0.0f),
                    std::span<const glm::mat4> instances = {});

// A skinned draw: its vertices are placed in world space by the joints, so its world matrix is
// the identity; `bounds` (pose/skinning.h skinnedBounds) become its bounds. Hidden when they are
// invalid or beyond a float.
Placement placeSkinnedDraw(scene::Draw& draw, const scene::Aabb& bounds);

// Sets the light's position and direction (its node's −Z) from `world`; a direction that cannot be
// normalized stays −Z.
void placeLight(scene::Light& light, const glm::dmat4& world);

// Sets camera.world to `world` without scale (glTF cameras ignore it). False, leaving the camera
// unchanged, when an axis has zero or non-finite length.
bool placeCamera(scene::Camera& camera, const glm::dmat4& world);

}  // namespace candela::pose
