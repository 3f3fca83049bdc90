// Levels of detail (geometry/mesh_lod.h) and the geometry preparation (geometry/mesh_optimize.h): the
// simplified levels against the surface they stand for, locked borders and seams, the choice of a
// level from its projected error, and what the preparation must leave alone.
#include "assets/builtin_scenes.h"
#include "geometry/mesh_lod.h"
#include "geometry/mesh_optimize.h"
#include "options/draw_selection.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace candela::geometry {
namespace {

// A unit UV sphere (64 × 32, as the built-in grid's) alone in a scene, indices relative to its vertices.
scene::Scene sphere() {
    scene::Scene scene;
    assets::appendUvSphere(scene, 1.0f, 64, 32);
    return scene;
}

// The distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
float pointTriangleDistance(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const float denom = 1.0f / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

// The largest distance from a vertex of `from` to the surface of triangle list `to`.
float oneSidedDistance(const std::vector<scene::Vertex>& v, const std::vector<uint32_t>& from, const std::vector<uint32_t>& to) {
    float worst = 0.0f;
    for (uint32_t i : std::set<uint32_t>(from.begin(), from.end())) {
        float nearest = INFINITY;
        for (size_t t = 0; t < to.size(); t += 3)
            nearest = std::min(nearest, pointTriangleDistance(v[i].position, v[to[t]].position, v[to[t + 1]].position, v[to[t + 2]].position));
        worst = std::max(worst, nearest);
    }
    return worst;
}

TEST(MeshLod, SphereChainGetsCoarserWithGrowingErrorWithinTheMemoryBudget) {
    const scene::Scene s = sphere();
    const std::vector<SimplifiedLevel> levels = simplifyChain(s.vertices, s.indices);
    // Two: the poles' 65 coincident vertices (one per UV column) are locked, so the third level
    // would keep more than 0.6 of the second's triangles.
    ASSERT_GE(levels.size(), 2u);
    size_t previous = s.indices.size(), extra = 0;
    float previousError = 0.0f;
    for (const SimplifiedLevel& level : levels) {
        EXPECT_EQ(level.indices.size() % 3, 0u);
        EXPECT_LE(double(level.indices.size()), 0.6 * double(previous));
        EXPECT_GE(level.error, previousError);
        previous = level.indices.size(), previousError = level.error, extra += level.indices.size();
    }
    EXPECT_LE(double(extra), 0.5 * double(s.indices.size()));
}

TEST(MeshLod, EachLevelStaysWithinItsErrorOfTheFullDetail) {
    // Brute force, every vertex of each against every triangle of the other: no level lies further
    // from the full detail than its error says (the simplifier's own estimate alone would not hold).
    const scene::Scene s = sphere();
    for (const SimplifiedLevel& level : simplifyChain(s.vertices, s.indices)) {
        const float distance = std::max(oneSidedDistance(s.vertices, s.indices, level.indices),
                                        oneSidedDistance(s.vertices, level.indices, s.indices));
        EXPECT_LE(distance, level.error * 1.00001f) << level.indices.size() / 3 << " triangles";
        // ...and the error is no gross overestimate either (it picks the level).
        EXPECT_GE(distance, 0.5f * level.error) << level.indices.size() / 3 << " triangles";
    }
}

TEST(MeshLod, TheBuiltInSpheresChainLeavesNoGapAtTheDefaultView) {
    // The default view (1280 × 720) sees the grid's spheres at about 35 px per metre. The chain
    // once went from 64 × 32 straight to 24 × 12, whose error (0.0164 m, 0.57 px there) missed the
    // 0.5 px default: every sphere drew its full 3,968 triangles. No step may multiply the error
    // by more than 2.5 (a step is one level per distance doubling, DistanceDoublingMovesOneLevel),
    // and the first level (32 × 16: 0.0096 m, 0.33 px) must show at most 0.75 of the default there.
    const scene::Scene grid = assets::makeSphereGrid();
    ASSERT_EQ(grid.lodChains.size(), 1u);
    const scene::LodChain& chain = grid.lodChains[0];
    ASSERT_GE(chain.levels.size(), 3u);
    for (size_t i = 1; i < chain.levels.size(); ++i) {
        std::printf("level %zu: %u triangles, error %.4f m (%.2f px at 35 px/m)\n", i, chain.levels[i].indexCount / 3,
                    double(chain.levels[i].error), double(chain.levels[i].error * 35.0f));
        if (i >= 2) {
            EXPECT_LE(chain.levels[i].error, 2.5f * chain.levels[i - 1].error) << "level " << i;
        }
    }
    EXPECT_LE(chain.levels[1].error * 35.0f, 0.75f * options::DrawSelection::kDefaultLodErrorPixels);
}

TEST(MeshLod, SurfaceDeviationMatchesBruteForce) {
    // The grid search against the brute-force distance, both ways, on the sphere and a coarser sphere.
    scene::Scene s;
    const auto [fine, fineCount] = assets::appendUvSphere(s, 1.0f, 48, 24);
    const auto [coarse, coarseCount] = assets::appendUvSphere(s, 1.0f, 10, 5);
    const std::vector<uint32_t> a(s.indices.begin() + fine, s.indices.begin() + fine + fineCount);
    const std::vector<uint32_t> b(s.indices.begin() + coarse, s.indices.begin() + coarse + coarseCount);
    const float brute = std::max(oneSidedDistance(s.vertices, a, b), oneSidedDistance(s.vertices, b, a));
    const float grid = surfaceDeviation(s.vertices, a, b);
    EXPECT_GE(grid, brute * 0.9999f);  // it samples the coarse edge midpoints and centres too: never less
    EXPECT_LE(grid, brute * 1.5f);
    // Analytically: a 10 × 5 sphere's quads at the equator dip below the unit sphere by 1 − cos²18°
    // at their centres (half of 36° each way).
    EXPECT_NEAR(grid, 1.0f - std::cos(glm::radians(18.0f)) * std::cos(glm::radians(18.0f)), 0.002f);
}

TEST(MeshLod, DistanceDoublingMovesOneLevel) {
    // Errors doubling along the chain: from a perspective view, doubling the distance halves the
    // projected error and moves the choice one level coarser.
    scene::LodChain chain;
    for (float error : {0.0f, 0.01f, 0.02f, 0.04f, 0.08f}) chain.levels.push_back({0, 3, error});
    scene::OrbitCamera camera;
    const scene::ViewSetup view = camera.view(1.0f);
    const auto levelAt = [&](float distance) {
        const glm::vec3 centre = view.eye + glm::normalize(camera.target - view.eye) * (distance + 0.5f);
        return selectLod(chain, 1.0f, pixelsPerUnit(view, 1000, scene::Aabb{centre - 0.5f / std::sqrt(3.0f), centre + 0.5f / std::sqrt(3.0f)}), 1.0f);
    };
    // 1 px at distance d: error = d · 2 tan(22.5°) / 1000 ≈ d · 8.3e-4; level 1 (0.01) from d ≈ 12.
    const uint32_t first = levelAt(13.0f);
    EXPECT_EQ(first, 1u);
    EXPECT_EQ(levelAt(26.0f), first + 1);
    EXPECT_EQ(levelAt(52.0f), first + 2);
    EXPECT_EQ(levelAt(104.0f), first + 3);
    EXPECT_EQ(levelAt(6.0f), 0u);
    // No error allowed, or the eye inside the bounds: full detail.
    EXPECT_EQ(selectLod(chain, 1.0f, 1.0f, 0.0f), 0u);
    EXPECT_EQ(selectLod(chain, 1.0f, pixelsPerUnit(view, 1000, scene::Aabb{view.eye - 1.0f, view.eye + 1.0f}), 1.0f), 0u);
    // A world scale of 2 doubles every error: one level finer.
    const glm::vec3 centre = view.eye + glm::normalize(camera.target - view.eye) * 26.5f;
    EXPECT_EQ(selectLod(chain, 2.0f, pixelsPerUnit(view, 1000, scene::Aabb{centre - 0.2f, centre + 0.2f}), 1.0f), first);
}

TEST(MeshLod, MaxScaleIsExactForTrsAndNeverLessUnderShear) {
    const glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    EXPECT_NEAR(maxScale(rotation * glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))), 2.0f, 1e-5f);
    EXPECT_NEAR(maxScale(glm::translate(glm::mat4(1.0f), glm::vec3(5)) * rotation * glm::scale(glm::mat4(1.0f), glm::vec3(1, 3, 2))), 3.0f, 1e-5f);
    glm::mat4 shear(1.0f);
    shear[1][0] = 1.0f;  // x += y: largest singular value (1 + √5) / 2
    EXPECT_GE(maxScale(shear), 1.618f);
}

