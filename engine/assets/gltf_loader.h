#pragma once
// glTF 2.0 loading (.gltf with external, embedded or data-URI buffers and images; .glb) through
// tinygltf, flattened into a scene::Scene.

#include "scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace candela::assets {

// Reads the file a relative URI names (after the loader's checks: no absolute path, no scheme, not
// leaving the model's folder): its bytes, or nullopt when there is none.
using UriReader = std::function<std::optional<std::vector<uint8_t>>(const std::string& uri)>;

struct LoadOptions {
    // Images whose declared width or height exceeds this are rejected before decoding.
    uint32_t maxImageDimension = 16384;
    // Decoded (RGBA8) bytes allowed per image and for all of a scene's images together (an image
    // used both as colour and as data counts twice). Both are checked from the sizes the image
    // headers declare, before any pixel is decoded: a small file that would decompress to
    // gigabytes (a decompression bomb) fails at once with the sizes in the message.
    uint64_t maxImageBytes = uint64_t(256) << 20;
    uint64_t maxTotalImageBytes = uint64_t(2) << 30;
    // The glTF scene to load (--scene-index); unset: the file's `scene`, else scene 0.
    std::optional<uint32_t> sceneIndex;
    // Prepare the geometry for drawing (geometry/mesh_optimize.h: reordered for the vertex cache,
    // overdraw and fetch, with levels of detail). false keeps the file's triangle and vertex order
    // and builds no levels.
    bool prepareGeometry = true;
    // Leave the levels of detail for later (geometry::buildLevelsOfDetail, when a cost model says
    // they pay: the API decides from the frames it is asked for; Scene::report.geometry.lodDeferred).
    bool deferLevelsOfDetail = false;
    // Decode the images (PNG, JPEG, WebP) on their own thread beside the rest of the load (the
    // materials, nodes, animations and geometry); false: before it, with nothing else on the cores
    // (the decode term of a render's floor: candela_decode_floor_bench). The scene is the same.
    bool decodeBesideTheLoad = true;
    // Where external URIs are read from; unset: the files in the model's folder.
    UriReader uriReader;
};

// Loads `path`. Throws candela::UserError with one line "PATH: problem" for anything malformed
// (JSON errors, missing files, out-of-range accessors or indices, URIs escaping the model's
// folder, unsupported required extensions, NaN positions...). Non-fatal issues (unsupported
// optional extensions, skipped points/lines) go to Scene::warnings.
scene::Scene loadGltf(const std::filesystem::path& path, const LoadOptions& options = {});

// As loadGltf, for a file's contents already in memory: `path` names the file in messages and its
// folder is where relative URIs (buffers, images) are read from. Borrows `bytes` for the call.
scene::Scene loadGltfFromMemory(std::span<const uint8_t> bytes, const std::filesystem::path& path,
                         const LoadOptions& options = {});

}  // namespace candela::assets
