#pragma once
// Internal to the glTF loader: a primitive's morph targets and skin weights (JOINTS_n/WEIGHTS_n),
// read in the file's vertex order and then carried over to the converted vertices.

#include "assets/gltf_context.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace candela::assets::gltf {

struct SourceDeformation {
    uint32_t targetCount = 0;
    std::vector<scene::MorphDelta> deltas;  // targetCount × vertexCount, target-major
    uint32_t influencesPerVertex = 0;
    std::vector<scene::JointInfluence> influences;  // vertexCount × influencesPerVertex
    uint32_t maxJoint = 0;                   // the largest joint index with a non-zero weight
    size_t renormalized = 0;  // vertices whose weights summed to more than 1% off 1 (renormalized)
    bool empty() const { return targetCount == 0 && influencesPerVertex == 0; }
};

// Reads the morph targets (POSITION, NORMAL, TANGENT, TEXCOORD_0/1 and COLOR_0 deltas; sparse
// accessors included) and the JOINTS_n/WEIGHTS_n sets of a primitive with `vertexCount` vertices.
// Weights are renormalized to sum to 1. Throws UserError (via ctx) for: a target or set whose
// count differs from the vertex count, JOINTS not VEC4 of UNSIGNED_BYTE/SHORT, WEIGHTS not VEC4 of
// FLOAT or normalized UNSIGNED_BYTE/SHORT, a JOINTS_n without its WEIGHTS_n, non-finite or negative
// weights, a vertex whose weights are all zero, non-finite deltas.
SourceDeformation readDeformation(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                  const std::string& what, size_t vertexCount);

// The deformation of the converted vertices [firstVertex, firstVertex + origin.size()), vertex v
// taking the data of source vertex origin[v].
scene::Deformation remapDeformation(const SourceDeformation& source, std::span<const uint32_t> origin, uint32_t firstVertex);

}  // namespace candela::assets::gltf
