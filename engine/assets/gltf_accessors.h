#pragma once
// Internal to the glTF loader: bounds-checked reading of bufferViews and accessors. Every byte range
// is checked against its buffer with overflow-safe arithmetic before anything is read, so a
// malformed file yields a UserError, never an out-of-bounds read.

#include "assets/gltf_context.h"

#include <glm/vec4.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Accessor;
}

namespace candela::assets::gltf {

// True when every component of `v` is finite (no NaN, no infinity).
inline bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// Bytes of one component of glTF componentType `componentType`; 0 for an unknown type.
size_t componentSize(int componentType);

// The name of glTF accessor type `type` ("VEC3", "MAT4"; "type 9" for an unknown one).
std::string typeName(int type);

// True for the index component types: UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT.
bool isIndexType(int componentType);

// Accessor `index` once it exists and has a known componentType; else fails via ctx naming `what`.
// The reference is into model.accessors: adding accessors invalidates it.
const tinygltf::Accessor& checkedAccessor(const LoadContext& ctx, const tinygltf::Model& model, int index,
                                          const std::string& what);

// The bytes of bufferView `view` once it is known to lie inside its buffer. `what` names the
// referrer in messages ("image 2"). The span borrows the model's buffer.
std::span<const uint8_t> bufferViewBytes(const LoadContext& ctx, const tinygltf::Model& model, int view,
                                         const std::string& what);

// Reads accessor `accessor` as count × vec4 (components beyond the accessor's type are 0). `types`
// lists the accepted accessor types (TINYGLTF_TYPE_VEC3, ...). Every glTF component type is read;
// normalized integers map to [0, 1] or [-1, 1] as the specification says, other integers convert
// to float unchanged (KHR_mesh_quantization). Sparse substitution is applied. An accessor without
// a bufferView reads as zeros. `what` names the use in messages ("mesh 0 primitive 1 POSITION").
std::vector<glm::vec4> readVectors(const LoadContext& ctx, const tinygltf::Model& model, int accessor,
                                   std::initializer_list<int> types, const std::string& what);

// Reads accessor `accessor` of glTF type `type` (TINYGLTF_TYPE_SCALAR … TINYGLTF_TYPE_MAT4, which
// it must have) as count × components floats, sparse substitution applied. Its components must be
// FLOAT, or, with `normalizedIntegers`, normalized BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT (mapped
// as readVectors does): animation outputs, skin matrices, morph-target deltas.
std::vector<float> readFloats(const LoadContext& ctx, const tinygltf::Model& model, int accessor, int type,
                              bool normalizedIntegers, const std::string& what);

// Reads an index accessor: SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT (sparse allowed).
std::vector<uint32_t> readIndices(const LoadContext& ctx, const tinygltf::Model& model, int accessor,
                                  const std::string& what);

// The `count` of accessor `accessor` after checking the index. Used to size vertex arrays.
size_t accessorCount(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& what);

}  // namespace candela::assets::gltf
