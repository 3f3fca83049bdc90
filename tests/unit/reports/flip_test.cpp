// io::flip: LDR- and HDR-ꟻLIP on images whose answer is known without the metric — identical
// images, the largest difference the papers define (green against blue), symmetry, the viewing
// distance, the exposure range and tone mapper of the HDR paper, HDR-ꟻLIP as the largest LDR-ꟻLIP
// over its exposures — and the statistics and colour map of the error maps. The values of the
// authors' implementation on real renders: flip_reference_test.cpp.

#include "reports/flip.h"
#include "reports/magma.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace candela::reports {
namespace {

RgbImage uniform(uint32_t w, uint32_t h, float r, float g, float b) {
    RgbImage image{w, h, {}};
    for (uint32_t i = 0; i < w * h; ++i) image.rgb.insert(image.rgb.end(), {r, g, b});
    return image;
}

// A deterministic pattern with edges, points and colour in [0, 1] (scaled by `scale`).
RgbImage pattern(uint32_t w, uint32_t h, uint32_t seed, float scale = 1.0f) {
    RgbImage image{w, h, {}};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            for (uint32_t c = 0; c < 3; ++c) {
                const uint32_t hash = (x * 73856093u) ^ (y * 19349663u) ^ ((c + seed) * 83492791u);
                const float stripes = ((x / 4 + y / 6 + c) % 3) / 2.0f;
                image.rgb.push_back(scale * (0.7f * stripes + 0.3f * float(hash % 1000) / 999.0f));
            }
    return image;
}

TEST(Flip, PixelsPerDegreeIsThePapersFormula) {
    // 0.7 m × (3840 px / 0.7 m) × π/180 = 3840 π / 180.
    EXPECT_NEAR(pixelsPerDegree({}), 3840.0 * std::numbers::pi / 180.0, 1e-4);
    EXPECT_NEAR(pixelsPerDegree({}), 67.0206, 1e-4);
    // Twice as far: twice the pixels per degree; a monitor twice as wide: half.
    EXPECT_NEAR(pixelsPerDegree({1.4f, 0.7f, 3840.0f}), 2.0f * pixelsPerDegree({}), 1e-3);
    EXPECT_NEAR(pixelsPerDegree({0.5f, 0.6f, 1920.0f}), 0.5 * 1920.0 / 0.6 * std::numbers::pi / 180.0, 1e-4);
}

TEST(Flip, IdenticalImagesHaveNoError) {
    const RgbImage image = pattern(40, 30, 1);
    for (float ppd : {10.0f, 67.0f, 120.0f}) {
        const std::vector<float> error = ldrFlip(image, image, ppd);
        ASSERT_EQ(error.size(), 40u * 30u);
        for (float e : error) ASSERT_EQ(e, 0.0f);
    }
    const RgbImage bright = pattern(40, 30, 2, 50.0f);
    const std::vector<float> error = hdrFlip(bright, bright, 67.0f, flipExposures(bright));
    for (float e : error) ASSERT_EQ(e, 0.0f);
    EXPECT_EQ(flipStatistics(error).mean, 0.0);
}

TEST(Flip, GreenAgainstBlueIsTheLargestError) {
    // The papers scale the colour difference so that pure green against pure blue is 1; flat
    // images have no edges or points, so the feature term leaves it at 1.
    const std::vector<float> error = ldrFlip(uniform(32, 24, 0, 1, 0), uniform(32, 24, 0, 0, 1), 67.0f);
    for (float e : error) ASSERT_NEAR(e, 1.0f, 1e-5f);
    // Any other pair of colours is less.
    const std::vector<float> blackWhite = ldrFlip(uniform(32, 24, 0, 0, 0), uniform(32, 24, 1, 1, 1), 67.0f);
    for (float e : blackWhite) ASSERT_TRUE(e > 0.5f && e < 1.0f) << e;
}

TEST(Flip, ErrorsAreInTheUnitIntervalAndSymmetric) {
    const RgbImage a = pattern(48, 36, 1), b = pattern(48, 36, 7);
    const std::vector<float> ab = ldrFlip(a, b, 67.0f), ba = ldrFlip(b, a, 67.0f);
    for (size_t i = 0; i < ab.size(); ++i) {
        ASSERT_GE(ab[i], 0.0f);
        ASSERT_LE(ab[i], 1.0f);
        ASSERT_EQ(ab[i], ba[i]) << i;  // HyAB and the feature difference are both symmetric
    }
}

TEST(Flip, SmallerDifferencesGiveSmallerErrors) {
    // The same change at 1/4 the amplitude is less visible.
    const RgbImage a = pattern(48, 36, 1);
    RgbImage strong = a, weak = a;
    for (size_t i = 0; i < a.rgb.size(); i += 7) {
        strong.rgb[i] = std::min(1.0f, a.rgb[i] + 0.4f);
        weak.rgb[i] = std::min(1.0f, a.rgb[i] + 0.1f);
    }
    EXPECT_LT(flipStatistics(ldrFlip(a, weak, 67.0f)).mean, flipStatistics(ldrFlip(a, strong, 67.0f)).mean);
}

TEST(Flip, FartherAwayFineDetailMattersLess) {
    // A one-pixel checkerboard against flat grey of the same mean: seen from farther away (more
    // pixels per degree), the eye's filters average the checkerboard out.
    RgbImage checker{64, 64, {}};
    for (uint32_t y = 0; y < 64; ++y)
        for (uint32_t x = 0; x < 64; ++x) {
            const float v = (x + y) % 2 ? 1.0f : 0.0f;
            checker.rgb.insert(checker.rgb.end(), {v, v, v});
        }
    const RgbImage grey = uniform(64, 64, 0.5f, 0.5f, 0.5f);
    const double near = flipStatistics(ldrFlip(checker, grey, 10.0f)).mean;
    const double far = flipStatistics(ldrFlip(checker, grey, 120.0f)).mean;
    EXPECT_LT(far, near);
    // So close that the feature filter is one tap: still finite.
    for (float e : ldrFlip(checker, grey, 0.5f)) ASSERT_TRUE(std::isfinite(e) && e >= 0.0f && e <= 1.0f) << e;
}

TEST(Flip, OutOfRangeValuesAreClampedForLdr) {
    RgbImage a = pattern(20, 20, 3), b = a;
    for (float& v : b.rgb) v = v * 3.0f - 1.0f;  // beyond [0, 1] on both sides, NaN below
    b.rgb[5] = NAN;
    RgbImage clamped = b;
    for (float& v : clamped.rgb) v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
    EXPECT_EQ(ldrFlip(a, b, 67.0f), ldrFlip(a, clamped, 67.0f));
}

TEST(Flip, BadArgumentsThrow) {
    EXPECT_THROW(ldrFlip(uniform(4, 4, 0, 0, 0), uniform(4, 5, 0, 0, 0), 67.0f), std::invalid_argument);
    EXPECT_THROW(ldrFlip(uniform(4, 4, 0, 0, 0), uniform(4, 4, 0, 0, 0), 0.0f), std::invalid_argument);
    RgbImage shortData = uniform(4, 4, 0, 0, 0);
    shortData.rgb.pop_back();
    EXPECT_THROW(ldrFlip(shortData, uniform(4, 4, 0, 0, 0), 67.0f), std::invalid_argument);
    EXPECT_THROW(hdrFlip(uniform(4, 4, 0, 0, 0), uniform(4, 4, 0, 0, 0), 67.0f, {0.0f, 1.0f, 1}), std::invalid_argument);
    EXPECT_TRUE(ldrFlip(RgbImage{}, RgbImage{}, 67.0f).empty());
    // A 1 × 1 image: every filter tap clamps to the one pixel.
    EXPECT_EQ(ldrFlip(uniform(1, 1, 0, 1, 0), uniform(1, 1, 0, 1, 0), 67.0f), std::vector<float>{0.0f});
}

TEST(FlipHdr, ToneMapperIsNarkowiczAcesAfterPointSixExposure) {
    for (float x : {0.0f, 0.1f, 1.0f, 4.0f, 100.0f}) {
        const float e = 0.6f * x;
        EXPECT_NEAR(flipToneMap(x), (e * (2.51f * e + 0.03f)) / (e * (2.43f * e + 0.59f) + 0.14f), 1e-5f) << x;
    }
    EXPECT_EQ(flipToneMap(0.0f), 0.0f);
}

TEST(FlipHdr, ExposureRangeFromTheReference) {
    // x₀.₈₅: the radiance the tone mapper takes to 0.85.
    float lo = 0.0f, hi = 100.0f;
    for (int i = 0; i < 60; ++i) ((flipToneMap(0.5f * (lo + hi)) < 0.85f) ? lo : hi) = 0.5f * (lo + hi);
    const float x85 = 0.5f * (lo + hi);
    // Grey luminances 1/16 … 64 (the median pixel 1, the largest 64), one pixel each, plus 3 black.
    RgbImage image{11, 1, {}};
    for (float v : {0.0f, 0.0f, 0.0f, 0.0625f, 0.25f, 1.0f, 1.0f, 2.0f, 8.0f, 32.0f, 64.0f}) image.rgb.insert(image.rgb.end(), {v, v, v});
    const FlipExposures e = flipExposures(image);
    EXPECT_NEAR(e.start, std::log2(x85 / 64.0f), 1e-4f);
    EXPECT_NEAR(e.stop, std::log2(x85 / 1.0f), 1e-4f);
    EXPECT_EQ(e.count, uint32_t(std::ceil(e.stop - e.start)));  // 6 stops: 6 exposures
    EXPECT_EQ(e.count, 6u);
    EXPECT_NEAR(e.exposure(0), e.start, 1e-6f);
    EXPECT_NEAR(e.exposure(e.count - 1), e.stop, 1e-5f);
    // Never fewer than two; a median of 0 falls back to the smallest positive luminance; a black
    // image has nothing to expose for.
    EXPECT_EQ(flipExposures(uniform(8, 8, 1, 1, 1)).count, 2u);
    RgbImage mostlyBlack = uniform(9, 1, 0, 0, 0);
    mostlyBlack.rgb[0] = mostlyBlack.rgb[1] = mostlyBlack.rgb[2] = 0.5f;
    mostlyBlack.rgb[3] = mostlyBlack.rgb[4] = mostlyBlack.rgb[5] = 8.0f;
    EXPECT_NEAR(flipExposures(mostlyBlack).stop, std::log2(x85 / 0.5f), 1e-4f);
    const FlipExposures black = flipExposures(uniform(8, 8, 0, 0, 0));
    EXPECT_EQ(black.start, 0.0f);
    EXPECT_EQ(black.stop, 0.0f);
    EXPECT_EQ(black.count, 2u);
    // A dynamic range of 2^100 is sampled by at most kMaxFlipExposures exposures.
    RgbImage wide = uniform(3, 1, 1e-20f, 1e-20f, 1e-20f);
    wide.rgb[0] = wide.rgb[1] = wide.rgb[2] = 1e10f;
    EXPECT_EQ(flipExposures(wide).count, kMaxFlipExposures);
}

TEST(FlipHdr, IsTheLargestLdrFlipOverTheExposures) {
    // The Eurographics 2021 definition: tone map both images at each exposure, clamp, LDR-ꟻLIP,
    // and keep each pixel's largest error.
    RgbImage reference = pattern(32, 24, 1), test = pattern(32, 24, 5);
    for (RgbImage* image : {&reference, &test})  // pixels scaled by 1 … 256: eight stops
        for (size_t v = 0; v < image->rgb.size(); ++v) image->rgb[v] *= std::exp2(float((v / 3) % 9));
    const FlipExposures exposures = flipExposures(reference);
    ASSERT_GE(exposures.count, 3u);
    std::vector<float> expected(32 * 24, 0.0f);
    for (uint32_t i = 0; i < exposures.count; ++i) {
        RgbImage r = reference, t = test;
        for (RgbImage* image : {&r, &t})
            for (float& v : image->rgb) v = std::clamp(flipToneMap(v * std::exp2(exposures.exposure(i))), 0.0f, 1.0f);
        const std::vector<float> ldr = ldrFlip(r, t, 67.0f);
        for (size_t p = 0; p < expected.size(); ++p) expected[p] = std::max(expected[p], ldr[p]);
    }
    EXPECT_EQ(hdrFlip(reference, test, 67.0f, exposures), expected);
}

TEST(FlipHdr, SeesDifferencesThatLdrClipsAway) {
    // Two images that differ only above 1 (highlights a display clips) are identical to LDR-ꟻLIP
    // but not to HDR-ꟻLIP, whose darker exposures bring the highlights into range.
    RgbImage reference = pattern(32, 32, 2), test = reference;
    for (size_t i = 0; i < reference.rgb.size(); i += 3) {
        reference.rgb[i] = reference.rgb[i + 1] = reference.rgb[i + 2] = (i / 3) % 5 == 0 ? 4.0f : 0.2f;
        test.rgb[i] = test.rgb[i + 1] = test.rgb[i + 2] = (i / 3) % 5 == 0 ? 16.0f : 0.2f;
    }
    EXPECT_EQ(flipStatistics(ldrFlip(reference, test, 67.0f)).max, 0.0);
    EXPECT_GT(flipStatistics(hdrFlip(reference, test, 67.0f, flipExposures(reference))).mean, 0.05);
}

TEST(FlipStatistics, MeanExtremesAndWeightedPercentiles) {
    // Sorted 0, 0.1, 0.2, 0.3, 0.4 (total 1): the running sums 0, 0.1, 0.3, 0.6, 1 pass 0.25 at
    // 0.2, 0.5 at 0.3 and 0.75 at 0.4.
    const std::vector<float> error = {0.3f, 0.0f, 0.4f, 0.1f, 0.2f};
    const FlipStatistics s = flipStatistics(error);
    EXPECT_NEAR(s.mean, 0.2, 1e-7);
    EXPECT_EQ(s.min, 0.0);
    EXPECT_NEAR(s.max, 0.4, 1e-7);
    EXPECT_NEAR(s.weightedQuartile1, 0.2, 1e-7);
    EXPECT_NEAR(s.weightedMedian, 0.3, 1e-7);
    EXPECT_NEAR(s.weightedQuartile3, 0.4, 1e-7);
    // Histogram of 20 intervals: 0 → [0, 0.05), 0.1 → [0.1, 0.15), …; 1 lands in the last.
    EXPECT_EQ(s.histogram[0], 1u);
    EXPECT_EQ(s.histogram[2], 1u);
    EXPECT_EQ(s.histogram[8], 1u);
    EXPECT_EQ(flipStatistics(std::vector<float>{1.0f}).histogram[19], 1u);
    const FlipStatistics empty = flipStatistics({});
    EXPECT_EQ(empty.mean, 0.0);
    EXPECT_EQ(empty.weightedMedian, 0.0);
    const FlipStatistics zeros = flipStatistics(std::vector<float>(100, 0.0f));
    EXPECT_EQ(zeros.weightedMedian, 0.0);
    EXPECT_EQ(zeros.histogram[0], 100u);
}

TEST(FlipStatistics, WeightedPercentilesAgreeWithASortedRunningSum) {
    // The bucketed search must find exactly what summing the sorted values finds.
    const RgbImage a = pattern(64, 48, 1), b = pattern(64, 48, 9);
    std::vector<float> error = ldrFlip(a, b, 67.0f);
    const FlipStatistics s = flipStatistics(error);
    std::sort(error.begin(), error.end());
    double total = 0.0;
    for (float e : error) total += e;
    for (auto [fraction, value] : {std::pair{0.25, s.weightedQuartile1}, std::pair{0.5, s.weightedMedian}, std::pair{0.75, s.weightedQuartile3}}) {
        double running = 0.0;
        float expected = 0.0f;
        for (float e : error)
            if ((running += e) > fraction * total) {
                expected = e;
                break;
            }
        EXPECT_EQ(value, double(expected)) << fraction;
    }
}

TEST(Magma, EndpointsAndRounding) {
    // matplotlib's magma: entry 0 (0.001462, 0.000466, 0.013866) and 255 (0.987053, 0.991438,
    // 0.749504), times 255, rounded.
    EXPECT_EQ(magma(0.0f), (std::array<uint8_t, 3>{0, 0, 4}));
    EXPECT_EQ(magma(1.0f), (std::array<uint8_t, 3>{252, 253, 191}));
    // Entry 128, (0.716387, 0.214982, 0.475290), is where 0.5 lands (127.5 rounds up).
    EXPECT_EQ(magma(0.5f), (std::array<uint8_t, 3>{183, 55, 121}));
    EXPECT_EQ(magma(-1.0f), magma(0.0f));
    EXPECT_EQ(magma(2.0f), magma(1.0f));
    EXPECT_EQ(magma(NAN), magma(0.0f));
    const std::vector<uint8_t> rgba = magmaImage(std::vector<float>{0.0f, 1.0f});
    EXPECT_EQ(rgba, (std::vector<uint8_t>{0, 0, 4, 255, 252, 253, 191, 255}));
}

TEST(Magma, BrightensMonotonically) {
    // Perceptually ordered: luma never decreases along the map.
    float previous = -1.0f;
    for (int i = 0; i < 256; ++i) {
        const std::array<uint8_t, 3> c = magma(float(i) / 255.0f);
        const float luma = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
        EXPECT_GE(luma, previous - 0.5f) << i;
        previous = luma;
    }
}

TEST(Flip, SrgbDecoding) {
    EXPECT_EQ(srgbToLinear(0), 0.0f);
    EXPECT_FLOAT_EQ(srgbToLinear(255), 1.0f);
    EXPECT_NEAR(srgbToLinear(10), 10.0f / 255.0f / 12.92f, 1e-9f);  // the linear segment
    EXPECT_NEAR(srgbToLinear(128), std::pow((128.0f / 255.0f + 0.055f) / 1.055f, 2.4f), 1e-7f);
}

}  // namespace
}  // namespace candela::reports
