// vk::chooseMsaa: the device default (4 on GPUs, 1 on CPU devices) and the clamp to the counts a
// device supports, with the line `info` and `--explain` print.

#include "vk/msaa.h"

#include <gtest/gtest.h>

namespace candela::vk {
namespace {

constexpr VkSampleCountFlags kLavapipe = VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT;
constexpr VkSampleCountFlags kDesktop = VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_2_BIT | VK_SAMPLE_COUNT_4_BIT |
                                        VK_SAMPLE_COUNT_8_BIT;

TEST(MsaaChoice, DefaultsToFourOnGpusAndOneOnCpuDevices) {
    for (VkPhysicalDeviceType gpu : {VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU,
                                     VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU}) {
        const MsaaChoice choice = chooseMsaa(gpu, kDesktop, std::nullopt);
        EXPECT_EQ(choice.samples, 4u);
        EXPECT_FALSE(choice.clamped);
        EXPECT_NE(choice.reason.find("default on GPUs"), std::string::npos) << choice.reason;
    }
    const MsaaChoice cpu = chooseMsaa(VK_PHYSICAL_DEVICE_TYPE_CPU, kLavapipe, std::nullopt);
    EXPECT_EQ(cpu.samples, 1u);
    EXPECT_NE(cpu.reason.find("default on CPU devices"), std::string::npos) << cpu.reason;
}

TEST(MsaaChoice, RequestsAreHonouredOrClampedDownToASupportedCount) {
    EXPECT_EQ(chooseMsaa(VK_PHYSICAL_DEVICE_TYPE_CPU, kLavapipe, 4u).samples, 4u);
    EXPECT_EQ(chooseMsaa(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, kDesktop, 2u).samples, 2u);
    EXPECT_EQ(chooseMsaa(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, kDesktop, 1u).samples, 1u);
    const MsaaChoice eight = chooseMsaa(VK_PHYSICAL_DEVICE_TYPE_CPU, kLavapipe, 8u);
    EXPECT_EQ(eight.samples, 4u);
    EXPECT_TRUE(eight.clamped);
    EXPECT_EQ(eight.reason, "4 samples: 8 asked, the device supports 1, 4");
    const MsaaChoice two = chooseMsaa(VK_PHYSICAL_DEVICE_TYPE_CPU, kLavapipe, 2u);
    EXPECT_EQ(two.samples, 1u);
    EXPECT_TRUE(two.clamped);
}

}  // namespace
}  // namespace candela::vk
