#pragma once
// MemoryAllocator: sub-allocates device memory from large blocks, so small resources do not each
// cost a vkAllocateMemory (drivers cap the count; maxMemoryAllocationCount is often 4096).
// Vulkan Memory Allocator is not packaged in Debian 12; this is a deliberately small first-fit
// block allocator (see docs/hand-written.md).
//
// Blocks are kept per (memory type, linear/optimal) so buffers and optimally tiled images never
// share a block and bufferImageGranularity cannot bite. Requests larger than half a block get a
// dedicated allocation. Host-visible memory is mapped persistently.
// Not thread-safe: one owner thread (the renderer's).

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace candela::vk {

enum class MemoryUsage : uint8_t {
    GpuOnly,   // device-local
    Upload,    // host-visible, coherent, for staging: preferably not device-local (a discrete GPU's
               // host-visible device-local heap, resizable BAR, is small and kept for Stream)
    Stream,    // host-visible, coherent, written by the host each frame and read by shaders:
               // preferably device-local (resizable BAR, unified memory), else system memory
    Readback,  // host-visible, preferably cached, for reading results back
};

enum class ResourceTiling : uint8_t { Linear, Optimal };  // buffers are Linear

struct Allocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
    std::byte* mapped = nullptr;  // null unless host-visible
    uint32_t memoryType = 0;
    uint32_t block = ~0u;  // index of the owning block; ~0u for dedicated allocations
    bool coherent = true;
    explicit operator bool() const { return memory != VK_NULL_HANDLE; }
};

// Memory a resource is bound to but does not own (aliased transients of the render graph): `size`
// bytes at `offset` of `memory`, of memory type `memoryType`.
struct ExternalMemory {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
    uint32_t memoryType = 0;
};

// Checks that `requirements` (queried from the object about to be bound) fit `memory`: enough
// bytes, the offset aligned, the memory type allowed. Throws InternalError naming `what` otherwise
// (the placement was planned from other requirements than the object has).
void checkFits(const VkMemoryRequirements& requirements, const ExternalMemory& memory, const char* what);

struct MemoryStats {
    uint64_t deviceMemoryBytes = 0;  // bytes held in VkDeviceMemory objects (blocks + dedicated)
    uint32_t deviceMemoryObjects = 0;
    uint64_t allocatedBytes = 0;     // bytes handed out to resources
    uint32_t liveAllocations = 0;
};

// The memory type for `usage` among the types in `typeBits` & `typeMask` of `properties`: one with
// the flags the usage requires, then the most preferred flags, then the fewest avoided ones (see
// MemoryUsage), then not lazily allocated; ~0u if none has the required flags. Pure: unit-tested
// on real GPUs' memory types.
uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& properties, uint32_t typeBits, uint32_t typeMask,
                          MemoryUsage usage);

// Why an allocation of `size` bytes from a heap that uses `usage` of `budget` bytes
// (VK_EXT_memory_budget) must be refused, or "" when it fits. Pure.
std::string heapBudgetRefusal(VkDeviceSize usage, VkDeviceSize budget, VkDeviceSize size);

class MemoryAllocator {
public:
    // Allocates only from the memory types in `typeMask` (DeviceCaps::memoryTypeMask: a device
    // profile may hide some).
    MemoryAllocator(VkPhysicalDevice physicalDevice, VkDevice device, uint32_t typeMask = ~0u,
                    VkDeviceSize blockSize = 64ull << 20);
    ~MemoryAllocator();
    MemoryAllocator(const MemoryAllocator&) = delete;
    MemoryAllocator& operator=(const MemoryAllocator&) = delete;

    // Allocates memory satisfying `requirements` for `usage`. Throws OutOfDeviceMemory when the
    // device has no memory left or the budget would be exceeded (a small request that does not fit
    // a new block is tried once more as a dedicated allocation of its own size).
    Allocation allocate(const VkMemoryRequirements& requirements, MemoryUsage usage, ResourceTiling tiling);
    // Returns memory to its block (or frees a dedicated allocation). Empty allocations are ignored.
    // Precondition: no pending GPU work uses it (callers free through the deferred deletion queue).
    void free(const Allocation& allocation);

    // Caps the bytes held in VkDeviceMemory objects (0: no cap) — to simulate small devices and
    // test what happens when memory runs out. New blocks are then an eighth of the budget.
    void setBudget(VkDeviceSize bytes) { mBudget = bytes; }
    VkDeviceSize budget() const { return mBudget; }
    // With VK_EXT_memory_budget enabled: before each vkAllocateMemory the heap's budget (what the
    // driver says this process may use, other processes' use considered) is read, and an
    // allocation that would pass it fails as OutOfDeviceMemory (so the memory fallbacks run)
    // instead of paging or failing later.
    void useHeapBudgets(bool enabled) { mHeapBudgets = enabled; }
    // The device's memory is ordinary host memory (a CPU device: lavapipe's is the process's own
    // heap). With it, each new mapped allocation is advised to the kernel as a transparent-huge-page
    // candidate (core/process_memory.h adviseHugePages), so that first touches fault 2 MiB at a time
    // rather than 4 KiB: a DamagedHelmet render touched ~27,000 fresh pages of texture memory.
    void useHugePages(bool enabled) { mHugePages = enabled; }
    // Per heap: bytes this process uses and may use (VK_EXT_memory_budget); empty without it.
    std::vector<std::pair<VkDeviceSize, VkDeviceSize>> heapBudgets() const;

    // Frees blocks that hold no allocation. Context::waitIdleAndCollect calls it.
    void trim();

    MemoryStats stats() const;
    const VkPhysicalDeviceMemoryProperties& properties() const { return mProperties; }
    uint32_t typeMask() const { return mTypeMask; }
    // Index of the best memory type for `usage` among `typeBits`; throws if none fits.
    uint32_t findMemoryType(uint32_t typeBits, MemoryUsage usage) const;

private:
    struct Block {
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkDeviceSize size = 0;
        uint32_t memoryType = 0;
        ResourceTiling tiling = ResourceTiling::Linear;
        std::byte* mapped = nullptr;
        std::map<VkDeviceSize, VkDeviceSize> freeRanges;  // offset → size, coalesced
        uint32_t liveAllocations = 0;
    };

    VkDeviceMemory allocateDeviceMemory(VkDeviceSize size, uint32_t memoryType, std::byte** mapped);
    bool tryAllocateFromBlock(Block& block, const VkMemoryRequirements& requirements, Allocation& out);

    VkPhysicalDevice mPhysicalDevice;
    VkDevice mDevice;
    uint32_t mTypeMask = ~0u;
    VkDeviceSize mBlockSize;
    VkDeviceSize mBudget = 0;
    bool mHeapBudgets = false;
    bool mHugePages = false;
    VkPhysicalDeviceMemoryProperties mProperties{};
    std::vector<std::unique_ptr<Block>> mBlocks;  // null entries are freed blocks (indices stay stable)
    MemoryStats mStats;
};

}  // namespace candela::vk