TEST(MeshLod, OpenBordersStayLocked) {
    // A bumpy 33 × 33 grid with an open border: every border edge of the full detail is still a
    // border edge of every level (no crack against a neighbouring primitive).
    scene::Scene s;
    constexpr uint32_t n = 33;
    for (uint32_t y = 0; y < n; ++y)
        for (uint32_t x = 0; x < n; ++x) {
            scene::Vertex v;
            v.position = glm::vec3(float(x), float(y), 0.3f * std::sin(0.4f * float(x)) * std::cos(0.3f * float(y)));
            s.vertices.push_back(v);
        }
    for (uint32_t y = 0; y + 1 < n; ++y)
        for (uint32_t x = 0; x + 1 < n; ++x) {
            const uint32_t a = y * n + x;
            s.indices.insert(s.indices.end(), {a, a + 1, a + n + 1, a, a + n + 1, a + n});
        }
    const auto borderEdges = [](const std::vector<uint32_t>& indices) {
        std::map<std::pair<uint32_t, uint32_t>, int> count;
        for (size_t t = 0; t < indices.size(); t += 3)
            for (int e = 0; e < 3; ++e) {
                const uint32_t a = indices[t + e], b = indices[t + (e + 1) % 3];
                ++count[{std::min(a, b), std::max(a, b)}];
            }
        std::set<uint32_t> vertices;
        for (const auto& [edge, c] : count)
            if (c == 1) vertices.insert(edge.first), vertices.insert(edge.second);
        return vertices;
    };
    const std::set<uint32_t> border = borderEdges(s.indices);
    ASSERT_EQ(border.size(), 4u * (n - 1));
    const std::vector<SimplifiedLevel> levels = simplifyChain(s.vertices, s.indices);
    ASSERT_FALSE(levels.empty());
    for (const SimplifiedLevel& level : levels) {
        const std::set<uint32_t> kept(level.indices.begin(), level.indices.end());
        for (uint32_t v : border) EXPECT_TRUE(kept.count(v)) << "border vertex " << v << " collapsed";
    }
}

