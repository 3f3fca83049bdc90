#pragma once
// Internal to the glTF loader: reads a .gltf or .glb file into a tinygltf::Model, safely.
// tinygltf 2.7 trusts the file more than we do, so this layer
//  - validates the GLB container itself and hands tinygltf a re-packed, well-formed copy;
//  - resolves every external URI itself (no absolute paths, no '..' leaving the model's folder,
//    no URI schemes, no current-directory fallback);
//  - receives URI images through its own image-loader callback, which checks the declared size with
//    stbi_info_from_memory and keeps the encoded bytes; ImageTable decodes only the images that
//    materials use. Images stored in bufferViews are not touched here (tinygltf does not
//    range-check those bufferViews); ImageTable checks the view first;
//  - takes out of the JSON what tinygltf would refuse in a valid file: a Draco primitive's indices
//    accessor has no bufferView (kept in ParsedFile), an EXT_meshopt_compression placeholder
//    buffer has no URI (replaced by an empty one), a KHR_animation_pointer channel has no target
//    node (given node -1, so that tinygltf keeps it: target_node -1, target_path "pointer").

#include "assets/gltf_context.h"
#include "assets/gltf_draco.h"
#include "assets/gltf_images.h"
#include "assets/gltf_loader.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <vector>

namespace candela::assets::gltf {

struct ParsedFile {
    tinygltf::Model model;
    std::map<int, std::vector<uint8_t>> uriImages;  // glTF image index → encoded bytes, for URI images
    DracoIndices dracoIndices;  // Draco primitives' indices accessors, kept from tinygltf (see gltf_draco.h)
};

// Reads the whole file at `path` (failing via ctx when it is missing, a directory, empty or 4 GiB
// or larger: tinygltf takes lengths as 32 bits).
std::vector<uint8_t> readGltfFile(const LoadContext& ctx, const std::filesystem::path& path);

// Parses `file` (JSON or GLB, told apart by content), the contents of a file at `path`: `path`'s
// folder is where relative URIs are resolved, read by `reader` when it is set. Throws UserError via
// ctx for anything malformed, missing or escaping that folder. tinygltf's warnings go to ctx.warn.
// Borrows `file` for the call.
ParsedFile parseGltf(const LoadContext& ctx, std::span<const uint8_t> file, const std::filesystem::path& path,
                     uint32_t maxImageDimension, const UriReader& reader = {});

}  // namespace candela::assets::gltf
