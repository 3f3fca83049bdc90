// The bright-texel split of an environment (engine/ibl_maps/bright_texels.h), on small maps.

#include "ibl_maps/bright_texels.h"

#include "reports/ibl_reference.h"
#include "shared/ibl.h"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace candela::ibl_maps {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 32;

// A kWidth × kHeight map of constant radiance `base` in half floats, times `scale`.
struct HalfMap {
    std::vector<uint16_t> texels;
    float scale = 1.0f;
    HalfMap(glm::vec3 base, float s) : texels(size_t(kWidth) * kHeight * 4), scale(s) {
        for (uint32_t i = 0; i < kWidth * kHeight; ++i) set(i % kWidth, i / kWidth, base);
    }
    void set(uint32_t x, uint32_t y, glm::vec3 radiance) {
        uint16_t* t = &texels[(size_t(y) * kWidth + x) * 4];
        for (int c = 0; c < 3; ++c) t[c] = glm::packHalf1x16(radiance[c] * scale);
        t[3] = glm::packHalf1x16(1.0f);
    }
    glm::vec3 get(uint32_t x, uint32_t y) const {
        const uint16_t* t = &texels[(size_t(y) * kWidth + x) * 4];
        return glm::vec3(glm::unpackHalf1x16(t[0]), glm::unpackHalf1x16(t[1]), glm::unpackHalf1x16(t[2])) / scale;
    }
};

struct Entry {
    glm::vec3 direction, flux;
};
Entry entry(const BrightTexels& b, uint32_t i) { return {glm::vec3(b.buffer[1 + 2 * i]), glm::vec3(b.buffer[2 + 2 * i])}; }

TEST(BrightTexels, AUniformMapHasNone) {
    const HalfMap map(glm::vec3(0.3f, 0.5f, 0.7f), 1.0f);
    const BrightTexels bright = findBrightTexels(map.texels, kWidth, kHeight, map.scale, 256);
    EXPECT_EQ(bright.count(), 0u);
    EXPECT_EQ(bright.buffer.size(), 1u);
    EXPECT_EQ(bright.buffer[0].x, 0.0f);
    EXPECT_TRUE(std::isinf(bright.threshold));
}

// One sun texel of 1e4 (scaled by 1/4 as a half-float upload of a brighter map would be): it is the
// only entry, at its texel's centre direction, and its flux is the excess over the threshold (20×
// the mean luminance) times the texel's solid angle, in radiance units. Clamped + excess = the texel.
TEST(BrightTexels, ASunTexelCarriesItsExcessFlux) {
    HalfMap map(glm::vec3(1.0f), 0.25f);
    const glm::vec3 sun(1.0e4f, 0.9e4f, 0.8e4f);
    map.set(10, 7, sun);
    const BrightTexels bright = findBrightTexels(map.texels, kWidth, kHeight, map.scale, 256);
    ASSERT_EQ(bright.count(), 1u);
    double power = 0, solidAngle = 0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const double omega = reports::reference::texelSolidAngle(y, kWidth, kHeight);
            power += shading::iblLuminance(map.get(x, y)) * omega;
            solidAngle += omega;
        }
    EXPECT_NEAR(bright.threshold, kBrightTexelFactor * power / solidAngle * map.scale, 1e-3 * bright.threshold);
    const Entry e = entry(bright, 0);
    const glm::dvec3 expectedDirection = reports::reference::texelDirection(10, 7, kWidth, kHeight);
    EXPECT_NEAR(glm::distance(glm::dvec3(e.direction), expectedDirection), 0.0, 1e-6);
    const glm::vec3 stored = map.get(10, 7) * map.scale;
    const glm::vec3 clamped = shading::iblClampLuminance(stored, bright.threshold);
    EXPECT_NEAR(shading::iblLuminance(clamped), bright.threshold, 1e-3 * bright.threshold);
    const double omega = reports::reference::texelSolidAngle(7, kWidth, kHeight);
    for (int c = 0; c < 3; ++c) {
        const double expected = (stored[c] - clamped[c]) / map.scale * omega;
        EXPECT_NEAR(e.flux[c], expected, 1e-5 * expected) << c;
        // Excess + clamp = the texel, in radiance units.
        EXPECT_NEAR(e.flux[c] / omega + clamped[c] / map.scale, map.get(10, 7)[c], 1e-3 * sun[c]) << c;
    }
}

// With more candidates than maxCount, the brightest are kept and the threshold rises to the
// luminance of the brightest texel left out, so the rest stays in the sampled map unclamped.
TEST(BrightTexels, TheCountIsCappedAtTheBrightest) {
    HalfMap map(glm::vec3(1.0f), 1.0f);
    for (uint32_t i = 0; i < 6; ++i) map.set(4 + i, 16, glm::vec3(1000.0f * float(i + 1)));
    const BrightTexels all = findBrightTexels(map.texels, kWidth, kHeight, map.scale, 256);
    EXPECT_EQ(all.count(), 6u);
    const BrightTexels three = findBrightTexels(map.texels, kWidth, kHeight, map.scale, 3);
    ASSERT_EQ(three.count(), 3u);
    EXPECT_FLOAT_EQ(three.threshold, shading::iblLuminance(map.get(6, 16)));  // the 4th brightest (3000)
    for (uint32_t i = 0; i < 3; ++i) {
        const glm::dvec3 d(entry(three, i).direction);
        bool found = false;
        for (uint32_t x = 7; x < 10; ++x)
            found |= glm::distance(d, reports::reference::texelDirection(x, 16, kWidth, kHeight)) < 1e-6;
        EXPECT_TRUE(found) << "entry " << i << " is not one of the three brightest texels";
    }
    const BrightTexels none = findBrightTexels(map.texels, kWidth, kHeight, map.scale, 0);
    EXPECT_EQ(none.count(), 0u);
    EXPECT_TRUE(std::isinf(none.threshold));
}

// Energy: Σ clamped L Ω + Σ flux = Σ L Ω over the map (the split loses nothing), to float rounding.
TEST(BrightTexels, TheSplitKeepsTheMapsEnergy) {
    HalfMap map(glm::vec3(0.5f, 0.6f, 0.7f), 1.0f);
    for (uint32_t i = 0; i < 40; ++i) map.set((i * 7) % kWidth, 3 + (i * 5) % 20, glm::vec3(50.0f + 300.0f * float(i)));
    const BrightTexels bright = findBrightTexels(map.texels, kWidth, kHeight, map.scale, 16);
    ASSERT_EQ(bright.count(), 16u);
    glm::dvec3 original(0.0), split(0.0);
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const double omega = reports::reference::texelSolidAngle(y, kWidth, kHeight);
            original += glm::dvec3(map.get(x, y)) * omega;
            split += glm::dvec3(shading::iblClampLuminance(map.get(x, y), bright.threshold)) * omega;
        }
    for (uint32_t i = 0; i < bright.count(); ++i) split += glm::dvec3(entry(bright, i).flux);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(split[c], original[c], 1e-5 * original[c]) << c;
}

}  // namespace
}  // namespace candela::ibl_maps
