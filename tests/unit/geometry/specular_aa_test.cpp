// Specular anti-aliasing: the roughness widening (shared/brdf.h) against the formulas it states, and
// the normal-map mip chain that keeps what its averaging loses (geometry/normal_map_mips.h).
#include "geometry/normal_map_mips.h"
#include "shared/brdf.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela::test {
namespace {

using shading::specularAntiAliasedRoughness;

// The same formulas in double precision: α² + min(2 · 0.25 · change, 0.18) + 2 (1 − r²) / (3r − r³).
double reference(double roughness, double change, double r) {
    double a2 = std::pow(roughness, 4.0) + std::min(0.5 * change, 0.18);
    // The thresholds as the float code compares them.
    if (r < double(1e-4f)) return 1.0;
    if (r < double(0.9999f)) a2 += 2.0 * (1.0 - r * r) / (3.0 * r - r * r * r);
    return std::pow(std::min(a2, 1.0), 0.25);
}

TEST(SpecularAa, NothingChangesWhereTheNormalIsConstantAndTheMapAgrees) {
    for (float roughness : {0.0f, 0.05f, 0.3f, 1.0f}) EXPECT_NEAR(specularAntiAliasedRoughness(roughness, 0.0f, 1.0f), roughness, 1e-6f);
}

TEST(SpecularAa, MatchesItsFormulasInDoublePrecision) {
    for (float roughness : {0.0f, 0.05f, 0.2f, 0.5f, 0.9f})
        for (float change : {0.0f, 1e-4f, 0.01f, 0.1f, 0.36f, 10.0f})
            for (float r : {1.0f, 0.9999f, 0.999f, 0.99f, 0.9f, 0.5f, 0.1f, 0.0f}) {
                const double expected = reference(roughness, change, r);
                EXPECT_NEAR(specularAntiAliasedRoughness(roughness, change, r), expected, 2e-6 + 1e-5 * expected)
                    << roughness << " " << change << " " << r;
            }
}

TEST(SpecularAa, TheGeometricKernelIsClampedAndTheMapTermGrowsAsTheMeanShortens) {
    // κ = 0.18 caps the geometric term: a mirror under any normal change stays at α² = 0.18.
    EXPECT_NEAR(std::pow(specularAntiAliasedRoughness(0.0f, 1e6f, 1.0f), 4.0f), 0.18f, 1e-6f);
    float previous = 0.0f;
    for (float r : {1.0f, 0.99f, 0.95f, 0.9f, 0.7f, 0.4f, 0.1f}) {
        const float widened = specularAntiAliasedRoughness(0.1f, 0.0f, r);
        EXPECT_GE(widened, previous);
        previous = widened;
    }
    EXPECT_EQ(specularAntiAliasedRoughness(0.1f, 0.0f, 0.0f), 1.0f);
}

scene::Image image(uint32_t width, uint32_t height, auto&& texel) {
    scene::Image out{.name = "normal", .width = width, .height = height};
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const glm::vec3 n = texel(x, y);
            for (float c : {n.x, n.y, n.z}) out.rgba8.push_back(uint8_t(std::lround((c * 0.5f + 0.5f) * 255.0f)));
            out.rgba8.push_back(7);  // whatever A the file has: the chain replaces it
        }
    return out;
}

TEST(NormalMapMips, AFlatMapStaysFlatAndFullLength) {
    const auto mips = geometry::normalMapMipChain(image(8, 4, [](uint32_t, uint32_t) { return glm::vec3(0, 0, 1); }));
    ASSERT_EQ(mips.size(), 4u);  // 8×4, 4×2, 2×1, 1×1
    EXPECT_EQ(mips[3].size(), 4u);
    for (const auto& mip : mips)
        for (size_t i = 0; i < mip.size(); i += 4) {
            EXPECT_EQ(mip[i + 2], 255);
            EXPECT_EQ(mip[i + 3], 255);
        }
}

TEST(NormalMapMips, DivergingNormalsShortenTheMeanAndMipZeroKeepsItsTexels) {
    // A checkerboard of normals tilted ±30° about Y: every mip beyond 0 averages them to (0, 0, 1)
    // with length cos 30° = 0.866 (A = 221).
    const float s = std::sin(glm::radians(30.0f)), c = std::cos(glm::radians(30.0f));
    const scene::Image source = image(16, 16, [&](uint32_t x, uint32_t y) { return glm::vec3((x + y) % 2 ? s : -s, 0.0f, c); });
    const auto mips = geometry::normalMapMipChain(source);
    ASSERT_EQ(mips.size(), 5u);
    for (size_t i = 0; i < mips[0].size(); ++i) EXPECT_EQ(mips[0][i], i % 4 == 3 ? 255 : source.rgba8[i]);
    for (size_t level = 1; level < mips.size(); ++level)
        for (size_t i = 0; i < mips[level].size(); i += 4) {
            EXPECT_NEAR(mips[level][i], 128, 1);
            EXPECT_NEAR(mips[level][i + 2], 255, 1);
            EXPECT_NEAR(mips[level][i + 3], 221, 1) << "mip " << level;
        }
}

TEST(NormalMapMips, OddSizesFollowVulkansMipSizes) {
    const auto mips = geometry::normalMapMipChain(image(5, 3, [](uint32_t x, uint32_t) { return glm::normalize(glm::vec3(0.1f * float(x), 0, 1)); }));
    ASSERT_EQ(mips.size(), 3u);  // 5×3, 2×1, 1×1
    EXPECT_EQ(mips[1].size(), 2u * 1u * 4u);
    EXPECT_EQ(mips[2].size(), 4u);
}

}  // namespace
}  // namespace candela::test
