#pragma once
// Internal to the glTF loader: KHR_draco_mesh_compression. Decoding happens before anything reads
// a mesh: each compressed primitive's Draco stream is decoded (Google's Draco library) and the
// result written into the model as plain accessors, so the usual accessor checks apply to it.

#include "assets/gltf_context.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <map>
#include <utility>

namespace tinygltf {
class Model;
}

namespace candela::assets::gltf {

// The indices accessor of each Draco primitive that has one, by (mesh, primitive).
using DracoIndices = std::map<std::pair<size_t, size_t>, int>;

// tinygltf (Debian's, built without Draco) refuses a primitive whose indices accessor has no
// bufferView, which is how a Draco primitive's indices are written. Takes "indices" out of every
// primitive of the document `doc` that has a KHR_draco_mesh_compression extension, recording them
// in `indices`. Returns whether `doc` changed. Precondition: `doc` passed checkGltfJson.
bool detachDracoIndices(nlohmann::json& doc, DracoIndices& indices);

// For every primitive with a KHR_draco_mesh_compression extension: decodes the extension's
// bufferView as a Draco triangle mesh, appends one buffer to `model` holding the decoded indices
// and the attributes the extension names, and points the primitive's indices (its accessor from
// `indices`, or unsigned int when it had none) and those
// `attributes` at new accessors over it (the file's accessors keep their componentType, type and
// normalized flag, their bufferView and sparse are ignored, as the extension asks). A strip
// primitive becomes a triangle list (Draco decodes faces). The extension is removed from the
// primitive afterwards. Attributes the extension does not name are left as they are.
// Throws UserError via ctx naming the mesh and primitive when the stream does not decode, is not a
// triangle mesh, lacks a named attribute, or disagrees with an accessor (count, component count,
// values that do not fit the accessor's type); and when the extension's JSON is malformed.
// Returns the number of primitives decoded.
size_t decodeDracoPrimitives(const LoadContext& ctx, tinygltf::Model& model, const DracoIndices& indices);

}  // namespace candela::assets::gltf
