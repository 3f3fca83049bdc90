// End-to-end capture through the foundation's frame graph: the pixels read back must equal what the
// passes compute, evaluated on the CPU from the same shared pattern function.
#include "gpu_test.h"

#include "core/errors.h"
#include "render/renderer.h"
#include "shared/pattern.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>

namespace candela::test::capture_test {
namespace {

glm::vec3 referenceRadiance(uint32_t x, uint32_t y, uint32_t width, uint32_t height) {
    const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / glm::vec2(width, height);
    return shading::patternRadiance(uv);
}

double srgbEncode(double linear) {
    linear = std::clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

uint32_t passIndex(const graph::RenderGraph& g, const char* name) { return *g.findPass(name); }

// Sizes that are not multiples of the 8×8 workgroup exercise the shader's bounds check.
constexpr uint32_t kWidth = 97, kHeight = 61;

TEST_F(GpuTest, PngCaptureMatchesCpuReferenceWithinOneLevel) {
    Renderer renderer(context());
    const CapturedFrame frame = renderer.capture({.width = kWidth, .height = kHeight});
    ASSERT_EQ(frame.rgba8.size(), size_t(kWidth) * kHeight * 4);
    // Metric: max abs difference per 8-bit channel over all pixels; tolerance 1 level (the GPU's
    // sRGB encode and the pattern's float math may round differently by one step).
    int maxDiff = 0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const glm::vec3 radiance = referenceRadiance(x, y, kWidth, kHeight);
            for (int c = 0; c < 3; ++c) {
                const int expected = static_cast<int>(std::lround(srgbEncode(radiance[c]) * 255.0));
                maxDiff = std::max(maxDiff, std::abs(expected - frame.rgba8[(size_t(y) * kWidth + x) * 4 + c]));
            }
            EXPECT_EQ(frame.rgba8[(size_t(y) * kWidth + x) * 4 + 3], 255);
        }
    EXPECT_LE(maxDiff, 1);
    const graph::CompiledGraph& compiled = renderer.lastGraph().compiled();
    EXPECT_EQ(compiled.order.size(), 3u);  // pattern, encode, readback
}

TEST_F(GpuTest, FloatCaptureMatchesCpuReferenceAndCullsEncode) {
    Renderer renderer(context());
    const CapturedFrame frame = renderer.capture({.width = kWidth, .height = kHeight, .floatOutput = true});
    ASSERT_EQ(frame.rgba32f.size(), size_t(kWidth) * kHeight * 4);
    // Metric: max relative error per channel against the CPU float evaluation rounded to half
    // precision; tolerance 2e-3 (half has an 11-bit significand, the GPU's exp2 a few ulp).
    double maxRelative = 0.0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const glm::vec3 radiance = referenceRadiance(x, y, kWidth, kHeight);
            for (int c = 0; c < 3; ++c) {
                const double expected = glm::unpackHalf1x16(glm::packHalf1x16(radiance[c]));
                const double got = frame.rgba32f[(size_t(y) * kWidth + x) * 4 + c];
                maxRelative = std::max(maxRelative, std::abs(got - expected) / std::max(expected, 1e-3));
            }
        }
    EXPECT_LE(maxRelative, 2e-3);
    const graph::RenderGraph& g = renderer.lastGraph();
    EXPECT_EQ(g.compiled().passes[passIndex(g, "encode")].cullReason, graph::CullReason::NoOutput);
    EXPECT_EQ(g.compiled().order.size(), 2u);
}

TEST_F(GpuTest, DisablingThePatternPassCullsEverythingAndReportsIt) {
    Renderer renderer(context());
    EXPECT_THROW(renderer.capture({.width = 16, .height = 16, .disabledPasses = {"pattern"}}), UserError);
    const graph::RenderGraph& g = renderer.lastGraph();
    EXPECT_EQ(g.compiled().passes[passIndex(g, "pattern")].cullReason, graph::CullReason::Disabled);
    EXPECT_EQ(g.compiled().passes[passIndex(g, "encode")].cullReason, graph::CullReason::LostInput);
    EXPECT_EQ(g.compiled().passes[passIndex(g, "readback")].cullReason, graph::CullReason::LostInput);
}

TEST_F(GpuTest, TimestampsMeasureEveryPassThatRan) {
    if (context().report().timestampValidBits == 0) GTEST_SKIP() << "queue has no timestamps";
    Renderer renderer(context());
    const CapturedFrame frame = renderer.capture({.width = 64, .height = 64});
    for (uint32_t pass : renderer.lastGraph().compiled().order) EXPECT_GE(frame.timings.gpuMs[pass], 0.0);
}

}  // namespace
}  // namespace candela::test::capture_test
