#include "assets/gltf_mesh.h"

#include "assets/gltf_accessors.h"
#include "assets/gltf_deform.h"
#include "geometry/mesh_normals.h"
#include "geometry/tangents.h"
#include "scene/texture_transform.h"

#include <glm/geometric.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <limits>
#include <numeric>

namespace candela::assets::gltf {
namespace {

scene::Topology topologyOf(int mode) {
    if (mode == TINYGLTF_MODE_POINTS) return scene::Topology::Points;
    if (mode >= TINYGLTF_MODE_LINE && mode <= TINYGLTF_MODE_LINE_STRIP) return scene::Topology::Lines;
    return scene::Topology::Triangles;
}

// Reads the vertex attributes of one primitive into `vertices` (positions already set).
struct Attributes {
    bool normals = false;
    bool tangents = false;
    bool uv[2] = {false, false};
};

Attributes readAttributes(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                          const std::string& what, std::vector<scene::Vertex>& vertices) {
    const size_t count = vertices.size();
    auto read = [&](const char* name, std::initializer_list<int> types) {
        auto it = primitive.attributes.find(name);
        if (it == primitive.attributes.end()) return std::vector<glm::vec4>{};
        std::vector<glm::vec4> values = readVectors(ctx, model, it->second, types, what + " " + name);
        if (values.size() != count)
            ctx.fail(what + " " + name + ": " + std::to_string(values.size()) + " elements, POSITION has " +
                     std::to_string(count));
        return values;
    };
    const auto normals = read("NORMAL", {TINYGLTF_TYPE_VEC3});
    const auto tangents = read("TANGENT", {TINYGLTF_TYPE_VEC4});
    const auto uv0 = read("TEXCOORD_0", {TINYGLTF_TYPE_VEC2});
    const auto uv1 = read("TEXCOORD_1", {TINYGLTF_TYPE_VEC2});
    const auto colors = read("COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4});
    const bool rgb = !colors.empty() && model.accessors[size_t(primitive.attributes.at("COLOR_0"))].type == TINYGLTF_TYPE_VEC3;

    // Non-finite attributes (other than positions) are repaired, not fatal: exporters do write them.
    // Counted per attribute: TEXCOORD_0, TEXCOORD_1, COLOR_0, NORMAL, TANGENT.
    std::array<size_t, 5> repaired{};
    auto orDefault = [&](size_t attribute, const glm::vec4& v, const glm::vec4& fallback) {
        if (finite(v)) return v;
        ++repaired[attribute];
        return fallback;
    };
    for (size_t i = 0; i < count; ++i) {
        scene::Vertex& v = vertices[i];
        if (!uv0.empty()) v.uv0 = glm::vec2(orDefault(0, uv0[i], glm::vec4(0.0f)));
        if (!uv1.empty()) v.uv1 = glm::vec2(orDefault(1, uv1[i], glm::vec4(0.0f)));
        if (!colors.empty()) v.color = orDefault(2, rgb ? glm::vec4(glm::vec3(colors[i]), 1.0f) : colors[i], glm::vec4(1.0f));
        if (!normals.empty()) {
            const glm::vec3 n(orDefault(3, normals[i], glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)));
            // Zero-length normals stay zero (the shader copes); others are made unit length.
            v.normal = geometry::normalizeOrZero(n);
        }
        if (!tangents.empty() && !normals.empty()) {
            const glm::vec4 t = orDefault(4, tangents[i], glm::vec4(0.0f));
            const glm::vec3 xyz = geometry::normalizeOrZero(glm::vec3(t));
            v.tangent = xyz != glm::vec3(0.0f) ? glm::vec4(xyz, t.w < 0.0f ? -1.0f : 1.0f) : geometry::fallbackTangent(v.normal);
        }
    }
    constexpr std::array<const char*, 5> kNames = {"TEXCOORD_0", "TEXCOORD_1", "COLOR_0", "NORMAL", "TANGENT"};
    for (size_t a = 0; a < repaired.size(); ++a)
        if (repaired[a])
            ctx.warn(what + " " + kNames[a] + ": " + std::to_string(repaired[a]) + " non-finite value" +
                     (repaired[a] == 1 ? "" : "s") + " replaced by the default");
    return {!normals.empty(), !tangents.empty(), {!uv0.empty(), !uv1.empty()}};
}

// MikkTSpace tangents for the UV set of `tangentMap` (a normal map, or the texture an anisotropy
// direction follows); corners of one vertex that get different tangents (mirrored UVs, seams)
// become separate vertices.
void generateVertexTangents(const LoadContext& ctx, const std::string& what, const scene::TextureRef& tangentMap,
                            const Attributes& attributes, std::vector<scene::Vertex>& vertices, std::vector<uint32_t>& indices,
                            std::vector<uint32_t>& origin) {
    const uint32_t set = tangentMap.texCoord;
    if (!attributes.uv[set]) {
        ctx.warn(what + ": its tangent frame (normal map or anisotropy) follows TEXCOORD_" + std::to_string(set) +
                 ", which the primitive lacks; tangents are arbitrary");
        for (scene::Vertex& v : vertices) v.tangent = geometry::fallbackTangent(v.normal);
        return;
    }
    // The tangent frame follows the texture's own axes, so the UVs go through its transform (offset
    // does not change derivatives and is left out).
    scene::TextureTransform linear = tangentMap.transform;
    linear.offset = glm::vec2(0.0f);
    std::vector<glm::vec3> positions(vertices.size()), normals(vertices.size());
    std::vector<glm::vec2> uvs(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        positions[i] = vertices[i].position;
        normals[i] = vertices[i].normal;
        const glm::vec2 uv = set == 0 ? vertices[i].uv0 : vertices[i].uv1;
        uvs[i] = linear.identity() ? uv : scene::applyTextureTransform(linear, uv);
    }
    const std::vector<glm::vec4> tangents = geometry::generateTangents(positions, normals, uvs, indices);

    std::vector<scene::Vertex> split;
    split.reserve(vertices.size());
    std::vector<uint32_t> splitOrigin;
    std::vector<int64_t> first(vertices.size(), -1);  // first split vertex made from each vertex
    std::vector<int64_t> next;                        // chain of split vertices from the same vertex
    for (size_t c = 0; c < indices.size(); ++c) {
        const uint32_t source = indices[c];
        int64_t found = -1, last = -1;
        for (int64_t k = first[source]; k >= 0; last = k, k = next[size_t(k)])
            if (split[size_t(k)].tangent == tangents[c]) {
                found = k;
                break;
            }
        if (found < 0) {
            found = int64_t(split.size());
            split.push_back(vertices[source]);
            split.back().tangent = tangents[c];
            splitOrigin.push_back(origin[source]);
            next.push_back(-1);
            (last < 0 ? first[source] : next[size_t(last)]) = found;
        }
        indices[c] = uint32_t(found);
    }
    vertices = std::move(split);
    origin = std::move(splitOrigin);
}

}  // namespace

std::vector<uint32_t> toTriangleList(int mode, std::span<const uint32_t> in) {
    std::vector<uint32_t> out;
    const size_t n = in.size();
    auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (a == b || b == c || a == c) return;
        out.insert(out.end(), {a, b, c});
    };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(in.begin(), in.begin() + std::ptrdiff_t(n - n % 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        out.reserve(n >= 2 ? 3 * (n - 2) : 0);
        // p_i = {v_i, v_(i+1+i%2), v_(i+2-i%2)} keeps every triangle's winding.
        for (size_t i = 0; i + 2 < n; ++i)
            i % 2 == 0 ? add(in[i], in[i + 1], in[i + 2]) : add(in[i], in[i + 2], in[i + 1]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        out.reserve(n >= 2 ? 3 * (n - 2) : 0);
        // p_i = {v_(i+1), v_(i+2), v_0}.
        for (size_t i = 0; i + 2 < n; ++i) add(in[i + 1], in[i + 2], in[0]);
    }
    return out;
}

std::vector<uint32_t> toLineList(int mode, std::span<const uint32_t> in) {
    std::vector<uint32_t> out;
    const size_t n = in.size();
    if (mode == TINYGLTF_MODE_LINE) {
        out.assign(in.begin(), in.begin() + std::ptrdiff_t(n - n % 2));
        return out;
    }
    // LINE_STRIP: p_i = {v_i, v_(i+1)}; LINE_LOOP adds {v_(n-1), v_0}.
    for (size_t i = 0; i + 1 < n; ++i) out.insert(out.end(), {in[i], in[i + 1]});
    if (mode == TINYGLTF_MODE_LINE_LOOP && n >= 2) out.insert(out.end(), {in[n - 1], in[0]});
    return out;
}

size_t dropZeroAreaTriangles(std::span<const scene::Vertex> vertices, std::vector<uint32_t>& indices) {
    size_t kept = 0;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 a(vertices[indices[t]].position), b(vertices[indices[t + 1]].position),
            c(vertices[indices[t + 2]].position);
        if (glm::cross(b - a, c - a) == glm::dvec3(0.0)) continue;
        for (size_t k = 0; k < 3; ++k) indices[kept + k] = indices[t + k];
        kept += 3;
    }
    const size_t dropped = (indices.size() - kept) / 3;
    indices.resize(kept);
    return dropped;
}

PrimitiveSource primitiveSource(const tinygltf::Model& model, int meshIndex, int primitiveIndex, const scene::TextureRef* tangentMap) {
    const tinygltf::Primitive& primitive = model.meshes[size_t(meshIndex)].primitives[size_t(primitiveIndex)];
    PrimitiveSource source{.mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode,
                           .indices = primitive.indices,
                           .attributes = primitive.attributes,
                           .targets = primitive.targets};
    if (tangentMap) {
        source.generatedTangents = true;
        source.tangentTexCoord = tangentMap->texCoord;
        source.tangentRotation = tangentMap->transform.rotation;
        source.tangentScaleX = tangentMap->transform.scale.x;
        source.tangentScaleY = tangentMap->transform.scale.y;
    }
    return source;
}

PrimitiveGeometry appendPrimitive(const LoadContext& ctx, const tinygltf::Model& model, int meshIndex, int primitiveIndex,
                                  const scene::TextureRef* tangentMap, scene::Scene& scene) {
    const tinygltf::Mesh& mesh = model.meshes[size_t(meshIndex)];
    const tinygltf::Primitive& primitive = mesh.primitives[size_t(primitiveIndex)];
    const std::string what = label("mesh", meshIndex, mesh.name) + " primitive " + std::to_string(primitiveIndex);
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode > TINYGLTF_MODE_TRIANGLE_FAN) ctx.fail(what + ": invalid mode " + std::to_string(mode));
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
        ctx.tally(Severity::Warning, {"primitive", "no POSITION attribute, not drawn"}, what);
        return {};
    }

    const std::vector<glm::vec4> positions = readVectors(ctx, model, position->second, {TINYGLTF_TYPE_VEC3}, what + " POSITION");
    const size_t count = positions.size();
    std::vector<scene::Vertex> vertices(count);
    for (size_t i = 0; i < count; ++i) {
        if (!finite(positions[i])) ctx.fail(what + " POSITION: vertex " + std::to_string(i) + " is not finite (NaN or infinity)");
        vertices[i].position = glm::vec3(positions[i]);
    }
    const Attributes attributes = readAttributes(ctx, model, primitive, what, vertices);
    const SourceDeformation deformation = readDeformation(ctx, model, primitive, what, count);

    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
        indices = readIndices(ctx, model, primitive.indices, what + " indices");
        for (size_t k = 0; k < indices.size(); ++k)
            if (indices[k] >= count)
                ctx.fail(what + ": index " + std::to_string(indices[k]) + " (element " + std::to_string(k) +
                         ") >= vertex count " + std::to_string(count));
    } else {
        indices.resize(count);
        std::iota(indices.begin(), indices.end(), 0u);
    }
    const scene::Topology topology = topologyOf(mode);
    std::vector<uint32_t> origin(vertices.size());
    std::iota(origin.begin(), origin.end(), 0u);
    if (topology == scene::Topology::Triangles) {
        if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
            ctx.warn(what + ": " + std::to_string(indices.size()) + " indices is not a multiple of 3 (extra dropped)");
        indices = toTriangleList(mode, indices);
        // Degenerate triangles cover no pixel: the glTF-Validator reports them as information.
        if (const size_t dropped = dropZeroAreaTriangles(vertices, indices))
            ctx.tally(Severity::Note, {"primitive", "zero-area triangle dropped", "zero-area triangles dropped"}, what, dropped);
        if (indices.empty()) {
            ctx.tally(Severity::Note, {"primitive", "no triangles, skipped"}, what);
            return {};
        }
        // Without normals the specification asks for flat normals, and any TANGENT is ignored.
        // Both steps may split vertices: `origin` maps each vertex to the file's vertex it came from.
        if (!attributes.normals) geometry::makeFlatNormals(vertices, indices, origin);
        const bool haveTangents = attributes.tangents && attributes.normals;
        if (!haveTangents && tangentMap)
            generateVertexTangents(ctx, what, *tangentMap, attributes, vertices, indices, origin);
    } else {
        if (mode == TINYGLTF_MODE_LINE && indices.size() % 2 != 0)
            ctx.warn(what + ": " + std::to_string(indices.size()) + " indices is not a multiple of 2 (extra dropped)");
        if (topology == scene::Topology::Lines) indices = toLineList(mode, indices);
        if (indices.empty()) {
            ctx.tally(Severity::Note, {"primitive", "nothing to draw, skipped"}, what);
            return {};
        }
        // Points and lines have no surface to derive a normal or a tangent frame from: without
        // NORMAL they are drawn unshaded; with it, a normal map's tangent follows the normal.
        if (attributes.normals && !attributes.tangents && tangentMap)
            for (scene::Vertex& v : vertices) v.tangent = geometry::fallbackTangent(v.normal);
    }

    const size_t base = scene.vertices.size();
    if (base + vertices.size() > std::numeric_limits<uint32_t>::max() ||
        scene.indices.size() + indices.size() > std::numeric_limits<uint32_t>::max())
        ctx.fail(what + ": the scene exceeds 2^32 vertices or indices");
    PrimitiveGeometry out;
    out.drawable = true;
    out.topology = topology;
    out.unshaded = topology != scene::Topology::Triangles && !attributes.normals;
    out.firstIndex = uint32_t(scene.indices.size());
    out.indexCount = uint32_t(indices.size());
    for (uint32_t i : indices) {
        out.bounds.extend(vertices[i].position);
        scene.indices.push_back(uint32_t(base + i));
    }
    scene.vertices.insert(scene.vertices.end(), vertices.begin(), vertices.end());
    if (!deformation.empty()) {
        out.deformation = int32_t(scene.deformations.size());
        out.renormalizedWeights = deformation.renormalized;
        scene.deformations.push_back(assets::gltf::remapDeformation(deformation, origin, uint32_t(base)));
    }
    return out;
}

}  // namespace candela::assets::gltf
