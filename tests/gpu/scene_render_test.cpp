// The scene frame graph (forward → tonemap → readback) on the built-in sphere grid.
#include "gpu_test.h"

#include "assets/builtin_scenes.h"
#include "assets/image_file.h"
#include "render/renderer.h"
#include "shared/tonemap.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace candela::test {
namespace {

// Writes captures next to the test binary when CANDELA_TEST_OUTPUT is set (for looking at them).
void maybeWrite(const char* name, const CapturedFrame& frame) {
    if (const char* dir = std::getenv("CANDELA_TEST_OUTPUT"))
        assets::writePng(std::string(dir) + "/" + name, frame.width, frame.height, frame.rgba8);
}

TEST_F(GpuTest, SphereGridRendersFiniteHdrAndCullsTonemapForFloatOutput) {
    const scene::Scene grid = assets::makeSphereGrid();
    Renderer renderer(context());
    const CapturedFrame hdr = renderer.capture({.width = 160, .height = 90, .floatOutput = true, .scene = &grid});
    double covered = 0.0;  // pixels, by alpha: the area covered whatever the device's default sample count
    for (size_t i = 0; i < hdr.rgba32f.size(); ++i) {
        ASSERT_TRUE(std::isfinite(hdr.rgba32f[i])) << "texel " << i / 4;
        if (i % 4 == 3) covered += hdr.rgba32f[i];
    }
    // 49 unit spheres framed head-on, the grid's box across 1/1.1 of the height of a 16:9 image,
    // cover about 18% of it (measured 18.4% at 1 sample, 18.3% at 4). Counting pixels of alpha
    // over 0.5 instead would drop to 16.9% at 4 samples: the identical spheres' edges cross
    // their pixels alike, two of four samples in.
    const double pixels = double(hdr.rgba32f.size() / 4);
    EXPECT_GT(covered, pixels * 0.16);
    EXPECT_LT(covered, pixels * 0.21);
    const graph::RenderGraph& g = renderer.lastGraph();
    EXPECT_EQ(g.compiled().passes[*g.findPass("tonemap")].cullReason, graph::CullReason::NoOutput);
}

TEST_F(GpuTest, SphereGridPngHasLitSpheresOnTheBackground) {
    const scene::Scene grid = assets::makeSphereGrid();
    Renderer renderer(context());
    RenderSettings settings{.width = 960, .height = 540, .scene = &grid};
    settings.tonemap.background = shading::srgbDecode(glm::vec3(0x26 / 255.0f));
    const CapturedFrame frame = renderer.capture(settings);
    maybeWrite("sphere_grid.png", frame);
    ASSERT_EQ(frame.rgba8.size(), 960u * 540u * 4u);
    // Corner pixel: the default background #262626.
    EXPECT_EQ(frame.rgba8[0], 0x26);
    EXPECT_EQ(frame.rgba8[3], 255);
}

TEST_F(GpuTest, TransparentBackgroundWritesAlphaZeroOutsideGeometry) {
    const scene::Scene grid = assets::makeSphereGrid();
    Renderer renderer(context());
    const CapturedFrame frame = renderer.capture({.width = 160, .height = 90, .scene = &grid});  // no background
    EXPECT_EQ(frame.rgba8[3], 0);  // corner: background
    const size_t centre = (size_t(45) * 160 + 80) * 4;  // the middle sphere
    EXPECT_EQ(frame.rgba8[centre + 3], 255);
}

TEST_F(GpuTest, SceneLightsOffLeavesTheFilesLightsOut) {
    // The grid's four point lights are the scene's own: off, with no default lights and no
    // environment, nothing lights the spheres — covered pixels stay, black; with default lights
    // the scene counts as light-less and gets the key and fill lights instead.
    const scene::Scene grid = assets::makeSphereGrid();
    Renderer renderer(context());
    RenderSettings settings{.width = 160, .height = 90, .floatOutput = true, .scene = &grid, .defaultLights = false,
                            .sceneLights = false};
    // Full detail: at this size the spheres' coarsest level (8 × 4) would flatten the difference
    // between the two lightings this test looks for.
    settings.drawSelection.lodErrorPixels = 0.0f;
    const CapturedFrame dark = renderer.capture(settings);
    size_t covered = 0;
    for (size_t i = 0; i < dark.rgba32f.size(); i += 4) {
        if (dark.rgba32f[i + 3] < 0.5f) continue;
        ++covered;
        for (int c = 0; c < 3; ++c) ASSERT_EQ(dark.rgba32f[i + size_t(c)], 0.0f) << "texel " << i / 4;
    }
    EXPECT_GT(covered, dark.rgba32f.size() / 4 * 8 / 100);
    const std::vector<std::string> notes = renderer.explain();
    EXPECT_NE(std::find(notes.begin(), notes.end(), "left out: the scene's 4 punctual lights (--scene-lights off)"), notes.end());

    settings.defaultLights = true;
    const CapturedFrame keyFill = renderer.capture(settings);
    settings.sceneLights = true;
    const CapturedFrame own = renderer.capture(settings);
    double keyFillSum = 0.0, ownSum = 0.0;
    for (size_t i = 0; i < own.rgba32f.size(); i += 4) keyFillSum += keyFill.rgba32f[i], ownSum += own.rgba32f[i];
    EXPECT_GT(keyFillSum, 0.0);
    EXPECT_GT(ownSum, 0.0);
    EXPECT_GT(std::abs(keyFillSum - ownSum), 0.05 * ownSum);  // different lights, a different image
}

}  // namespace
}  // namespace candela::test
