#pragma once
// Internal to the glTF loader: EXT_meshopt_compression. Compressed bufferViews (vertex attributes,
// indices, morph targets, animation keys, instance transforms: anything) are decoded with
// meshoptimizer's decoders and filters right after parsing, into a new buffer the views then point
// at, so everything downstream reads plain bufferViews with the usual range checks.

#include "assets/gltf_context.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>

namespace tinygltf {
class Model;
}

namespace candela::assets::gltf {

// A file that requires the extension may give its placeholder ("fallback") buffers no URI, which
// tinygltf refuses. In a document `doc` that uses EXT_meshopt_compression, replaces every buffer
// without a URI (except a GLB's buffer 0, the BIN chunk) and every buffer marked
// `"fallback": true` by a 3-byte embedded buffer: nothing is read from them once the views are
// decoded. Returns whether `doc` changed. Precondition: `doc` passed checkGltfJson.
bool emptyMeshoptFallbackBuffers(nlohmann::json& doc, bool binary);

// Decodes every bufferView with an EXT_meshopt_compression extension (modes ATTRIBUTES, TRIANGLES,
// INDICES; filters NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL) into one buffer appended to `model`,
// and points the view there (same byteLength and byteStride). Throws UserError via ctx naming the
// bufferView when the extension object breaks the specification's rules (stride, count, mode and
// filter combinations, byteLength = count × byteStride), its source range lies outside its buffer,
// the data claims more decoded bytes than the codec can produce from its size, or the data does
// not decode. Returns the number of views decoded.
size_t decodeMeshoptBufferViews(const LoadContext& ctx, tinygltf::Model& model);

}  // namespace candela::assets::gltf
