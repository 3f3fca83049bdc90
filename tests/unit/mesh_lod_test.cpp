// Levels of detail (scene/mesh_lod.h) and the geometry preparation (scene/mesh_optimize.h): the
// simplified levels against the surface they stand for, locked borders and seams, the choice of a
// level from its projected error, and what the preparation must leave alone.
#include "scene/builtin_scenes.h"
#include "scene/mesh_lod.h"
#include "scene/mesh_optimize.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace candela::scene {
namespace {

// A unit UV sphere (64 × 32, as the built-in grid's) alone in a scene, indices relative to its vertices.
Scene sphere() {
    Scene scene;
    appendUvSphere(scene, 1.0f, 64, 32);
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
float oneSidedDistance(const std::vector<Vertex>& v, const std::vector<uint32_t>& from, const std::vector<uint32_t>& to) {
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
    const Scene s = sphere();
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
    const Scene s = sphere();
    for (const SimplifiedLevel& level : simplifyChain(s.vertices, s.indices)) {
        const float distance = std::max(oneSidedDistance(s.vertices, s.indices, level.indices),
                                        oneSidedDistance(s.vertices, level.indices, s.indices));
        EXPECT_LE(distance, level.error * 1.00001f) << level.indices.size() / 3 << " triangles";
        // ...and the error is no gross overestimate either (it picks the level).
        EXPECT_GE(distance, 0.5f * level.error) << level.indices.size() / 3 << " triangles";
    }
}

TEST(MeshLod, SurfaceDeviationMatchesBruteForce) {
    // The grid search against the brute-force distance, both ways, on the sphere and a coarser sphere.
    Scene s;
    const auto [fine, fineCount] = appendUvSphere(s, 1.0f, 48, 24);
    const auto [coarse, coarseCount] = appendUvSphere(s, 1.0f, 10, 5);
    const std::vector<uint32_t> a(s.indices.begin() + fine, s.indices.begin() + fine + fineCount);
    const std::vector<uint32_t> b(s.indices.begin() + coarse, s.indices.begin() + coarse + coarseCount);
    const float brute = std::max(oneSidedDistance(s.vertices, a, b), oneSidedDistance(s.vertices, b, a));
    const float grid = surfaceDeviation(s.vertices, a, b);
    EXPECT_GE(grid, brute * 0.9999f);  // it samples edge midpoints and centres too: never less
    EXPECT_LE(grid, brute * 1.5f);
    // Analytically: a 10 × 5 sphere's quads at the equator dip below the unit sphere by 1 − cos²18°
    // at their centres (half of 36° each way).
    EXPECT_NEAR(grid, 1.0f - std::cos(glm::radians(18.0f)) * std::cos(glm::radians(18.0f)), 0.002f);
}

}  // namespace
}  // namespace candela::scene
