#include "assets/gltf_nodes.h"

#include "assets/gltf_accessors.h"
#include "assets/gltf_animations.h"
#include "assets/gltf_materials.h"
#include "assets/gltf_mesh.h"
#include "pose/node_placement.h"
#include "pose/shown_points.h"
#include "pose/skinning.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <utility>

namespace candela::assets::gltf {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool allFinite(const std::vector<double>& values) {
    for (double v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

animation::NodeTransform localTransform(const LoadContext& ctx, const tinygltf::Node& node, const std::string& what) {
    animation::NodeTransform t;
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) ctx.fail(what + ": matrix must have 16 numbers");
        if (!allFinite(node.matrix)) ctx.fail(what + ": matrix is not finite");
        t.matrix = glm::make_mat4(node.matrix.data());  // glTF matrices are column-major, as GLM's
        return t;
    }
    if (!allFinite(node.translation) || !allFinite(node.rotation) || !allFinite(node.scale))
        ctx.fail(what + ": transform is not finite");
    if (!node.translation.empty()) {
        if (node.translation.size() != 3) ctx.fail(what + ": translation must have 3 numbers");
        t.translation = glm::dvec3(node.translation[0], node.translation[1], node.translation[2]);
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) ctx.fail(what + ": rotation must have 4 numbers");
        // glTF stores quaternions as x, y, z, w; a zero quaternion is read as no rotation.
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        if (length > 0.0) t.rotation = q / length;
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3) ctx.fail(what + ": scale must have 3 numbers");
        t.scale = glm::dvec3(node.scale[0], node.scale[1], node.scale[2]);
    }
    return t;
}

// The morph-target weights a node starts with: its own, else its mesh's defaults, else zeros; one
// per morph target of the mesh, whose primitives must all have the same number of targets.
std::vector<float> morphWeights(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Node& node,
                                const std::string& what) {
    if (node.mesh < 0 || size_t(node.mesh) >= model.meshes.size()) {
        if (!node.weights.empty()) ctx.fail(what + ": has weights but no mesh");
        return {};
    }
    const tinygltf::Mesh& mesh = model.meshes[size_t(node.mesh)];
    const std::string meshWhat = label("mesh", node.mesh, mesh.name);
    const size_t targets = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    for (size_t p = 1; p < mesh.primitives.size(); ++p)
        if (mesh.primitives[p].targets.size() != targets)
            ctx.fail(meshWhat + " primitive " + std::to_string(p) + ": " + std::to_string(mesh.primitives[p].targets.size()) +
                     " morph targets, primitive 0 has " + std::to_string(targets));
    auto convert = [&](const std::vector<double>& weights, const std::string& owner) {
        if (weights.size() != targets)
            ctx.fail(owner + ": " + std::to_string(weights.size()) + " weights for " + std::to_string(targets) +
                     " morph targets");
        std::vector<float> out;
        for (double w : weights) out.push_back(toFloat(ctx, w, owner + ": a weight"));
        return out;
    };
    if (!mesh.weights.empty() || !node.weights.empty()) {
        std::vector<float> meshWeights = mesh.weights.empty() ? std::vector<float>(targets, 0.0f) : convert(mesh.weights, meshWhat);
        return node.weights.empty() ? meshWeights : convert(node.weights, what);
    }
    return std::vector<float>(targets, 0.0f);
}

// KHR_node_visibility's flag of `node` (true without the extension; the schema check vetted its type).
bool visibleFlag(const tinygltf::Node& node) {
    const auto it = node.extensions.find("KHR_node_visibility");
    if (it == node.extensions.end() || !it->second.Get("visible").IsBool()) return true;
    return it->second.Get("visible").Get<bool>();
}

class NodeWalker {
public:
    // Nodes some animation channel moves, by a core channel or a pointer (bad indices are reported
    // by loadAnimations).
    NodeWalker(const LoadContext& ctx, const tinygltf::Model& model, scene::Scene& scene)
        : mCtx(ctx), mModel(model), mScene(scene), mGltfMaterials(scene.materials.size()), mTargeted(animatedNodes(model)) {}

