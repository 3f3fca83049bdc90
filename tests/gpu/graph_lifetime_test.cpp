// Building, executing and destroying the frame graph many times must leak nothing, and the barriers
// the graph plans must be exactly what synchronization validation needs.
#include "gpu_test.h"

#include "render/renderer.h"

namespace candela::test {
namespace {

TEST_F(GpuTest, ThousandGraphsLeaveNoGrowthInVulkanObjectsOrDeviceMemory) {
    Renderer renderer(context());
    const RenderSettings settings{.width = 32, .height = 24};
    // Warm-up: every frame slot builds its transients once.
    for (int i = 0; i < 10; ++i) renderer.capture(settings);
    const int64_t objects = context().liveObjects();
    const vk::MemoryStats memory = context().allocator().stats();
    const uint32_t rebuilds = renderer.transientRebuilds();
    for (int i = 0; i < 1000; ++i) renderer.capture(settings);
    EXPECT_EQ(context().liveObjects(), objects);
    EXPECT_EQ(context().allocator().stats().deviceMemoryBytes, memory.deviceMemoryBytes);
    EXPECT_EQ(context().allocator().stats().deviceMemoryObjects, memory.deviceMemoryObjects);
    EXPECT_EQ(context().allocator().stats().liveAllocations, memory.liveAllocations);
    EXPECT_EQ(renderer.transientRebuilds(), rebuilds);
}

TEST_F(GpuTest, ChangingTheGraphRebuildsTransientsWithoutLeaking) {
    {
        Renderer renderer(context());
        for (uint32_t size = 16; size < 48; size += 4) renderer.capture({.width = size, .height = size});
    }
    context().waitIdleAndCollect();
    EXPECT_EQ(context().liveObjects(), 0);
    EXPECT_EQ(context().allocator().stats().liveAllocations, 0u);
}

TEST_F(GpuTest, SynchronizationValidationCatchesAGraphWithoutBarriers) {
    // Proves the layer is on and watching: the same graph with its planned barriers removed must be
    // reported (the planned barriers are what keeps every other test clean).
    expectValidationMessages();
    Renderer renderer(context(), {.emitBarriers = false});
    renderer.capture({.width = 32, .height = 32});
    bool hazard = false;
    for (const vk::ValidationMessage& m : context().validationMessages())
        hazard = hazard || m.text.find("SYNC-HAZARD") != std::string::npos;
    EXPECT_TRUE(hazard) << "synchronization validation reported no hazard";
}

}  // namespace
}  // namespace candela::test
