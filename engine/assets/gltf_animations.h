#pragma once
// Internal to the glTF loader: glTF animations → Scene::animations, validated so that playing them
// (animation/node_tree.h applyAnimation) needs no further checks.

#include "assets/gltf_context.h"
#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace candela::scene::gltf {

// Reads every animation of the file. Channels are remapped from glTF node indices to Scene::nodes
// (so loadNodes must have run); a channel whose node is not in the loaded scene animates nothing
// drawn and is dropped, as is one without a target node (the specification lets extensions name
// the target). Throws UserError (via ctx) for: a sampler or node index that does not exist, an
// input that is not SCALAR FLOAT, an output of the wrong type, times that are not finite or
// decrease, an output count that does not match the input and the interpolation, an unknown
// interpolation, a channel on a node with a matrix, and a weights channel on a node without morph
// targets (or whose width differs from that node's target count). An unsupported path (e.g.
// KHR_animation_pointer's "pointer") is a warning and its channel is dropped.
void loadAnimations(const LoadContext& ctx, const tinygltf::Model& model, Scene& scene);

}  // namespace candela::scene::gltf
