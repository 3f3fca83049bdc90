// Frames in flight with an environment (#27 item 6): Renderer::renderToTarget waits only for a
// frame that computed persistent maps (the IBL precompute, the sheen LUT), not for every frame
// lit by the maps; the frames after it run ahead and still see the computed maps. The target is
// an offscreen image standing in for a swapchain image, so no window is needed (the viewer tests
// run the same frames into a swapchain). The fixture fails the test on any validation message
// (synchronization validation included): the frames in flight are ordered by the graph's barriers.
#include "gpu_test.h"

#include "assets/builtin_scenes.h"
#include "assets/procedural_sky.h"
#include "render/renderer.h"
#include "vk/image.h"

#include <cstdio>
#include <vector>

namespace candela::test::frames_in_flight_test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;

// A presentable image without a window (as `bench --in-flight` uses): RGBA8, readable by the
// screenshot path, no semaphores (no presentation engine), resting in the colour-attachment layout.
class OffscreenTarget {
public:
    explicit OffscreenTarget(vk::Context& context)
        : mImage(context, {.width = kWidth,
                           .height = kHeight,
                           .format = VK_FORMAT_R8G8B8A8_UNORM,
                           .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           .name = "offscreen target"}) {}

    // One frame as the viewer renders it; with `shot`, read back into it (which waits for it).
    void frame(Renderer& renderer, const RenderSettings& settings, CapturedFrame* shot = nullptr) {
        renderer.renderToTarget(settings,
                                {.image = mImage.handle(),
                                 .view = mImage.view(),
                                 .format = VK_FORMAT_R8G8B8A8_UNORM,
                                 .finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
                                {}, shot);
    }

private:
    vk::Image mImage;
};

class FramesInFlightTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        // The sphere grid with a sheen on its first material: the first frame computes the IBL
        // maps and the sheen LUT.
        mScene.materials[0].sheenColorFactor = glm::vec3(1.0f);
        mScene.materials[0].sheenRoughnessFactor = 0.5f;
        mSettings.scene = &mScene;
        mSettings.environment = &mSky;
        mSettings.iblQuality.cubeSize = 64;  // a short precompute; the maps are not under test
        mSettings.iblQuality.prefilterSamples = 8;
    }
    bool ran(const Renderer& renderer, const char* pass) const {
        const std::optional<uint32_t> index = renderer.lastGraph().findPass(pass);
        return index && renderer.lastGraph().compiled().passes[*index].cullReason == graph::CullReason::None;
    }

    scene::Scene mScene = assets::makeSphereGrid();
    assets::Environment mSky = assets::makeProceduralSky();
    RenderSettings mSettings{.width = kWidth, .height = kHeight};
};

TEST_F(FramesInFlightTest, OnlyTheFrameComputingTheMapsIsWaitedForAndTheOthersRenderTheSame) {
    // The waited version: every frame read back, so each is waited for.
    std::vector<uint8_t> waited;
    {
        Renderer renderer(context());
        OffscreenTarget target(context());
        for (int i = 0; i < 3; ++i) {
            CapturedFrame shot;
            target.frame(renderer, mSettings, &shot);
            if (i > 0) {
                EXPECT_TRUE(shot.rgba8 == waited) << "frame " << i;
            }
            waited = shot.rgba8;
        }
        EXPECT_EQ(renderer.completionWaits(), 3u);
    }
    ASSERT_EQ(waited.size(), size_t(kWidth) * kHeight * 4);

    Renderer renderer(context());
    OffscreenTarget target(context());
    target.frame(renderer, mSettings);
    EXPECT_TRUE(ran(renderer, "ibl_prefilter"));
    EXPECT_TRUE(ran(renderer, "ibl_sheen_lut"));
    EXPECT_EQ(renderer.completionWaits(), 1u) << "the precompute frame is waited for";
    EXPECT_GT(renderer.lastPrecompute().gpuMs, 0.0);
    const vk::FrameRingStats before = renderer.frameRingStats();
    constexpr uint32_t kFrames = 8;
    for (uint32_t i = 0; i < kFrames; ++i) {
        target.frame(renderer, mSettings);
        // The maps are current: imported, never computed again (nor the sheen LUT).
        EXPECT_FALSE(renderer.lastGraph().findPass("ibl_prefilter").has_value()) << "frame " << i;
        EXPECT_FALSE(renderer.lastGraph().findPass("ibl_sheen_lut").has_value()) << "frame " << i;
        EXPECT_TRUE(renderer.lastGraph().findResource(ibl_maps::IblMaps::kSpecularName).has_value());
    }
    EXPECT_EQ(renderer.completionWaits(), 1u) << "a frame lit by the maps was waited for";
    const vk::FrameRingStats& after = renderer.frameRingStats();
    std::printf("%llu of %u frames with an environment submitted while an earlier one still ran; "
                "%llu blocking fence waits (%.1f ms)\n",
                (unsigned long long)(after.overlappedSubmits - before.overlappedSubmits), kFrames,
                (unsigned long long)(after.blockingWaits - before.blockingWaits), after.blockedMs - before.blockedMs);

    // The last of a run of frames in flight, read back: the same pixels as the waited version.
    CapturedFrame shot;
    target.frame(renderer, mSettings, &shot);
    EXPECT_EQ(renderer.completionWaits(), 2u);
    EXPECT_TRUE(shot.rgba8 == waited) << "frames in flight render differently";
}

TEST_F(FramesInFlightTest, ANewEnvironmentIsComputedOnceAndWaitedForOnce) {
    Renderer renderer(context());
    OffscreenTarget target(context());
    for (int i = 0; i < 3; ++i) target.frame(renderer, mSettings);
    EXPECT_EQ(renderer.completionWaits(), 1u);
    // Another sun: the next frame runs the precompute (and is waited for), the ones after do not.
    const assets::Environment other = assets::makeProceduralSky({.sunAzimuthDegrees = 200.0f});
    mSettings.environment = &other;
    target.frame(renderer, mSettings);
    EXPECT_TRUE(ran(renderer, "ibl_prefilter"));
    EXPECT_EQ(renderer.completionWaits(), 2u);
    for (int i = 0; i < 3; ++i) {
        target.frame(renderer, mSettings);
        EXPECT_FALSE(renderer.lastGraph().findPass("ibl_prefilter").has_value());
    }
    EXPECT_EQ(renderer.completionWaits(), 2u);
    // Without an environment nothing is waited for either (the sheen LUT was computed already).
    mSettings.environment = nullptr;
    for (int i = 0; i < 3; ++i) target.frame(renderer, mSettings);
    EXPECT_EQ(renderer.completionWaits(), 2u);
}

}  // namespace
}  // namespace candela::test::frames_in_flight_test