    void walk(const std::vector<int>& roots) {
        const size_t count = mModel.nodes.size();
        std::vector<uint8_t> visited(count, 0), onPath(count, 0);
        struct Item {
            int node;
            int32_t parent;  // index into Scene::nodes; -1 for a root
            bool exit;
        };
        std::vector<Item> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, -1, false});
        while (!stack.empty()) {
            const Item item = stack.back();
            stack.pop_back();
            if (item.exit) {
                onPath[size_t(item.node)] = 0;
                continue;
            }
            if (item.node < 0 || size_t(item.node) >= count) mCtx.fail("node " + std::to_string(item.node) + " does not exist");
            const tinygltf::Node& node = mModel.nodes[size_t(item.node)];
            const std::string what = label("node", item.node, node.name);
            if (onPath[size_t(item.node)]) mCtx.fail(what + ": cycle in the node hierarchy");
            if (visited[size_t(item.node)])
                mCtx.fail(what + ": reached twice (a node must have at most one parent and appear once in the scene)");
            visited[size_t(item.node)] = onPath[size_t(item.node)] = 1;
            // Depth-first: the parent is already in Scene::nodes, before this node.
            animation::SceneNode sceneNode{.name = node.name, .source = item.node, .parent = item.parent,
                                .transform = localTransform(mCtx, node, what),
                                .weights = morphWeights(mCtx, mModel, node, what),
                                .visible = visibleFlag(node)};
            const glm::dmat4 local = sceneNode.transform.local();
            sceneNode.world = item.parent >= 0 ? mScene.nodes[size_t(item.parent)].world * local : local;
            sceneNode.shown = sceneNode.visible && (item.parent < 0 || mScene.nodes[size_t(item.parent)].shown);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) toFloat(mCtx, sceneNode.world[c][r], what + ": world transform");
            const int32_t index = int32_t(mScene.nodes.size());
            mMovable.push_back(mTargeted[size_t(item.node)] || (item.parent >= 0 && mMovable[size_t(item.parent)]));
            mScene.nodes.push_back(std::move(sceneNode));
            visit(node, what, index);
            stack.push_back({item.node, -1, true});
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, index, false});
        }
    }

    // After the walk: the skins the draws use (joints must be in the scene), skinned draws placed
    // by their joints' rest pose, one warning for renormalized skin weights, the scene bounds (of
    // the vertices of the draws not hidden; of all, with a warning, when every one is).
    void finish() {
        std::vector<int32_t> sceneNode(mModel.nodes.size(), -1);
        for (size_t i = 0; i < mScene.nodes.size(); ++i) sceneNode[size_t(mScene.nodes[i].source)] = int32_t(i);
        std::map<int, int32_t> skins;  // glTF skin → Scene::skins
        std::vector<glm::dmat4> joints;
        for (scene::Draw& draw : mScene.draws) {
            if (draw.skin >= 0) {
                auto [it, added] = skins.try_emplace(draw.skin, int32_t(mScene.skins.size()));
                if (added) mScene.skins.push_back(loadSkin(draw.skin, sceneNode));
                const scene::Skin& skin = mScene.skins[size_t(it->second)];
                const scene::Deformation& deformation = mScene.deformations[size_t(draw.deformation)];
                if (deformation.maxJoint >= skin.joints.size())
                    mCtx.fail(label("skin", draw.skin, skin.name) + ": a vertex names joint " + std::to_string(deformation.maxJoint) +
                              ", but the skin has " + std::to_string(skin.joints.size()) + " joints");
                draw.skin = it->second;
                pose::jointMatrices(skin, mScene.nodes, joints);
                // As for a rigid mesh: a rest pose beyond a float (huge inverse bind or joint
                // matrices) fails the file rather than leaving infinite bounds.
                if (pose::placeSkinnedDraw(draw, pose::skinnedBounds(pose::jointMeshBounds(deformation, skin, mScene.vertices), joints,
                                                         pose::morphReach(deformation, mScene.nodes[size_t(draw.node)].weights))) !=
                    pose::Placement::Placed)
                    mCtx.fail(label("skin", int(it->first), skin.name) + ": the skinned mesh's rest pose is beyond single precision");
                draw.hidden = !mScene.nodes[size_t(draw.node)].shown;
            }
        }
        // The vertices as placed, skinned and morphed, not the draws' boxes: the same bounds for
        // every structure of the file that draws the same image.
        mScene.bounds = pose::shownBounds(mScene);
        if (!mScene.bounds.valid() && !mScene.draws.empty()) {
            mScene.bounds = pose::shownBounds(mScene, /*includeHidden=*/true);
            if (std::any_of(mScene.draws.begin(), mScene.draws.end(), [&](const scene::Draw& d) { return !mScene.nodes[size_t(d.node)].shown; }))
                mCtx.warn("every node is hidden (KHR_node_visibility): framing uses the hidden geometry");
        }
        if (mRenormalizedWeights)
            mCtx.warn(std::to_string(mRenormalizedWeights) + " vertices have skin weights that do not sum to 1 (renormalized)");
    }

    // How many of the nodes walked hold a mesh (drawn or not: a zero scale or a hidden node still
    // holds one).
    size_t meshNodes() const { return mMeshNodes; }

