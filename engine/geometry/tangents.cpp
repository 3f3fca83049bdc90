#include "geometry/tangents.h"

#include "geometry/mesh_normals.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace candela::geometry {
namespace {

// MikkTSpace's tests for "not zero".
bool notZero(float x) { return std::fabs(x) > FLT_MIN; }
bool notZero(const glm::vec3& v) { return notZero(v.x) || notZero(v.y) || notZero(v.z); }

glm::vec3 normalizeIfNotZero(const glm::vec3& v) { return notZero(v) ? glm::normalize(v) : v; }

// The component of v in the plane orthogonal to n (n unit), normalized if not zero.
glm::vec3 projectNormalized(const glm::vec3& v, const glm::vec3& n) { return normalizeIfNotZero(v - n * glm::dot(n, v)); }

// Exact equality as MikkTSpace compares floats (-0 == +0): the bits of x + 0.
uint32_t keyBits(float x) {
    x += 0.0f;
    uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
}

struct WeldKey {
    std::array<uint32_t, 8> bits;
    bool operator==(const WeldKey&) const = default;
};

struct WeldKeyHash {
    size_t operator()(const WeldKey& key) const {
        uint64_t h = 1469598103934665603ull;
        for (uint32_t b : key.bits) h = (h ^ b) * 1099511628211ull;
        return size_t(h);
    }
};

struct Triangle {
    std::array<uint32_t, 3> v{};  // welded vertex ids
    glm::vec3 os{0.0f};           // unit texture-space tangent direction (∂P/∂u), or 0
    bool orient = false;          // texture-space area > 0 (orientation preserving)
    bool groupWithAny = true;     // no usable texture-space extent: joins any group, adds nothing
    bool degenerate = false;      // two corners at the same position
    std::array<int, 3> neighbor{-1, -1, -1};  // across edge i (corner i → corner i+1)
    std::array<int, 3> group{-1, -1, -1};     // group of corner i
};

// A group's triangles are groupTriangles[begin, end): each group is grown whole before the next starts.
struct Group {
    uint32_t vertex;
    bool orient;
    uint32_t begin = 0, end = 0;
};

int cornerOf(const Triangle& t, uint32_t vertex) {
    for (int i = 0; i < 3; ++i)
        if (t.v[size_t(i)] == vertex) return i;
    return -1;
}

// MikkTSpace's AssignRecur from triangle `start`, iteratively (a vertex can have thousands of
// triangles around it), appending the group's triangles to `triangles`; `stack` is scratch. Pushing
// the right neighbour before the left one visits triangles in the recursive version's order, which
// matters for which group a group-with-any triangle's orientation comes from.
void growGroup(std::vector<Triangle>& tris, int groupIndex, const Group& group, int start, std::vector<uint32_t>& triangles,
               std::vector<int>& stack) {
    stack.assign(1, start);
    while (!stack.empty()) {
        const int t = stack.back();
        stack.pop_back();
        Triangle& tri = tris[size_t(t)];
        const int i = cornerOf(tri, group.vertex);
        if (i < 0 || tri.group[size_t(i)] >= 0) continue;
        if (tri.groupWithAny && tri.group[0] < 0 && tri.group[1] < 0 && tri.group[2] < 0) tri.orient = group.orient;
        if (tri.orient != group.orient) continue;
        triangles.push_back(uint32_t(t));
        tri.group[size_t(i)] = groupIndex;
        const int left = tri.neighbor[size_t(i)];
        const int right = tri.neighbor[size_t(i > 0 ? i - 1 : 2)];
        if (right >= 0) stack.push_back(right);
        if (left >= 0) stack.push_back(left);
    }
}

}  // namespace

glm::vec4 fallbackTangent(const glm::vec3& normal) {
    const glm::vec3 n = normalizeOrZero(normal);
    if (n == glm::vec3(0.0f)) return glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    // The axis least aligned with n, made orthogonal to it.
    const glm::vec3 a = std::fabs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::vec4(glm::normalize(a - n * glm::dot(n, a)), 1.0f);
}

