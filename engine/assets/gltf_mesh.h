#pragma once
// Internal to the glTF loader: one mesh primitive → vertices and a triangle list in the Scene.

#include "assets/gltf_context.h"
#include "scene/scene.h"

#include <compare>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace candela::assets::gltf {

struct PrimitiveGeometry {
    bool drawable = false;  // false: skipped (no POSITION, nothing left to draw), with a warning or note
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    scene::Topology topology = scene::Topology::Triangles;
    bool unshaded = false;  // points or lines without NORMAL (scene::Draw::unshaded)
    scene::Aabb bounds;  // local (mesh) space
    int32_t deformation = -1;        // Scene::deformations entry (morph targets, skin weights)
    size_t renormalizedWeights = 0;  // vertices whose skin weights were more than 1% off 1
};

// What appendPrimitive reads of a primitive: two primitives with equal sources convert to the same
// geometry, which the loader then converts once and shares among their draws (exporters often give
// each material its own mesh over the same accessors: MetalRoughSpheresNoTextures' 98 spheres are
// one accessor set). The tangent frame generated for a normal map is part of it: its texture
// coordinate set and the linear part of its transform (an offset changes no derivative).
struct PrimitiveSource {
    int mode = 0;      // TINYGLTF_MODE_*, TRIANGLES when the primitive gives none
    int indices = -1;  // accessor, -1 for none
    std::map<std::string, int> attributes;
    std::vector<std::map<std::string, int>> targets;
    bool generatedTangents = false;  // a tangent map was given (whether or not the primitive has TANGENT)
    uint32_t tangentTexCoord = 0;
    float tangentRotation = 0.0f, tangentScaleX = 1.0f, tangentScaleY = 1.0f;
    auto operator<=>(const PrimitiveSource&) const = default;
};

// The source of primitive `primitive` of mesh `mesh` (both indices valid) converted with
// `tangentMap` (as appendPrimitive takes it).
PrimitiveSource primitiveSource(const tinygltf::Model& model, int mesh, int primitive, const scene::TextureRef* tangentMap);

// Reads primitive `primitive` of mesh `mesh` (both indices valid) and appends it to scene.vertices
// and scene.indices as a triangle, line or point list (scene::Topology), with absolute indices.
// Strips, fans and loops are converted. Triangles: normals are computed flat when absent; tangents
// are generated (MikkTSpace, on the texture coordinates of `tangentMap`) when `tangentMap` is given
// (a material of the primitive has a normal map: Material::tangentSpaceMap) and the primitive has
// no TANGENT, splitting vertices whose corners disagree. Points and lines keep their vertices:
// without NORMAL they are unshaded; with it and without TANGENT, a tangent is made from the normal.
// Throws UserError (via ctx) on malformed data: out-of-range accessors or indices, non-finite
// positions, attribute counts that differ from POSITION's.
PrimitiveGeometry appendPrimitive(const LoadContext& ctx, const tinygltf::Model& model, int mesh, int primitive,
                                  const scene::TextureRef* tangentMap, scene::Scene& scene);

// Converts an index sequence of glTF topology `mode` (TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN)
// to a triangle list with the winding the specification defines. Strip and fan triangles that
// repeat an index (degenerate stitching) are dropped; a partial trailing list triangle is dropped.
std::vector<uint32_t> toTriangleList(int mode, std::span<const uint32_t> indices);

// Converts an index sequence of glTF topology `mode` (LINES, LINE_LOOP or LINE_STRIP) to a line
// list (index pairs), as the specification defines them: a loop closes from its last index to its
// first; an odd trailing LINES index is dropped.
std::vector<uint32_t> toLineList(int mode, std::span<const uint32_t> indices);

// Removes the triangles of a triangle list whose corners are collinear or coincide (exactly zero
// area: they cover no pixel and give no normal or tangent); returns how many were removed.
// Precondition: every index < vertices.size().
size_t dropZeroAreaTriangles(std::span<const scene::Vertex> vertices, std::vector<uint32_t>& indices);

}  // namespace candela::assets::gltf
