// Descriptor pools that grow with the scene (#27): the allocator tracks what each pool has left
// and moves on before a pool overflows (as AMD and Intel enforce, and lavapipe does not), with no
// cap on the number of pools; a scene of 5,041 materials renders. In CI these also run under the
// minimum device profile ("minimum/" tests).
#include "gpu_test.h"

#include "assets/builtin_scenes.h"
#include "render/renderer.h"
#include "vk/descriptors.h"

#include <set>

namespace candela::test {
namespace {

TEST_F(GpuTest, DescriptorPoolsGrowPastAFullPoolWithoutACap) {
    const vk::Pipeline pipeline = vk::Pipeline::compute(context(), "pattern.comp");
    vk::Image image(context(), {.width = 4, .height = 4, .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                .usage = VK_IMAGE_USAGE_STORAGE_BIT});
    // First pool: 4 sets. Then 8, 16, 32, 64: 124 sets in 5 pools; the 125th set needs a sixth.
    vk::DescriptorAllocator allocator(context(), 4);
    std::set<VkDescriptorSet> sets;
    const auto allocate = [&](uint32_t count) {
        for (uint32_t i = 0; i < count; ++i)
            sets.insert(vk::DescriptorWriter(pipeline.program(), 0)
                            .image("outImage", image.view(), VK_IMAGE_LAYOUT_GENERAL)
                            .commit(context(), allocator));
    };
    allocate(124);
    EXPECT_EQ(allocator.poolCount(), 5u);
    EXPECT_EQ(sets.size(), 124u);
    allocate(1);
    EXPECT_EQ(allocator.poolCount(), 6u);
    // After a reset the pools are reused, not multiplied.
    allocator.reset();
    allocate(125);
    EXPECT_EQ(allocator.poolCount(), 6u);
}

TEST_F(GpuTest, ReservedDescriptorsTakeOnePoolAndALargeSetGetsAPoolItFits) {
    const vk::Pipeline pipeline = vk::Pipeline::compute(context(), "pattern.comp");
    vk::Image image(context(), {.width = 4, .height = 4, .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                .usage = VK_IMAGE_USAGE_STORAGE_BIT});
    const vk::DescriptorCounts one = vk::DescriptorCounts::ofSet(pipeline.program(), 0);
    EXPECT_EQ(one.sets, 1u);
    vk::DescriptorAllocator allocator(context(), 1);
    allocator.reserve(one * 300);
    for (int i = 0; i < 300; ++i)
        vk::DescriptorWriter(pipeline.program(), 0).image("outImage", image.view(), VK_IMAGE_LAYOUT_GENERAL).commit(context(), allocator);
    EXPECT_EQ(allocator.poolCount(), 1u);

    // A set needing more descriptors of a type than a default pool holds gets a pool sized for it:
    // the forward program's material set has 5 combined image samplers, a 1-set pool holds 4.
    const vk::Program forward(context(), {"forward.vert", "forward.frag"});
    const vk::DescriptorCounts material = vk::DescriptorCounts::ofSet(forward, 1);
    EXPECT_EQ(material.descriptors[0], 5u);
    vk::DescriptorAllocator small(context(), 1);
    EXPECT_NE(small.allocate(forward.setLayout(1), material), VK_NULL_HANDLE);
    EXPECT_EQ(small.poolCount(), 1u);
}

TEST_F(GpuTest, FiveThousandMaterialsRender) {
    // Metric: the three base colours the 5,041 materials cycle through (red, green, blue by material
    // index) each dominate a share of the covered pixels: a material set written or bound for the
    // wrong material would shift the shares; a failed pool, a throw.
    const scene::Scene scene = assets::makeSphereGrid(71, true);
    ASSERT_EQ(scene.materials.size(), 71u * 71u);
    Renderer renderer(context());
    RenderSettings settings{.width = 320, .height = 320, .scene = &scene};
    const CapturedFrame frame = renderer.capture(settings);
    uint32_t dominant[3] = {0, 0, 0};
    for (size_t p = 0; p < frame.rgba8.size(); p += 4) {
        const uint8_t* c = &frame.rgba8[p];
        for (int i = 0; i < 3; ++i)
            if (c[i] > 2 * c[(i + 1) % 3] + 8 && c[i] > 2 * c[(i + 2) % 3] + 8) ++dominant[i];
    }
    const uint32_t covered = dominant[0] + dominant[1] + dominant[2];
    EXPECT_GT(covered, 5000u) << "the lit parts of the spheres (the metallic ones are dark without an environment)";
    for (int i = 0; i < 3; ++i) {
        EXPECT_GT(dominant[i], covered / 5) << "channel " << i;
        EXPECT_LT(dominant[i], covered / 2) << "channel " << i;
    }
}

}  // namespace
}  // namespace candela::test
