#pragma once
// Normals for primitives that come without them. The glTF specification asks for flat normals
// ("client implementations MUST calculate flat normals") and to ignore any provided tangents then.

#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace candela::geometry {

// Rewrites `vertices`/`indices` (a triangle list) so each triangle owns three vertices carrying its
// geometric normal (counter-clockwise front face). Other attributes are copied; tangents are reset
// to the default. Triangles with no area (or non-finite cross products) get +Z. A trailing partial
// triangle is dropped. `origin` (one entry per vertex: the source vertex it was made from) is
// rewritten alongside. Precondition: every index < vertices.size() == origin.size().
void makeFlatNormals(std::vector<scene::Vertex>& vertices, std::vector<uint32_t>& indices, std::vector<uint32_t>& origin);

// `v` scaled to unit length without overflow or underflow (its length may be anywhere in the float
// range, where dot(v, v) would overflow to Inf or underflow to 0); zero stays zero.
// Precondition: v is finite.
glm::vec3 normalizeOrZero(const glm::vec3& v);

// The unit normal of triangle (a, b, c) by the right-hand rule, or +Z if it has no area.
glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

}  // namespace candela::geometry