TEST(MeshLod, PreparationKeepsBlendOrderAndDeformedMeshesAndTheTrianglesDrawn) {
    scene::Scene s;
    for (int m = 0; m < 3; ++m) assets::appendUvSphere(s, 1.0f, 32, 16);
    const uint32_t perSphere = uint32_t(s.indices.size() / 3);
    s.materials.resize(2);
    s.materials[1].alphaMode = scene::AlphaMode::Blend;
    s.deformations.resize(1);
    for (uint32_t m = 0; m < 3; ++m) s.draws.push_back({.firstIndex = m * perSphere, .indexCount = perSphere, .material = m == 1 ? 1u : 0u, .deformation = m == 2 ? 0 : -1});
    const scene::Scene before = s;
    geometry::prepareGeometry(s);
    // The triangles each draw shows, as sets of corner positions, are the same.
    const auto triangles = [](const scene::Scene& scene, const scene::Draw& d) {
        std::multiset<std::array<float, 9>> out;
        for (uint32_t i = 0; i < d.indexCount; i += 3) {
            std::array<float, 9> t;
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k) t[size_t(c * 3 + k)] = scene.vertices[scene.indices[d.firstIndex + i + uint32_t(c)]].position[k];
            out.insert(t);
        }
        return out;
    };
    for (size_t d = 0; d < 3; ++d) EXPECT_EQ(triangles(s, s.draws[d]), triangles(before, before.draws[d])) << "draw " << d;
    // The blended sphere keeps its triangle order (its vertices may move: compare corner positions).
    for (uint32_t i = perSphere; i < 2 * perSphere; ++i)
        ASSERT_EQ(s.vertices[s.indices[i]].position, before.vertices[before.indices[i]].position) << "index " << i;
    // The deformed one gets no chain and keeps its vertices where they were (its triangles may be reordered).
    const uint32_t deformedFirst = before.indices[2 * perSphere];
    EXPECT_TRUE(std::equal(s.vertices.begin() + deformedFirst, s.vertices.end(), before.vertices.begin() + deformedFirst,
                           [](const scene::Vertex& a, const scene::Vertex& b) { return a.position == b.position && a.uv0 == b.uv0; }));
    EXPECT_GE(s.draws[0].lod, 0);
    EXPECT_GE(s.draws[1].lod, 0);
    EXPECT_EQ(s.draws[2].lod, -1);
    EXPECT_EQ(s.report.geometry.meshes, 3u);
    EXPECT_EQ(s.report.geometry.simplifiedMeshes, 2u);
    EXPECT_LE(s.report.geometry.lodIndexBytes, s.report.geometry.indexBytes / 2);
}

}  // namespace
}  // namespace candela::geometry
