#pragma once
// glTF 2.0 loading (.gltf with external, embedded or data-URI buffers and images; .glb) through
// tinygltf, flattened into a scene::Scene.

#include "scene/scene.h"

#include <filesystem>

namespace candela::scene {

struct LoadOptions {
    // Images whose declared width or height exceeds this are rejected before decoding.
    uint32_t maxImageDimension = 16384;
};

// Loads `path`. Throws candela::UserError with one line "PATH: problem" for anything malformed
// (JSON errors, missing files, out-of-range accessors or indices, URIs escaping the model's
// folder, unsupported required extensions, NaN positions...). Non-fatal issues (unsupported
// optional extensions, skipped points/lines) go to Scene::warnings.
Scene loadGltf(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace candela::scene
