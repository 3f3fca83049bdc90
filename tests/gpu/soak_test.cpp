// A short soak (engine/soak.h): frames with the environment switched every 50 frames. After one
// cycle through the environments, live Vulkan objects and device memory must stay exactly where
// they are, and host memory (RSS) must not keep growing.
#include "gpu_test.h"

#include "scene/builtin_scenes.h"
#include "soak.h"

namespace candela::test {
namespace {

TEST_F(GpuTest, SoakKeepsObjectsAndMemoryFlatAfterWarmUp) {
    const scene::Scene grid = scene::makeSphereGrid();
    const std::vector<scene::Environment> environments = soakEnvironments(3);
    Renderer renderer(context());
    RenderSettings settings{.width = 64, .height = 36, .scene = &grid};
    settings.iblQuality.cubeSize = 64;  // the precompute is not under test; keep it short
    const std::vector<SoakSample> samples =
        runSoak(renderer, context(), settings, environments, {.frames = 600, .switchEvery = 50, .sampleEvery = 50});
    ASSERT_EQ(samples.size(), 13u);  // frame 1, then every 50
    // Warm-up: one cycle through the three environments (150 frames) plus one switch.
    const SoakSample& reference = samples[4];  // frame 200
    ASSERT_EQ(reference.frame, 200u);
    for (size_t i = 5; i < samples.size(); ++i) {
        EXPECT_EQ(samples[i].liveVulkanObjects, reference.liveVulkanObjects) << "frame " << samples[i].frame;
        EXPECT_EQ(samples[i].deviceMemoryBytes, reference.deviceMemoryBytes) << "frame " << samples[i].frame;
        EXPECT_EQ(samples[i].liveAllocations, reference.liveAllocations) << "frame " << samples[i].frame;
    }
    // Host memory moves with the allocator's and the validation layer's caches; it must not trend up.
    EXPECT_LT(double(samples.back().residentBytes), double(reference.residentBytes) + 16.0 * (1 << 20));
}

}  // namespace
}  // namespace candela::test
