// io::image_error: the box downsample of a supersampled reference, the display encoding (the
// tonemap pass's: PBR Neutral, sRGB, 8 bits) and the display-value differences of the reports.

#include "reports/image_error.h"
#include "shared/tonemap.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela::reports {
namespace {

TEST(ImageError, BoxDownsampleAveragesEachBlockInLinearRadiance) {
    FloatImage image{4, 2, {}};
    for (uint32_t i = 0; i < 8; ++i) image.rgba.insert(image.rgba.end(), {float(i), 0.0f, 1.0f, 1.0f});
    const FloatImage half = boxDownsample(image, 2);
    ASSERT_EQ(half.width, 2u);
    ASSERT_EQ(half.height, 1u);
    EXPECT_FLOAT_EQ(half.rgba[0], (0.0f + 1.0f + 4.0f + 5.0f) / 4.0f);
    EXPECT_FLOAT_EQ(half.rgba[4], (2.0f + 3.0f + 6.0f + 7.0f) / 4.0f);
    EXPECT_FLOAT_EQ(half.rgba[2], 1.0f);
    EXPECT_THROW(boxDownsample(image, 3), std::invalid_argument);
}

TEST(ImageError, DisplayEncodingIsTheTonemapPasses) {
    const FloatImage image{2, 1, {0.0f, 0.0f, 0.0f, 1.0f, 0.5f, 2.0f, 40.0f, 1.0f}};
    const std::vector<uint8_t> display = displayEncode(image);
    ASSERT_EQ(display.size(), 6u);
    EXPECT_EQ(display[0], 0);
    const glm::vec3 expected = shading::srgbEncode(shading::tonemapPbrNeutral(glm::vec3(0.5f, 2.0f, 40.0f)));
    for (int c = 0; c < 3; ++c) EXPECT_EQ(display[3 + c], uint8_t(std::lround(expected[c] * 255.0f)));
}

TEST(ImageError, MeanOverValuesAndP99OverPixels) {
    // 100 pixels: 98 identical, one off by 10 in one channel, one off by 30 in all three.
    std::vector<uint8_t> a(300, 100), b = a;
    b[0] = 110;
    b[3] = b[4] = b[5] = 130;
    const DisplayError e = displayError(a, b);
    EXPECT_DOUBLE_EQ(e.mean, (10.0 + 90.0) / 300.0);
    EXPECT_EQ(e.p99, 30.0);  // the 99th of 100 pixel maxima, in order: 98 zeros, 10, 30
    EXPECT_EQ(displayError(a, a).p99, 0.0);
}

TEST(ImageError, FrameToFrameDifferenceIsTheMeanOfConsecutivePairs) {
    const std::vector<std::vector<uint8_t>> frames = {{0, 0, 0}, {3, 3, 3}, {3, 3, 3}};
    EXPECT_DOUBLE_EQ(meanFrameToFrameDifference(frames), (3.0 + 0.0) / 2.0);
    EXPECT_EQ(meanFrameToFrameDifference({{1, 2, 3}}), 0.0);
}

TEST(ImageError, TemporalErrorIsTheFlickerTheReferenceDoesNotHave) {
    // Both brighten by 3 (motion): no error. The sequence's second value flickers by 4 and back.
    const std::vector<std::vector<uint8_t>> reference = {{10, 10}, {13, 10}, {16, 10}};
    const std::vector<std::vector<uint8_t>> frames = {{10, 10}, {13, 14}, {16, 10}};
    EXPECT_DOUBLE_EQ(meanTemporalError(reference, reference), 0.0);
    EXPECT_DOUBLE_EQ(meanTemporalError(frames, reference), (0.0 + 4.0 + 0.0 + 4.0) / 4.0);
}

}  // namespace
}  // namespace candela::reports