private:
    scene::Skin loadSkin(int index, const std::vector<int32_t>& sceneNode) {
        const tinygltf::Skin& source = mModel.skins[size_t(index)];
        const std::string what = label("skin", index, source.name);
        // JOINTS are unsigned bytes or shorts: no vertex can name a joint beyond 65535.
        constexpr size_t kMaxJoints = 65536;
        if (source.joints.size() > kMaxJoints)
            mCtx.fail(what + ": " + std::to_string(source.joints.size()) + " joints, more than the " +
                      std::to_string(kMaxJoints) + " a vertex can name");
        if (source.joints.empty()) mCtx.fail(what + ": no joints");
        scene::Skin skin{.name = source.name};
        for (int joint : source.joints) {
            if (joint < 0 || size_t(joint) >= mModel.nodes.size())
                mCtx.fail(what + ": joint node " + std::to_string(joint) + " does not exist");
            if (sceneNode[size_t(joint)] < 0) mCtx.fail(what + ": joint node " + std::to_string(joint) + " is not in the scene");
            skin.joints.push_back(uint32_t(sceneNode[size_t(joint)]));
        }
        skin.inverseBind.assign(skin.joints.size(), glm::mat4(1.0f));
        if (source.inverseBindMatrices >= 0) {
            const std::vector<float> m =
                readFloats(mCtx, mModel, source.inverseBindMatrices, TINYGLTF_TYPE_MAT4, false, what + " inverseBindMatrices");
            if (m.size() != 16 * skin.joints.size())
                mCtx.fail(what + ": inverseBindMatrices has " + std::to_string(m.size() / 16) + " matrices for " +
                          std::to_string(skin.joints.size()) + " joints");
            for (size_t j = 0; j < skin.joints.size(); ++j) {
                for (size_t k = 0; k < 16; ++k)
                    if (!std::isfinite(m[16 * j + k])) mCtx.fail(what + ": inverse bind matrix " + std::to_string(j) + " is not finite");
                skin.inverseBind[j] = glm::make_mat4(m.data() + 16 * j);
            }
        }
        return skin;
    }

    void visit(const tinygltf::Node& node, const std::string& what, int32_t sceneNode) {
        const glm::dmat4 world = mScene.nodes[size_t(sceneNode)].world;  // a copy: the vector grows later
        if (node.mesh >= 0) ++mMeshNodes;
        if (node.mesh >= 0) addMesh(node, what, world, sceneNode);
        if (node.camera >= 0) addCamera(node, what, world, sceneNode);
        if (auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end())
            addLight(it->second, what, world, sceneNode);
    }

    uint32_t materialIndex(int material, const std::string& what) {
        if (material >= 0) {
            if (size_t(material) >= mGltfMaterials) mCtx.fail(what + ": material " + std::to_string(material) + " does not exist");
            return uint32_t(material);
        }
        if (mDefaultMaterial < 0) {
            mDefaultMaterial = int(mScene.materials.size());
            mScene.materials.push_back(scene::Material{.name = "default"});
        }
        return uint32_t(mDefaultMaterial);
    }

    // EXT_mesh_gpu_instancing: the node's instance matrices (TRS from its TRANSLATION, ROTATION and
    // SCALE accessors), or nullopt without the extension.
    std::optional<std::vector<glm::mat4>> readInstances(const tinygltf::Node& node, const std::string& what) {
        const auto extension = node.extensions.find("EXT_mesh_gpu_instancing");
        if (extension == node.extensions.end()) return std::nullopt;
        const std::string ext = what + " EXT_mesh_gpu_instancing";
        const tinygltf::Value& attributes = extension->second.Get("attributes");
        if (!attributes.IsObject()) mCtx.fail(ext + ": no attributes object");
        std::optional<size_t> count;
        auto read = [&](const char* name, int type, bool normalized) {
            const tinygltf::Value& index = attributes.Get(name);
            if (!index.IsNumber()) return std::vector<float>{};
            const double i = index.GetNumberAsDouble();
            if (!(i >= 0.0 && i < double(mModel.accessors.size()) && i == std::floor(i)))
            {
                char number[32];
                std::snprintf(number, sizeof number, "%.10g", i);
                mCtx.fail(ext + " " + name + ": accessor " + number + " does not exist");
            }
            std::vector<float> values = readFloats(mCtx, mModel, int(i), type, normalized, ext + " " + name);
            const size_t n = values.size() / (type == TINYGLTF_TYPE_VEC4 ? 4 : 3);
            if (count && *count != n)
                mCtx.fail(ext + ": " + name + " has " + std::to_string(n) + " instances, another attribute " + std::to_string(*count));
            count = n;
            for (float v : values)
                if (!std::isfinite(v)) mCtx.fail(ext + " " + name + ": a value is not finite");
            return values;
        };
        const std::vector<float> t = read("TRANSLATION", TINYGLTF_TYPE_VEC3, false);
        const std::vector<float> r = read("ROTATION", TINYGLTF_TYPE_VEC4, true);
        const std::vector<float> sc = read("SCALE", TINYGLTF_TYPE_VEC3, false);
        if (!count) mCtx.fail(ext + ": none of TRANSLATION, ROTATION, SCALE");
        std::vector<glm::mat4> out(*count);
        for (size_t i = 0; i < *count; ++i) {
            animation::NodeTransform transform;
            if (!t.empty()) transform.translation = glm::dvec3(t[3 * i], t[3 * i + 1], t[3 * i + 2]);
            if (!r.empty()) {
                const glm::dquat q(r[4 * i + 3], r[4 * i], r[4 * i + 1], r[4 * i + 2]);
                if (glm::length(q) > 0.0) transform.rotation = glm::normalize(q);
            }
            if (!sc.empty()) transform.scale = glm::dvec3(sc[3 * i], sc[3 * i + 1], sc[3 * i + 2]);
            out[i] = glm::mat4(transform.local());
        }
        return out;
    }

    void addMesh(const tinygltf::Node& node, const std::string& what, const glm::dmat4& world, int32_t sceneNode) {
        const int meshIndex = node.mesh, skin = node.skin;
        if (size_t(meshIndex) >= mModel.meshes.size()) mCtx.fail(what + ": mesh " + std::to_string(meshIndex) + " does not exist");
        if (skin >= 0 && size_t(skin) >= mModel.skins.size()) mCtx.fail(what + ": skin " + std::to_string(skin) + " does not exist");
        // A zero scale on any axis (here or inherited) flattens the mesh to nothing visible and
        // leaves no normal matrix: a static node's draws are left out, an animated one's are kept,
        // hidden until the animation scales them up. (A skinned mesh ignores its node's transform.)
        scene::Draw probe{.localBounds = scene::Aabb{glm::vec3(0.0f), glm::vec3(0.0f)}};
        const bool movable = mMovable[size_t(sceneNode)];
        if (skin < 0 && pose::placeDraw(probe, world) == pose::Placement::Singular && !movable)
            return mCtx.tally(Severity::Note, {"node", "zero scale, not drawn"}, what);
        // Instances, in at most two groups — those that mirror and those that do not — so that each
        // draw has one winding; shared by the mesh's primitives.
        std::optional<std::vector<glm::mat4>> instances = readInstances(node, what);
        if (instances && skin >= 0) {
            mCtx.warn(what + ": EXT_mesh_gpu_instancing on a skinned mesh is not supported (drawn once)");
            instances.reset();
        }
        std::vector<std::pair<uint32_t, uint32_t>> groups;  // (first, count) in Scene::instances
        if (instances) {
            for (bool mirrored : {false, true}) {
                const uint32_t first = uint32_t(mScene.instances.size());
                for (size_t i = 0; i < instances->size(); ++i)
                    if ((glm::determinant(glm::mat3((*instances)[i])) < 0.0f) == mirrored) {
                        mScene.instances.push_back((*instances)[i]);
                        mScene.instanceIndices.push_back(uint32_t(i));
                    }
                if (mScene.instances.size() > first) groups.emplace_back(first, uint32_t(mScene.instances.size()) - first);
            }
            if (groups.empty()) return;  // zero instances: nothing to draw
        } else {
            groups.emplace_back(0, 0);
        }
        const auto& primitives = mModel.meshes[size_t(meshIndex)].primitives;
        for (size_t p = 0; p < primitives.size(); ++p) {
            const std::string primitiveName = label("mesh", meshIndex) + " primitive " + std::to_string(p);
            const uint32_t material = materialIndex(primitives[p].material, primitiveName);
            const std::vector<std::pair<uint32_t, uint32_t>> variants =
                primitiveVariants(mCtx, primitives[p], mScene, primitiveName);
            // Tangents follow the first normal map among the materials the primitive may wear.
            std::optional<scene::TextureRef> tangentMap = mScene.materials[material].tangentSpaceMap();
            for (const auto& [variant, m] : variants)
                if (!tangentMap) tangentMap = mScene.materials[m].tangentSpaceMap();
            const scene::TextureRef* tangents = tangentMap ? &*tangentMap : nullptr;
            PrimitiveSource source = primitiveSource(mModel, meshIndex, int(p), tangents);
            auto cached = mGeometry.find(source);
            if (cached == mGeometry.end()) {
                cached = mGeometry.emplace(std::move(source), appendPrimitive(mCtx, mModel, meshIndex, int(p), tangents, mScene)).first;
                mRenormalizedWeights += cached->second.renormalizedWeights;
            }
            const PrimitiveGeometry& geometry = cached->second;
            if (!geometry.drawable) continue;
            const bool skinned = skin >= 0 && geometry.deformation >= 0 &&
                                 mScene.deformations[size_t(geometry.deformation)].influencesPerVertex > 0;
            for (const auto& [first, count] : groups) {
                scene::Draw draw{.firstIndex = geometry.firstIndex,
                          .indexCount = geometry.indexCount,
                          .topology = geometry.topology,
                          .unshaded = geometry.unshaded,
                          .material = material,
                          .localBounds = geometry.bounds,
                          .node = sceneNode,
                          .mesh = meshIndex,
                          .primitive = int32_t(p),
                          .deformation = geometry.deformation,
                          .skin = skinned ? skin : -1,  // the glTF skin until finishSkins
                          .firstInstance = first,
                          .instanceCount = count};
                // The world matrix itself was checked to fit a float as the node was reached.
                const glm::vec3 reach = geometry.deformation >= 0
                                            ? pose::morphReach(mScene.deformations[size_t(geometry.deformation)], mScene.nodes[size_t(sceneNode)].weights)
                                            : glm::vec3(0.0f);
                if (!skinned && pose::placeDraw(draw, world, reach, std::span(mScene.instances).subspan(first, count)) == pose::Placement::BeyondFloat)
                    mCtx.fail(what + ": a corner of its mesh in world space is beyond single precision");
                // KHR_node_visibility: hidden with its node (an animation may show it).
                if (!mScene.nodes[size_t(sceneNode)].shown) draw.hidden = true;
                if (!variants.empty())
                    mScene.drawVariants.push_back({uint32_t(mScene.draws.size()), material, variants});
                mScene.draws.push_back(draw);
            }
        }
    }

    void addCamera(const tinygltf::Node& node, const std::string& what, const glm::dmat4& world, int32_t sceneNode) {
        if (size_t(node.camera) >= mModel.cameras.size()) mCtx.fail(what + ": camera " + std::to_string(node.camera) + " does not exist");
        const tinygltf::Camera& source = mModel.cameras[size_t(node.camera)];
        const std::string cameraWhat = label("camera", node.camera, source.name);
        scene::Camera camera;
        camera.node = sceneNode;
        camera.source = node.camera;
        camera.name = !source.name.empty() ? source.name : !node.name.empty() ? node.name : "camera " + std::to_string(node.camera);
        if (!pose::placeCamera(camera, world)) return mCtx.warn(cameraWhat + ": degenerate node transform, camera skipped");
        bool valid = false;
        auto fits = [](std::initializer_list<double> values) { return std::all_of(values.begin(), values.end(), fitsFloat); };
        if (source.type == "perspective") {
            const auto& p = source.perspective;
            if (!fits({p.yfov, p.aspectRatio, p.znear, p.zfar}))
                return mCtx.warn(cameraWhat + ": parameters beyond single precision, camera skipped");
            camera.perspective = true;
            camera.yfov = float(p.yfov);
            camera.aspectRatio = float(p.aspectRatio);
            camera.znear = float(p.znear);
            camera.zfar = float(p.zfar);
            valid = p.yfov > 0.0 && p.yfov < kPi && p.znear > 0.0 && p.aspectRatio >= 0.0 &&
                    (p.zfar == 0.0 || p.zfar > p.znear) && std::isfinite(p.zfar) && std::isfinite(p.aspectRatio);
        } else if (source.type == "orthographic") {
            const auto& o = source.orthographic;
            if (!fits({o.xmag, o.ymag, o.znear, o.zfar}))
                return mCtx.warn(cameraWhat + ": parameters beyond single precision, camera skipped");
            camera.perspective = false;
            camera.xmag = float(o.xmag);
            camera.ymag = float(o.ymag);
            camera.znear = float(o.znear);
            camera.zfar = float(o.zfar);
            valid = o.xmag != 0.0 && o.ymag != 0.0 && o.znear >= 0.0 && o.zfar > o.znear && std::isfinite(o.xmag) &&
                    std::isfinite(o.ymag) && std::isfinite(o.zfar);
        }
        if (!valid) return mCtx.warn(cameraWhat + ": invalid " + source.type + " parameters, camera skipped");
        mScene.cameras.push_back(camera);
    }

    void addLight(const tinygltf::Value& extension, const std::string& what, const glm::dmat4& world, int32_t sceneNode) {
        const tinygltf::Value& index = extension.Has("light") ? extension.Get("light") : tinygltf::Value();
        const double i = index.IsNumber() ? index.GetNumberAsDouble() : -1.0;
        if (!(i >= 0.0 && i < double(mModel.lights.size()) && i == std::floor(i)))
            mCtx.fail(what + ": KHR_lights_punctual light index is missing or out of range");
        const tinygltf::Light& source = mModel.lights[size_t(i)];
        const std::string lightWhat = label("light", int(i), source.name);
        scene::Light light;
        light.node = sceneNode;
        light.source = int32_t(i);
        light.hidden = !mScene.nodes[size_t(sceneNode)].shown;  // KHR_node_visibility
        if (source.type == "directional") light.type = scene::LightType::Directional;
        else if (source.type == "point") light.type = scene::LightType::Point;
        else if (source.type == "spot") light.type = scene::LightType::Spot;
        else return mCtx.warn(lightWhat + ": unknown type '" + source.type + "', light skipped");
        if (source.color.size() == 3 && allFinite(source.color))
            light.color = glm::max(glm::vec3(toFloat(mCtx, source.color[0], lightWhat + " color"),
                                             toFloat(mCtx, source.color[1], lightWhat + " color"),
                                             toFloat(mCtx, source.color[2], lightWhat + " color")),
                                   glm::vec3(0.0f));
        else if (!source.color.empty())
            mCtx.warn(lightWhat + ": color must be 3 finite numbers, using white");
        if (!std::isfinite(source.intensity) || !std::isfinite(source.range) || !std::isfinite(source.spot.innerConeAngle) ||
            !std::isfinite(source.spot.outerConeAngle))
            mCtx.fail(lightWhat + ": parameters are not finite");
        light.intensity = toFloat(mCtx, std::max(source.intensity, 0.0), lightWhat + " intensity");
        light.range = toFloat(mCtx, std::max(source.range, 0.0), lightWhat + " range");
        // 0 <= inner < outer <= π/2, as the extension requires.
        light.outerConeAngle = float(std::clamp(source.spot.outerConeAngle, 1e-4, kPi / 2));
        light.innerConeAngle = float(std::clamp(source.spot.innerConeAngle, 0.0, double(light.outerConeAngle) * 0.9999));
        pose::placeLight(light, world);
        mScene.lights.push_back(light);
    }

    const LoadContext& mCtx;
    const tinygltf::Model& mModel;
    scene::Scene& mScene;
    size_t mGltfMaterials;
    int mDefaultMaterial = -1;
    std::map<PrimitiveSource, PrimitiveGeometry> mGeometry;  // each source converted once
    std::vector<uint8_t> mTargeted;  // per glTF node: an animation channel targets it
    std::vector<uint8_t> mMovable;   // per Scene::nodes entry: it or an ancestor is targeted
    size_t mRenormalizedWeights = 0;  // over every primitive read
    size_t mMeshNodes = 0;
};

}  // namespace

