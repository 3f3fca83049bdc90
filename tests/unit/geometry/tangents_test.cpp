// The MikkTSpace-compatible tangent generator on hand-made meshes with known answers.
#include "geometry/tangents.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace candela::geometry {
namespace {

void expectTangent(const glm::vec4& actual, const glm::vec4& expected, float eps = 1e-6f) {
    EXPECT_NEAR(actual.x, expected.x, eps);
    EXPECT_NEAR(actual.y, expected.y, eps);
    EXPECT_NEAR(actual.z, expected.z, eps);
    EXPECT_EQ(actual.w, expected.w);
}

// A unit quad in the XY plane facing +Z, corners (0,0) (1,0) (1,1) (0,1), two CCW triangles.
struct Quad {
    std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<glm::vec3> normals = std::vector<glm::vec3>(4, glm::vec3(0, 0, 1));
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
    std::vector<glm::vec4> tangents() const { return generateTangents(positions, normals, uvs, indices); }
};

TEST(Tangents, UprightImageGivesPlusXAndPositiveHandedness) {
    // glTF UVs: v runs down the image, so the image's top (v = 0) is at y = 1.
    Quad q;
    q.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const auto t = q.tangents();
    ASSERT_EQ(t.size(), 6u);
    for (const glm::vec4& tangent : t) expectTangent(tangent, {1, 0, 0, 1});
    // The glTF bitangent cross(N, T)·w points up the image (toward decreasing v): +Y here.
    const glm::vec3 bitangent = glm::cross(glm::vec3(0, 0, 1), glm::vec3(t[0])) * t[0].w;
    EXPECT_NEAR(bitangent.y, 1.0f, 1e-6f);
}

TEST(Tangents, HorizontallyMirroredImageFlipsTangentAndHandedness) {
    Quad q;
    q.uvs = {{1, 1}, {0, 1}, {0, 0}, {1, 0}};
    for (const glm::vec4& tangent : q.tangents()) expectTangent(tangent, {-1, 0, 0, -1});
}

TEST(Tangents, VerticallyMirroredImageFlipsHandednessOnly) {
    Quad q;
    q.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const glm::vec4& tangent : q.tangents()) expectTangent(tangent, {1, 0, 0, -1});
}

TEST(Tangents, RotatedMappingFollowsTheUAxis) {
    // u runs along +Y: the tangent is +Y.
    Quad q;
    q.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    for (const glm::vec4& tangent : q.tangents()) expectTangent(tangent, {0, 1, 0, 1});
}

TEST(Tangents, MirrorSeamKeepsBothSidesApart) {
    // Two quads side by side sharing the seam x = 1 (vertices 1 and 2, same position, normal and
    // uv on both sides); the right quad's image is mirrored. The seam corners must take their own
    // side's tangent, not an average.
    std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
    std::vector<glm::vec3> normals(6, glm::vec3(0, 0, 1));
    std::vector<glm::vec2> uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}, {0, 1}, {0, 0}};
    std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2};
    const auto t = generateTangents(positions, normals, uvs, indices);
    ASSERT_EQ(t.size(), 12u);
    for (int c = 0; c < 6; ++c) expectTangent(t[size_t(c)], {1, 0, 0, 1});
    for (int c = 6; c < 12; ++c) expectTangent(t[size_t(c)], {-1, 0, 0, -1});
}

TEST(Tangents, SmoothSurfaceAveragesAndStaysOrthogonalToTheNormal) {
    // A fold along the X axis with a shared, averaged normal on the crease; the tangent along the
    // fold is +X on both sides, and every tangent is unit and orthogonal to its vertex normal.
    const glm::vec3 crease = glm::normalize(glm::vec3(0, -1, 1));
    std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, -1}, {1, 0, -1}};
    std::vector<glm::vec3> normals = {crease, crease, {0, 0, 1}, {0, 0, 1}, {0, -1, 0}, {0, -1, 0}};
    std::vector<glm::vec2> uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}, {0, 2}, {1, 2}};
    std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3, 4, 5, 1, 4, 1, 0};
    const auto t = generateTangents(positions, normals, uvs, indices);
    for (size_t c = 0; c < indices.size(); ++c) {
        const glm::vec3 n = normals[indices[c]];
        EXPECT_NEAR(glm::length(glm::vec3(t[c])), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(glm::vec3(t[c]), n), 0.0f, 1e-6f);
        expectTangent(t[c], {1, 0, 0, 1});
    }
}

TEST(Tangents, AngleWeightingAtSharedVertices) {
    // Triangles A (0,1,2) and B (0,2,3) share the edge 0–2. A maps u along +X; B's uvs make u run
    // along (1,1)/√2. Shared vertices get the corner-angle-weighted average of both.
    std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 1, 0}};
    std::vector<glm::vec3> normals(4, glm::vec3(0, 0, 1));
    std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {0, -1}, {-1, -2}};
    std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
    const auto t = generateTangents(positions, normals, uvs, indices);
    const float quarter = float(M_PI / 4), half = float(M_PI / 2);
    const glm::vec3 tA(1, 0, 0), tB = glm::normalize(glm::vec3(1, 1, 0));
    const glm::vec4 at0(glm::normalize(half * tA + quarter * tB), 1.0f);  // A: 90°, B: 45° at vertex 0
    const glm::vec4 at2(glm::normalize(quarter * tA + half * tB), 1.0f);  // A: 45°, B: 90° at vertex 2
    ASSERT_EQ(t.size(), 6u);
    expectTangent(t[0], at0);
    expectTangent(t[3], at0);
    expectTangent(t[1], glm::vec4(tA, 1.0f));
    expectTangent(t[2], at2);
    expectTangent(t[4], at2);
    expectTangent(t[5], glm::vec4(tB, 1.0f));
}

TEST(Tangents, DegenerateTrianglesCopyANeighbourOrFallBack) {
    Quad q;
    q.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    q.positions.push_back({5, 5, 5});
    q.normals.push_back({0, 1, 0});
    q.uvs.push_back({0, 0});
    // Triangle 2 repeats a position (degenerate): its corners at vertex 0 and 2 copy the good
    // triangles' tangent. Triangle 3 is degenerate and shares nothing: unit fallback ⟂ normal.
    q.indices.insert(q.indices.end(), {0, 2, 2, 4, 4, 4});
    const auto t = q.tangents();
    ASSERT_EQ(t.size(), 12u);
    expectTangent(t[6], {1, 0, 0, 1});
    expectTangent(t[7], {1, 0, 0, 1});
    for (int c = 9; c < 12; ++c) {
        EXPECT_NEAR(glm::length(glm::vec3(t[size_t(c)])), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(glm::vec3(t[size_t(c)]), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(t[size_t(c)].w, 1.0f);
    }
}

TEST(Tangents, NoTextureExtentFallsBackToAUnitOrthogonalTangent) {
    Quad q;
    q.uvs = std::vector<glm::vec2>(4, glm::vec2(0.5f));
    q.normals = std::vector<glm::vec3>(4, glm::normalize(glm::vec3(1, 1, 1)));
    for (const glm::vec4& tangent : q.tangents()) {
        EXPECT_NEAR(glm::length(glm::vec3(tangent)), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(glm::vec3(tangent), q.normals[0]), 0.0f, 1e-6f);
        EXPECT_EQ(tangent.w, 1.0f);
    }
}

}  // namespace
}  // namespace candela::geometry