std::vector<glm::vec4> generateTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> uvs, std::span<const uint32_t> indices) {
    assert(positions.size() == normals.size() && positions.size() == uvs.size());
    const size_t triangleCount = indices.size() / 3;

    // 1. Weld corners by exact position, normal and (v-negated) texcoord.
    std::vector<glm::vec3> wPos, wNormal;
    std::vector<glm::vec2> wUv;
    std::vector<int64_t> weldOf(positions.size(), -1);
    std::unordered_map<WeldKey, uint32_t, WeldKeyHash> welded;
    welded.reserve(positions.size());
    auto weld = [&](uint32_t v) {
        if (weldOf[v] >= 0) return uint32_t(weldOf[v]);
        const glm::vec3& p = positions[v];
        const glm::vec3& n = normals[v];
        const glm::vec2 uv(uvs[v].x, -uvs[v].y);
        const WeldKey key{{keyBits(p.x), keyBits(p.y), keyBits(p.z), keyBits(n.x), keyBits(n.y), keyBits(n.z),
                           keyBits(uv.x), keyBits(uv.y)}};
        auto [it, inserted] = welded.try_emplace(key, uint32_t(wPos.size()));
        if (inserted) {
            wPos.push_back(p);
            wNormal.push_back(n);
            wUv.push_back(uv);
        }
        weldOf[v] = it->second;
        return it->second;
    };

    // 2. Per-triangle texture-space tangent and orientation (MikkTSpace's InitTriInfo).
    std::vector<Triangle> tris(triangleCount);
    for (size_t t = 0; t < triangleCount; ++t) {
        Triangle& tri = tris[t];
        for (size_t i = 0; i < 3; ++i) tri.v[i] = weld(indices[3 * t + i]);
        const glm::vec3 &p1 = wPos[tri.v[0]], &p2 = wPos[tri.v[1]], &p3 = wPos[tri.v[2]];
        if (p1 == p2 || p1 == p3 || p2 == p3) {
            tri.degenerate = true;
            continue;
        }
        const glm::vec2 &t1 = wUv[tri.v[0]], &t2 = wUv[tri.v[1]], &t3 = wUv[tri.v[2]];
        const float t21x = t2.x - t1.x, t21y = t2.y - t1.y, t31x = t3.x - t1.x, t31y = t3.y - t1.y;
        const glm::vec3 d1 = p2 - p1, d2 = p3 - p1;
        const float signedArea = t21x * t31y - t21y * t31x;
        const glm::vec3 os = t31y * d1 - t21y * d2;
        const glm::vec3 ot = -t31x * d1 + t21x * d2;
        tri.orient = signedArea > 0.0f;
        if (notZero(signedArea)) {
            const float absArea = std::fabs(signedArea);
            const float lenOs = glm::length(os), lenOt = glm::length(ot);
            const float sign = tri.orient ? 1.0f : -1.0f;
            if (notZero(lenOs)) tri.os = (sign / lenOs) * os;
            if (notZero(lenOs / absArea) && notZero(lenOt / absArea)) tri.groupWithAny = false;
        }
    }

    // 3. Neighbours across shared edges of consistently wound, non-degenerate triangles. The directed
    // edges a → b, bucketed by a (a counting sort: within a bucket in triangle and edge order, so
    // an edge's candidates are met in the order they were made).
    struct Edge {
        uint32_t to, triangle;
        uint8_t edge;
    };
    std::vector<uint32_t> edgeStart(wPos.size() + 1, 0);
    for (size_t t = 0; t < triangleCount; ++t)
        if (!tris[t].degenerate)
            for (size_t e = 0; e < 3; ++e) ++edgeStart[tris[t].v[e] + 1];
    for (size_t v = 0; v < wPos.size(); ++v) edgeStart[v + 1] += edgeStart[v];
    std::vector<Edge> edges(edgeStart.back());
    {
        std::vector<uint32_t> fill(edgeStart.begin(), edgeStart.end() - 1);
        for (size_t t = 0; t < triangleCount; ++t)
            if (!tris[t].degenerate)
                for (uint8_t e = 0; e < 3; ++e) edges[fill[tris[t].v[e]]++] = {tris[t].v[(e + 1) % 3], uint32_t(t), e};
    }
    for (size_t t = 0; t < triangleCount; ++t) {
        if (tris[t].degenerate) continue;
        for (size_t e = 0; e < 3; ++e) {
            if (tris[t].neighbor[e] >= 0) continue;
            // The opposite edge, v[e + 1] → v[e].
            const uint32_t from = tris[t].v[(e + 1) % 3], to = tris[t].v[e];
            for (uint32_t k = edgeStart[from]; k < edgeStart[from + 1]; ++k) {
                const Edge& other = edges[k];
                if (other.to != to || other.triangle == t || tris[other.triangle].neighbor[other.edge] >= 0) continue;
                tris[t].neighbor[e] = int(other.triangle);
                tris[other.triangle].neighbor[other.edge] = int(t);
                break;
            }
        }
    }

    // 4. Groups: per welded vertex, edge-connected triangles of one orientation (Build4RuleGroups).
    std::vector<Group> groups;
    std::vector<uint32_t> groupTriangles;
    std::vector<int> stack;
    for (size_t t = 0; t < triangleCount; ++t) {
        Triangle& tri = tris[t];
        if (tri.degenerate || tri.groupWithAny) continue;
        for (size_t i = 0; i < 3; ++i) {
            if (tri.group[i] >= 0) continue;
            const int groupIndex = int(groups.size());
            Group& group = groups.emplace_back(Group{tri.v[i], tri.orient, uint32_t(groupTriangles.size())});
            groupTriangles.push_back(uint32_t(t));
            tri.group[i] = groupIndex;
            const int left = tri.neighbor[i], right = tri.neighbor[i > 0 ? i - 1 : 2];
            // The recursive original handles the left neighbour's whole fan before the right one.
            if (left >= 0) growGroup(tris, groupIndex, group, left, groupTriangles, stack);
            if (right >= 0) growGroup(tris, groupIndex, group, right, groupTriangles, stack);
            group.end = uint32_t(groupTriangles.size());
        }
    }

    // 5. Per group: angle-weighted sum of the projected per-triangle tangents (EvalTspace).
    std::vector<glm::vec3> groupTangent(groups.size(), glm::vec3(0.0f));
    for (size_t g = 0; g < groups.size(); ++g) {
        const Group& group = groups[g];
        const glm::vec3& n = wNormal[group.vertex];
        glm::vec3 sum(0.0f);
        for (uint32_t k = group.begin; k < group.end; ++k) {
            const Triangle& tri = tris[groupTriangles[k]];
            if (tri.groupWithAny) continue;
            const int i = cornerOf(tri, group.vertex);
            const glm::vec3& p0 = wPos[tri.v[size_t(i > 0 ? i - 1 : 2)]];
            const glm::vec3& p1 = wPos[tri.v[size_t(i)]];
            const glm::vec3& p2 = wPos[tri.v[size_t(i < 2 ? i + 1 : 0)]];
            const glm::vec3 e1 = projectNormalized(p0 - p1, n), e2 = projectNormalized(p2 - p1, n);
            const float angle = std::acos(std::clamp(glm::dot(e1, e2), -1.0f, 1.0f));
            sum += angle * projectNormalized(tri.os, n);
        }
        groupTangent[g] = normalizeIfNotZero(sum);
    }

    // 6. Per corner; degenerate triangles copy the first good corner of the same welded vertex.
    std::vector<glm::vec4> out(indices.size());
    std::vector<int64_t> goodCorner(wPos.size(), -1);
    auto cornerTangent = [&](size_t t, size_t i) {
        const int g = tris[t].group[i];
        const glm::vec3 n = wNormal[tris[t].v[i]];
        if (g < 0 || !notZero(groupTangent[size_t(g)])) return fallbackTangent(n);
        return glm::vec4(groupTangent[size_t(g)], groups[size_t(g)].orient ? 1.0f : -1.0f);
    };
    for (size_t t = 0; t < triangleCount; ++t) {
        if (tris[t].degenerate) continue;
        for (size_t i = 0; i < 3; ++i) {
            out[3 * t + i] = cornerTangent(t, i);
            if (goodCorner[tris[t].v[i]] < 0) goodCorner[tris[t].v[i]] = int64_t(3 * t + i);
        }
    }
    for (size_t t = 0; t < triangleCount; ++t) {
        if (!tris[t].degenerate) continue;
        for (size_t i = 0; i < 3; ++i) {
            const int64_t source = goodCorner[tris[t].v[i]];
            out[3 * t + i] = source >= 0 ? out[size_t(source)] : fallbackTangent(wNormal[tris[t].v[i]]);
        }
    }
    for (size_t c = triangleCount * 3; c < indices.size(); ++c) out[c] = fallbackTangent(normals[indices[c]]);
    // Float overflow in the sums above (positions near the float range, slivers) must not reach the
    // GPU as NaN: such corners take the fallback too.
    for (size_t c = 0; c < out.size(); ++c)
        if (!std::isfinite(out[c].x) || !std::isfinite(out[c].y) || !std::isfinite(out[c].z))
            out[c] = fallbackTangent(normals[indices[c]]);
    return out;
}

}  // namespace candela::geometry
