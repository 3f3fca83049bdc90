// Device and queue-family choice on the layouts of real GPUs, not only lavapipe's single family.
#include "core/errors.h"
#include "vk/device_select.h"

#include <gtest/gtest.h>

namespace candela::vk {
namespace {

VkQueueFamilyProperties family(VkQueueFlags flags, uint32_t count = 1) {
    VkQueueFamilyProperties p{};
    p.queueFlags = flags;
    p.queueCount = count;
    return p;
}

constexpr VkQueueFlags G = VK_QUEUE_GRAPHICS_BIT, C = VK_QUEUE_COMPUTE_BIT, T = VK_QUEUE_TRANSFER_BIT,
                       S = VK_QUEUE_SPARSE_BINDING_BIT;

TEST(QueueFamilies, LavapipeSingleFamily) {
    const auto q = chooseQueueFamilies({family(G | C | T)});
    EXPECT_EQ(q.graphics, 0u);
    EXPECT_EQ(q.compute, 0u);
    EXPECT_EQ(q.transfer, 0u);
}

TEST(QueueFamilies, DiscreteGpuWithAsyncComputeAndCopyEngine) {
    // NVIDIA-like: 0 = G|C|T|S (16), 1 = T|S (2), 2 = C|T|S (8).
    const auto q = chooseQueueFamilies({family(G | C | T | S, 16), family(T | S, 2), family(C | T | S, 8)});
    EXPECT_EQ(q.graphics, 0u);
    EXPECT_EQ(q.compute, 2u);
    EXPECT_EQ(q.transfer, 1u);
}

TEST(QueueFamilies, GraphicsFamilyNotFirst) {
    // A device listing a transfer-only family first must not put the frame on it.
    const auto q = chooseQueueFamilies({family(T), family(C | T), family(G | C | T)});
    EXPECT_EQ(q.graphics, 2u);
    EXPECT_EQ(q.compute, 1u);
    EXPECT_EQ(q.transfer, 0u);
}

TEST(QueueFamilies, PresentSupportRequired) {
    const auto q = chooseQueueFamilies({family(G | C | T), family(G | C | T)}, {false, true});
    EXPECT_EQ(q.graphics, 1u);
    EXPECT_THROW(chooseQueueFamilies({family(G | C | T)}, {false}), std::runtime_error);
}

TEST(QueueFamilies, EmptyFamiliesAndNoGraphicsAreRejected) {
    EXPECT_THROW(chooseQueueFamilies({family(G | C | T, 0)}), std::runtime_error);
    EXPECT_THROW(chooseQueueFamilies({family(C | T)}), std::runtime_error);
}

const std::vector<DeviceCandidate> kDevices = {
    {"llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU, VK_API_VERSION_1_3, ""},
    {"Intel(R) UHD Graphics 630", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, VK_API_VERSION_1_3, ""},
    {"NVIDIA GeForce RTX 3080", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_3, ""},
    {"Old GPU", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_1, "Vulkan 1.1.0 < 1.3"},
};

TEST(DeviceChoice, PrefersDiscreteThenIntegratedThenCpu) {
    EXPECT_EQ(chooseDevice(kDevices, "").index, 2u);
    EXPECT_EQ(chooseDevice({kDevices[0], kDevices[1]}, "").index, 1u);
    EXPECT_EQ(chooseDevice({kDevices[0]}, "").index, 0u);
    EXPECT_EQ(chooseDevice({kDevices[3], kDevices[0]}, "").index, 1u);  // unsuitable discrete skipped
}

TEST(DeviceChoice, SelectorByIndexOrName) {
    EXPECT_EQ(chooseDevice(kDevices, "0").index, 0u);
    EXPECT_EQ(chooseDevice(kDevices, "intel").index, 1u);
    EXPECT_EQ(chooseDevice(kDevices, "LLVMPIPE").index, 0u);
    EXPECT_THROW(chooseDevice(kDevices, "radeon"), UserError);
    EXPECT_THROW(chooseDevice(kDevices, "9"), UserError);
    EXPECT_THROW(chooseDevice(kDevices, "old gpu"), UserError);  // matches, but unusable
    EXPECT_THROW(chooseDevice({}, ""), UserError);
}

TEST(DeviceChoice, ReasonSaysWhy) {
    EXPECT_NE(chooseDevice(kDevices, "").reason.find("discrete"), std::string::npos);
    EXPECT_NE(chooseDevice(kDevices, "intel").reason.find("--device"), std::string::npos);
}

}  // namespace
}  // namespace candela::vk
