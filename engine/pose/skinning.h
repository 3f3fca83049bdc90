#pragma once
// Skinning and morphing on the CPU: the joint matrices of a pose, the bounds of a deformed draw,
// and — as the double-precision reference the GPU's skin_morph pass is tested against, and for
// picking the posed mesh — the deformed vertices themselves. Pure: no Vulkan.
//
// The deformation of vertex v (glTF 2.0 §3.7.3 and §3.8.3): morph first, then skin,
//   p' = Σ_i w_i J_i (p + Σ_t m_t Δp_t),   J_i = world(joint_i) · inverseBind_i,
// normals by the cofactor of the blended 3×3 matrix M = Σ_i w_i J_i (correct under non-uniform
// scale), tangents by M; unskinned draws keep p + Σ_t m_t Δp and their node's world matrix.

#include "scene/scene.h"

#include <span>
#include <vector>

namespace candela::pose {

// J_i = world(joint_i) · inverseBind_i for every joint of `skin`, into `out`.
void jointMatrices(const scene::Skin& skin, const std::vector<animation::SceneNode>& nodes, std::vector<glm::dmat4>& out);

// Per joint of `skin`, the mesh-space box of the rest-pose vertices it pulls on with a non-zero
// weight; invalid for joints that pull on none.
std::vector<scene::Aabb> jointMeshBounds(const scene::Deformation& deformation, const scene::Skin& skin, std::span<const scene::Vertex> vertices);

// How far the morph targets at `weights` can move a vertex, per axis, in mesh space.
glm::vec3 morphReach(const scene::Deformation& deformation, std::span<const float> weights);

// World bounds of a skinned draw: each joint's mesh-space box, grown by the morph reach, placed
// by that joint's matrix. Contains every deformed vertex: each is a convex combination of its
// joints' placements of it.
scene::Aabb skinnedBounds(std::span<const scene::Aabb> jointBounds, std::span<const glm::dmat4> joints, const glm::vec3& reach);

// The vertices of `draw`'s deformation range as the GPU pass computes them, in double precision:
// morphed with `weights` (one per target), then skinned with `joints` when the draw is skinned
// (world space), else left in mesh space. Precondition: draw.deformation >= 0.
std::vector<scene::Vertex> deformVertices(const scene::Scene& scene, const scene::Draw& draw, std::span<const float> weights,
                                   std::span<const glm::dmat4> joints);

}  // namespace candela::pose
