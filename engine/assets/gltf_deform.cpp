#include "assets/gltf_deform.h"

#include "assets/gltf_accessors.h"

#include <tiny_gltf.h>

#include <cmath>

namespace candela::assets::gltf {
namespace {

// The accessor named `name` of `attributes`, or -1.
int attributeAccessor(const std::map<std::string, int>& attributes, const std::string& name) {
    const auto it = attributes.find(name);
    return it == attributes.end() ? -1 : it->second;
}

std::vector<glm::vec4> readCounted(const LoadContext& ctx, const tinygltf::Model& model, int accessor,
                                   std::initializer_list<int> types, size_t count, const std::string& what) {
    std::vector<glm::vec4> values = readVectors(ctx, model, accessor, types, what);
    if (values.size() != count)
        ctx.fail(what + ": " + std::to_string(values.size()) + " elements, POSITION has " + std::to_string(count));
    for (size_t i = 0; i < values.size(); ++i)
        if (!finite(values[i])) ctx.fail(what + ": element " + std::to_string(i) + " is not finite");
    return values;
}

void readTargets(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                 const std::string& what, size_t count, SourceDeformation& out) {
    out.targetCount = uint32_t(primitive.targets.size());
    out.deltas.assign(size_t(out.targetCount) * count, scene::MorphDelta{});
    for (uint32_t t = 0; t < out.targetCount; ++t) {
        const std::map<std::string, int>& target = primitive.targets[t];
        const std::string targetWhat = what + " morph target " + std::to_string(t);
        scene::MorphDelta* deltas = out.deltas.data() + size_t(t) * count;
        auto read = [&](const char* name, std::initializer_list<int> types, auto&& store) {
            const int accessor = attributeAccessor(target, name);
            if (accessor < 0) return;
            const std::vector<glm::vec4> values = readCounted(ctx, model, accessor, types, count, targetWhat + " " + name);
            for (size_t i = 0; i < count; ++i) store(deltas[i], values[i]);
        };
        read("POSITION", {TINYGLTF_TYPE_VEC3}, [](scene::MorphDelta& d, const glm::vec4& v) { d.position = glm::vec4(glm::vec3(v), 0.0f); });
        read("NORMAL", {TINYGLTF_TYPE_VEC3}, [](scene::MorphDelta& d, const glm::vec4& v) { d.normal = glm::vec4(glm::vec3(v), 0.0f); });
        read("TANGENT", {TINYGLTF_TYPE_VEC3}, [](scene::MorphDelta& d, const glm::vec4& v) { d.tangent = glm::vec4(glm::vec3(v), 0.0f); });
        read("TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, [](scene::MorphDelta& d, const glm::vec4& v) { d.uv.x = v.x, d.uv.y = v.y; });
        read("TEXCOORD_1", {TINYGLTF_TYPE_VEC2}, [](scene::MorphDelta& d, const glm::vec4& v) { d.uv.z = v.x, d.uv.w = v.y; });
        // An RGB colour delta leaves alpha unchanged.
        read("COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, [&](scene::MorphDelta& d, const glm::vec4& v) { d.color = v; });
        if (const int color = attributeAccessor(target, "COLOR_0");
            color >= 0 && model.accessors[size_t(color)].type == TINYGLTF_TYPE_VEC3)
            for (size_t i = 0; i < count; ++i) deltas[i].color.w = 0.0f;
    }
}

void readSkinWeights(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                     const std::string& what, size_t count, SourceDeformation& out) {
    uint32_t sets = 0;
    while (attributeAccessor(primitive.attributes, "JOINTS_" + std::to_string(sets)) >= 0) ++sets;
    if (sets == 0) {
        if (attributeAccessor(primitive.attributes, "WEIGHTS_0") >= 0) ctx.fail(what + ": WEIGHTS_0 without JOINTS_0");
        return;
    }
    out.influencesPerVertex = 4 * sets;
    out.influences.assign(count * out.influencesPerVertex, scene::JointInfluence{});
    for (uint32_t set = 0; set < sets; ++set) {
        const std::string joints = "JOINTS_" + std::to_string(set), weights = "WEIGHTS_" + std::to_string(set);
        const int jointAccessor = attributeAccessor(primitive.attributes, joints);
        const int weightAccessor = attributeAccessor(primitive.attributes, weights);
        if (weightAccessor < 0) ctx.fail(what + ": " + joints + " without " + weights);
        const std::vector<glm::vec4> j = readCounted(ctx, model, jointAccessor, {TINYGLTF_TYPE_VEC4}, count, what + " " + joints);
        const tinygltf::Accessor& ja = model.accessors[size_t(jointAccessor)];
        if ((ja.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ja.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) ||
            ja.normalized)
            ctx.fail(what + " " + joints + ": accessor " + std::to_string(jointAccessor) +
                     " must be VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT, not componentType " + std::to_string(ja.componentType));
        const std::vector<float> w = readFloats(ctx, model, weightAccessor, TINYGLTF_TYPE_VEC4, true, what + " " + weights);
        if (w.size() != 4 * count)
            ctx.fail(what + " " + weights + ": " + std::to_string(w.size() / 4) + " elements, POSITION has " + std::to_string(count));
        for (size_t v = 0; v < count; ++v)
            for (uint32_t c = 0; c < 4; ++c) {
                const float weight = w[4 * v + c];
                if (!std::isfinite(weight) || weight < 0.0f)
                    ctx.fail(what + " " + weights + ": vertex " + std::to_string(v) + " has weight " + std::to_string(weight) +
                             " (weights must be finite and >= 0)");
                out.influences[v * out.influencesPerVertex + 4 * set + c] = {uint32_t(j[v][int(c)]), weight};
            }
    }
    for (size_t v = 0; v < count; ++v) {
        scene::JointInfluence* influences = out.influences.data() + v * out.influencesPerVertex;
        double sum = 0.0;
        for (uint32_t i = 0; i < out.influencesPerVertex; ++i) sum += influences[i].weight;
        if (!(sum > 0.0)) ctx.fail(what + ": vertex " + std::to_string(v) + " has no joint weight (all are 0)");
        if (std::abs(sum - 1.0) > 0.01) ++out.renormalized;
        for (uint32_t i = 0; i < out.influencesPerVertex; ++i) {
            influences[i].weight = float(influences[i].weight / sum);
            if (influences[i].weight > 0.0f) out.maxJoint = std::max(out.maxJoint, influences[i].joint);
        }
    }
}

}  // namespace

SourceDeformation readDeformation(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                  const std::string& what, size_t vertexCount) {
    SourceDeformation out;
    readTargets(ctx, model, primitive, what, vertexCount, out);
    readSkinWeights(ctx, model, primitive, what, vertexCount, out);
    return out;
}

scene::Deformation remapDeformation(const SourceDeformation& source, std::span<const uint32_t> origin, uint32_t firstVertex) {
    const size_t count = origin.size();
    const size_t sourceCount = source.targetCount ? source.deltas.size() / source.targetCount
                               : source.influencesPerVertex ? source.influences.size() / source.influencesPerVertex
                                                            : 0;
    scene::Deformation out{.firstVertex = firstVertex, .vertexCount = uint32_t(count), .targetCount = source.targetCount,
                    .influencesPerVertex = source.influencesPerVertex, .maxJoint = source.maxJoint};
    out.deltas.resize(size_t(source.targetCount) * count);
    out.maxPositionDelta.assign(source.targetCount, glm::vec3(0.0f));
    for (uint32_t t = 0; t < source.targetCount; ++t)
        for (size_t v = 0; v < count; ++v) {
            const scene::MorphDelta& d = source.deltas[t * sourceCount + origin[v]];
            out.deltas[t * count + v] = d;
            out.maxPositionDelta[t] = glm::max(out.maxPositionDelta[t], glm::abs(glm::vec3(d.position)));
        }
    out.influences.resize(count * source.influencesPerVertex);
    for (size_t v = 0; v < count; ++v)
        for (uint32_t i = 0; i < source.influencesPerVertex; ++i)
            out.influences[v * source.influencesPerVertex + i] = source.influences[origin[v] * source.influencesPerVertex + i];
    return out;
}

}  // namespace candela::assets::gltf
