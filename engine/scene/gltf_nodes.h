#pragma once
// Internal to the glTF loader: the node hierarchy → draws, cameras and lights in world space.

#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace candela::scene::gltf {

// Walks the default scene (scene 0 if none is named; every parentless node if the file has no
// scenes), composing TRS or matrix transforms. Appends one Draw per (node, mesh primitive) —
// geometry is converted once per primitive and shared by every node using the mesh — plus the
// nodes' cameras and KHR_lights_punctual lights, and sets scene.bounds. Precondition: the glTF
// materials are already in scene.materials (same order); a default material is appended if a
// primitive has none. Throws UserError on cycles, nodes reachable twice, and bad indices.
void loadNodes(const LoadContext& ctx, const tinygltf::Model& model, Scene& scene);

}  // namespace candela::scene::gltf
