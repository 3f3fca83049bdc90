// The tone mapping operators and sRGB transfer functions of shaders/shared/tonemap.h (the same
// code the tonemap pass runs), on the CPU.
#include "shared/tonemap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace candela::shading {
namespace {

constexpr uint kOps[] = {CANDELA_TONEMAP_PBR_NEUTRAL, CANDELA_TONEMAP_ACES, CANDELA_TONEMAP_AGX,
                         CANDELA_TONEMAP_REINHARD, CANDELA_TONEMAP_LINEAR};

TEST(Tonemap, EveryOperatorMapsIntoUnitRangeMonotonicallyAndFinitely) {
    for (uint op : kOps) {
        float previous = -1.0f;
        for (float x = 0.0f; x < 1e6f; x = x * 1.25f + 1e-4f) {
            const vec3 out = applyTonemap(vec3(x), op);
            for (int c = 0; c < 3; ++c) {
                ASSERT_TRUE(std::isfinite(out[c])) << "op " << op << " x " << x;
                ASSERT_GE(out[c], 0.0f) << "op " << op << " x " << x;
                ASSERT_LE(out[c], 1.0f) << "op " << op << " x " << x;
            }
            // Grey stays grey-ish and never gets darker as the input grows.
            EXPECT_GE(out.g, previous - 1e-5f) << "op " << op << " x " << x;
            previous = out.g;
        }
        EXPECT_TRUE(std::isfinite(applyTonemap(vec3(-5.0f), op).r));
    }
}

TEST(Tonemap, PbrNeutralKeepsLowValuesAndCompressesHighlights) {
    // Below the compression start only the 0.04 toe offset applies.
    const vec3 mid = tonemapPbrNeutral(vec3(0.5f));
    EXPECT_NEAR(mid.r, 0.46f, 1e-6f);
    EXPECT_NEAR(tonemapPbrNeutral(vec3(0.18f, 0.3f, 0.5f)).b, 0.5f - 0.04f, 1e-6f);
    EXPECT_LT(tonemapPbrNeutral(vec3(100.0f)).r, 1.0f);
    EXPECT_GT(tonemapPbrNeutral(vec3(100.0f)).r, 0.99f);
    EXPECT_NEAR(tonemapPbrNeutral(vec3(0.0f)).r, 0.0f, 1e-6f);
}

TEST(Tonemap, AcesHillFitKnownValues) {
    // Grey passes the input matrix unchanged (rows sum to 1): RRT+ODT(0.18) =
    // (0.18·(0.18+0.0245786) − 0.000090537) / (0.18·(0.983729·0.18+0.4329510) + 0.238081) = 0.105591.
    // No exposure bias is applied (the Khronos sample viewer divides by 0.6 first).
    EXPECT_NEAR(tonemapAces(vec3(0.0f)).r, 0.0f, 2e-4f);
    EXPECT_NEAR(tonemapAces(vec3(0.18f)).g, 0.105591f, 2e-4f);
}

TEST(Tonemap, ReinhardAndLinear) {
    EXPECT_FLOAT_EQ(applyTonemap(vec3(1.0f), CANDELA_TONEMAP_REINHARD).r, 0.5f);
    EXPECT_FLOAT_EQ(applyTonemap(vec3(3.0f), CANDELA_TONEMAP_REINHARD).r, 0.75f);
    EXPECT_FLOAT_EQ(applyTonemap(vec3(0.25f), CANDELA_TONEMAP_LINEAR).r, 0.25f);
    EXPECT_FLOAT_EQ(applyTonemap(vec3(7.0f), CANDELA_TONEMAP_LINEAR).r, 1.0f);
}

TEST(Srgb, TransferFunctionKnownValuesAndRoundTrip) {
    EXPECT_NEAR(srgbEncode(vec3(0.5f)).r, 0.735357f, 1e-5f);
    EXPECT_NEAR(srgbEncode(vec3(0.001f)).r, 0.01292f, 1e-6f);
    EXPECT_NEAR(srgbDecode(vec3(0x26 / 255.0f)).r, 0.019382f, 1e-5f);
    for (float x = 0.0f; x <= 1.0f; x += 1.0f / 64.0f) EXPECT_NEAR(srgbDecode(srgbEncode(vec3(x))).r, x, 1e-5f);
}

// The encoding's polynomial against the transfer function in double precision, on a million
// points of [0, 1] (both sides of the linear segment's end): within 2e-6, so an 8-bit code differs
// from the exact one's only where the exact value lies within 5e-4 of a level's rounding boundary.
TEST(SrgbEncode, WithinAFewMillionthsOfTheTransferFunction) {
    const auto exact = [](double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055; };
    double largest = 0.0;
    int codesDiffering = 0;
    const int n = 1 << 20;
    for (int i = 0; i <= n; ++i) {
        const float x = float(i) / float(n);
        const double got = srgbEncode(vec3(x)).g;
        largest = std::max(largest, std::abs(got - exact(x)));
        codesDiffering += std::lround(got * 255.0) != std::lround(exact(x) * 255.0);
    }
    EXPECT_LE(largest, 2e-6);
    EXPECT_LE(codesDiffering, n / 1000);
    EXPECT_EQ(srgbEncode(vec3(0.0f)).r, 0.0f);
    EXPECT_NEAR(srgbEncode(vec3(1.0f)).r, 1.0f, 2e-6f);
}

}  // namespace
}  // namespace candela::shading
