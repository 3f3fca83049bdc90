#pragma once
// Internal to the glTF loader: the node hierarchy → draws, cameras and lights in world space.

#include "assets/gltf_context.h"
#include "scene/scene.h"

#include <optional>

namespace tinygltf {
class Model;
}

namespace candela::assets::gltf {

// Walks scene `sceneIndex` (unset: the file's default scene, else scene 0; every parentless node
// if the file has no scenes) and records the file's scene names and the one chosen, composing TRS or matrix transforms. Appends one Draw per (node, mesh primitive) —
// geometry is converted once per primitive source (PrimitiveSource, assets/gltf_mesh.h) and shared
// by every node using the mesh and every primitive over the same accessors — plus the
// nodes' cameras and KHR_lights_punctual lights; draws and lights under a node KHR_node_visibility
// hides are kept, hidden; sets scene.bounds (of the draws not hidden). Precondition: the glTF
// materials are already in scene.materials (same order); a default material is appended if a
// primitive has none. Throws UserError on cycles, nodes reachable twice, and bad indices.
void loadNodes(const LoadContext& ctx, const tinygltf::Model& model, std::optional<uint32_t> sceneIndex, scene::Scene& scene);

}  // namespace candela::assets::gltf