void loadNodes(const LoadContext& ctx, const tinygltf::Model& model, std::optional<uint32_t> sceneIndex, scene::Scene& scene) {
    std::vector<int> roots;
    if (model.scenes.empty()) {
        // No scene: draw every parentless node rather than nothing.
        std::vector<uint8_t> isChild(model.nodes.size(), 0);
        for (const tinygltf::Node& node : model.nodes)
            for (int child : node.children)
                if (child >= 0 && size_t(child) < model.nodes.size()) isChild[size_t(child)] = 1;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!isChild[i]) roots.push_back(int(i));
        if (sceneIndex) ctx.fail("scene " + std::to_string(*sceneIndex) + " does not exist (the file has no scenes)");
        // "scene" names a default scene the file does not have: an unresolved reference (the
        // glTF-Validator's UNRESOLVED_REFERENCE), not a file without scenes.
        if (model.defaultScene >= 0)
            ctx.fail("scene " + std::to_string(model.defaultScene) + " (the default scene) does not exist (the file has no scenes)");
    } else {
        const size_t index = sceneIndex ? *sceneIndex : size_t(model.defaultScene >= 0 ? model.defaultScene : 0);
        if (index >= model.scenes.size())
            ctx.fail("scene " + std::to_string(index) + " does not exist (the file has " + std::to_string(model.scenes.size()) +
                     " scenes)");
        roots = model.scenes[index].nodes;
        scene.sceneIndex = uint32_t(index);
        for (size_t i = 0; i < model.scenes.size(); ++i)
            scene.sceneNames.push_back(model.scenes[i].name.empty() ? "scene " + std::to_string(i) : model.scenes[i].name);
    }
    NodeWalker walker(ctx, model, scene);
    walker.walk(roots);
    walker.finish();
    // A file without scenes, or with an empty one, is valid (glTF 2.0 §3.5.1: a library of
    // meshes, materials, …): it loads, with one warning when nothing is drawn.
    if (model.scenes.empty()) {
        if (model.nodes.empty()) ctx.warn("nothing to draw: the file has no scene and no nodes");
        else if (walker.meshNodes() == 0) ctx.warn("nothing to draw: the file has no scene, and none of its root nodes holds a mesh");
        else ctx.warn("no scene defined: drawing every root node");
    } else if (walker.meshNodes() == 0) {
        const std::string which = "scene " + std::to_string(scene.sceneIndex);
        const std::string others = model.scenes.size() > 1 ? " (the file has " + std::to_string(model.scenes.size()) +
                                                                 " scenes: --scene-index)"
                                                           : "";
        ctx.warn("nothing to draw: " + (roots.empty() ? which + " has no nodes" : "no node of " + which + " holds a mesh") + others);
    }
}

}  // namespace candela::assets::gltf
