// Memory-type choice (vk::chooseMemoryType) on the memory types real GPUs report: per-frame data
// the shaders read (Stream) goes to host-visible device-local memory where the device has it
// (resizable BAR, unified memory), staging (Upload) stays out of it, device-only data is
// device-local, lazily allocated memory is never picked unless it is all that is allowed.
#include "vk/memory.h"

#include <gtest/gtest.h>

#include <initializer_list>

namespace candela::vk {
namespace {

constexpr VkMemoryPropertyFlags DL = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, HV = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT,
                                HC = VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, CA = VK_MEMORY_PROPERTY_HOST_CACHED_BIT,
                                LA = VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT;

VkPhysicalDeviceMemoryProperties types(std::initializer_list<VkMemoryPropertyFlags> flags) {
    VkPhysicalDeviceMemoryProperties p{};
    for (VkMemoryPropertyFlags f : flags) p.memoryTypes[p.memoryTypeCount++].propertyFlags = f;
    return p;
}

uint32_t choose(const VkPhysicalDeviceMemoryProperties& p, MemoryUsage usage, uint32_t typeBits = ~0u) {
    return chooseMemoryType(p, typeBits, ~0u, usage);
}

TEST(MemoryType, DiscreteGpuWithResizableBar) {
    // NVIDIA/AMD with resizable BAR: device-local; system memory (coherent; cached);
    // the BAR window (device-local, host-visible, coherent).
    const auto p = types({DL, HV | HC, HV | HC | CA, DL | HV | HC});
    EXPECT_EQ(choose(p, MemoryUsage::GpuOnly), 0u);
    EXPECT_EQ(choose(p, MemoryUsage::Stream), 3u) << "per-frame data in the BAR: the GPU reads it locally";
    EXPECT_EQ(choose(p, MemoryUsage::Upload), 1u) << "staging never in the BAR";
    EXPECT_EQ(choose(p, MemoryUsage::Readback), 2u);
}

TEST(MemoryType, DiscreteGpuWithoutResizableBar) {
    const auto p = types({DL, HV | HC, HV | HC | CA});
    EXPECT_EQ(choose(p, MemoryUsage::Stream), 1u) << "system memory, read over PCIe";
    EXPECT_EQ(choose(p, MemoryUsage::Upload), 1u);
}

TEST(MemoryType, UnifiedMemoryAndLavapipe) {
    // Intel/AMD integrated: every type device-local.
    const auto integrated = types({DL, DL | HV | HC, DL | HV | HC | CA});
    EXPECT_EQ(choose(integrated, MemoryUsage::Stream), 1u);
    EXPECT_EQ(choose(integrated, MemoryUsage::Upload), 1u);
    EXPECT_EQ(choose(integrated, MemoryUsage::Readback), 2u);
    // lavapipe: one type with every flag.
    const auto lavapipe = types({DL | HV | HC | CA});
    for (MemoryUsage u : {MemoryUsage::GpuOnly, MemoryUsage::Stream, MemoryUsage::Upload, MemoryUsage::Readback})
        EXPECT_EQ(choose(lavapipe, u), 0u);
}

TEST(MemoryType, LazilyAllocatedMemoryOnlyWhenItIsAllThatIsAllowed) {
    // Apple (MoltenVK): private, shared, memoryless.
    const auto p = types({DL | LA, DL, DL | HV | HC});
    EXPECT_EQ(choose(p, MemoryUsage::GpuOnly), 1u);
    EXPECT_EQ(choose(p, MemoryUsage::GpuOnly, 0b001u), 0u) << "a transient attachment restricted to it";
}

TEST(MemoryType, NoTypeWithTheRequiredFlags) {
    const auto p = types({DL});
    EXPECT_EQ(choose(p, MemoryUsage::Upload), ~0u);
    // A type hidden by the mask (a device profile) is not chosen.
    EXPECT_EQ(chooseMemoryType(types({DL, DL | HV | HC}), ~0u, 0b01u, MemoryUsage::Stream), ~0u);
}

TEST(MemoryType, AnAllocationPastTheHeapBudgetIsRefused) {
    EXPECT_EQ(heapBudgetRefusal(100 << 20, 256 << 20, 64 << 20), "");
    EXPECT_EQ(heapBudgetRefusal(200 << 20, 256 << 20, 64 << 20),
              "the memory heap's budget of 256.0 MiB would be passed (200.0 MiB in use by this process, VK_EXT_memory_budget)");
    EXPECT_EQ(heapBudgetRefusal(0, 0, 64 << 20), "") << "a budget of 0 means none reported";
}

}  // namespace
}  // namespace candela::vk
