#pragma once
// Internal to the glTF loader: glTF animations → Scene::animations, validated so that playing them
// (animation/node_tree.h applyAnimation, pose/scene_pose.h) needs no further checks. Core channels
// and KHR_animation_pointer channels (scene/animated_properties.h says which pointers Candela
// animates): pointers to nodes and mesh weights become node channels, the rest property channels.

#include "assets/gltf_context.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace tinygltf {
class Model;
}

namespace candela::assets::gltf {

// Per glTF node: 1 when some animation channel may move it — a core channel's target node, a
// pointer to the node (its transform, weights or KHR_node_visibility visible) or to the weights of
// its mesh. Bad indices are ignored here (loadAnimations reports them).
std::vector<uint8_t> animatedNodes(const tinygltf::Model& model);

// Sets Material::animatedLayers of scene.materials (the file's, in file order) from the pointers
// of every animation: the layers an animated factor may switch on (layersAnimationMayNeed).
// Call after loadMaterials and before the geometry is converted (tangent frames follow it).
// Unparsed or out-of-range pointers are ignored here (loadAnimations reports them).
void noteAnimatedMaterials(const tinygltf::Model& model, scene::Scene& scene);

// Reads every animation of the file. Node channels are remapped from glTF node indices to
// Scene::nodes (so loadNodes must have run); a channel whose node is not in the loaded scene
// animates nothing drawn and is dropped, as is a core one without a target node. Throws UserError
// (via ctx) for: a sampler, node, mesh, material, light or camera index that does not exist, an
// input that is not SCALAR FLOAT, an output of the wrong type (for a pointer, the type of the
// property it names), times that are not finite or decrease, an output count that does not match
// the input and the interpolation, an unknown interpolation, a visibility without STEP, a channel
// on a node with a matrix, and a weights channel on a node without morph targets (or whose width
// differs from that node's target count). An unsupported path, a pointer Candela does not
// animate (one warning per distinct pointer and animation) and a camera pointer of the other
// projection are warnings, and their channels are dropped.
void loadAnimations(const LoadContext& ctx, const tinygltf::Model& model, scene::Scene& scene);

}  // namespace candela::assets::gltf
