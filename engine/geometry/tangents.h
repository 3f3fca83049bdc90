#pragma once
// Tangent generation compatible with MikkTSpace (Morten S. Mikkelsen's reference implementation,
// mikktspace.c, at its default 180° angular threshold), which the glTF specification asks for when
// a primitive has a normal texture but no TANGENT attribute. Debian 12 packages no MikkTSpace, so
// this is a compact reimplementation of the same steps:
//   weld corners with identical position, normal and texcoord;
//   per triangle, the texture-space tangent and bitangent directions and the orientation
//   (sign of the texture-space area);
//   group the triangles around each welded vertex that are connected through shared edges and have
//   the same orientation (triangles with no usable texture area join any group);
//   per group, the corner-angle-weighted sum of the per-triangle tangents projected into the
//   vertex normal's plane; triangles with coincident positions copy a neighbour's result.
// Left out: MikkTSpace's quad handling (glTF has only triangles) and its sub-group split, which
// at the default threshold only separates exactly opposite tangents.
//
// Texture coordinates are glTF's (origin top-left). MikkTSpace assumes a bottom-left origin, so v is
// negated on input; this is what three.js's computeMikkTSpaceTangents(negateSign = true) does for
// glTF, and matches tangents exported by Blender.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace candela::geometry {

// One tangent per element of `indices` (a triangle list; a trailing partial triangle is ignored and
// gets the fallback tangent). xyz is unit length and orthogonal to the vertex normal; w = ±1 with
// the glTF convention bitangent = cross(normal, tangent.xyz) * w, which points toward decreasing v.
// Corners whose tangent is undefined (no texture-space extent anywhere around them) get an
// arbitrary unit tangent orthogonal to the normal and w = +1.
// Preconditions: positions, normals and uvs have one entry per vertex; every index is in range;
// all values finite; normals unit length or zero.
std::vector<glm::vec4> generateTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> uvs, std::span<const uint32_t> indices);

// A unit vector orthogonal to `normal` (any unit vector if normal is zero), as w = +1 tangent.
glm::vec4 fallbackTangent(const glm::vec3& normal);

}  // namespace candela::geometry
