#include "vk/memory.h"

#include "core/process_memory.h"
#include "vk/check.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace candela::vk {

void checkFits(const VkMemoryRequirements& requirements, const ExternalMemory& memory, const char* what) {
    const bool aligned = requirements.alignment == 0 || memory.offset % requirements.alignment == 0;
    const bool typeAllowed = (requirements.memoryTypeBits & (1u << memory.memoryType)) != 0;
    if (requirements.size <= memory.size && aligned && typeAllowed) return;
    throw InternalError(std::string(what ? what : "unnamed") + " needs " + formatBytes(requirements.size) + " aligned to " +
                        std::to_string(requirements.alignment) + " in memory-type bits " +
                        std::to_string(requirements.memoryTypeBits) + ", but was placed in " +
                        formatBytes(memory.size) + " at offset " + std::to_string(memory.offset) + " of type " +
                        std::to_string(memory.memoryType));
}

namespace {

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) { return (value + alignment - 1) / alignment * alignment; }

VkMemoryPropertyFlags requiredFlags(MemoryUsage usage) {
    switch (usage) {
        case MemoryUsage::GpuOnly: return 0;
        case MemoryUsage::Upload:
        case MemoryUsage::Stream: return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        case MemoryUsage::Readback: return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
    }
    return 0;
}

VkMemoryPropertyFlags preferredFlags(MemoryUsage usage) {
    switch (usage) {
        case MemoryUsage::GpuOnly: return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        case MemoryUsage::Upload: return 0;
        case MemoryUsage::Stream: return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        case MemoryUsage::Readback: return VK_MEMORY_PROPERTY_HOST_CACHED_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    }
    return 0;
}

// Flags a usage would rather not have (scored after the preferred ones).
VkMemoryPropertyFlags avoidedFlags(MemoryUsage usage) {
    switch (usage) {
        case MemoryUsage::Upload: return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;  // leave resizable BAR to Stream
        default: return 0;
    }
}

}  // namespace

MemoryAllocator::MemoryAllocator(VkPhysicalDevice physicalDevice, VkDevice device, uint32_t typeMask, VkDeviceSize blockSize)
    : mPhysicalDevice(physicalDevice), mDevice(device), mTypeMask(typeMask), mBlockSize(blockSize) {
    vkGetPhysicalDeviceMemoryProperties(mPhysicalDevice, &mProperties);
}

MemoryAllocator::~MemoryAllocator() {
    for (auto& block : mBlocks)
        if (block) vkFreeMemory(mDevice, block->memory, nullptr);
}

uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& properties, uint32_t typeBits, uint32_t typeMask,
                          MemoryUsage usage) {
    const VkMemoryPropertyFlags required = requiredFlags(usage);
    const VkMemoryPropertyFlags preferred = preferredFlags(usage);
    const VkMemoryPropertyFlags avoided = avoidedFlags(usage);
    uint32_t best = ~0u;
    int bestScore = -1;
    for (uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
        if (!(typeBits & typeMask & (1u << i))) continue;
        const VkMemoryPropertyFlags flags = properties.memoryTypes[i].propertyFlags;
        if ((flags & required) != required) continue;
        // Lazily allocated memory only when nothing else is allowed (the transient pool restricts
        // transient attachments to it).
        const bool lazy = flags & VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT;
        const int score = 4 * __builtin_popcount(flags & preferred) + 2 * !(flags & avoided) + !lazy;
        if (score > bestScore) best = i, bestScore = score;
    }
    return best;
}

std::string heapBudgetRefusal(VkDeviceSize usage, VkDeviceSize budget, VkDeviceSize size) {
    if (budget == 0 || usage + size <= budget) return {};
    return "the memory heap's budget of " + formatBytes(budget) + " would be passed (" + formatBytes(usage) +
           " in use by this process, VK_EXT_memory_budget)";
}

std::vector<std::pair<VkDeviceSize, VkDeviceSize>> MemoryAllocator::heapBudgets() const {
    std::vector<std::pair<VkDeviceSize, VkDeviceSize>> out;
    if (!mHeapBudgets) return out;
    VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT};
    VkPhysicalDeviceMemoryProperties2 properties{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2,
                                                 .pNext = &budget};
    vkGetPhysicalDeviceMemoryProperties2(mPhysicalDevice, &properties);
    for (uint32_t i = 0; i < properties.memoryProperties.memoryHeapCount; ++i)
        out.emplace_back(budget.heapUsage[i], budget.heapBudget[i]);
    return out;
}

uint32_t MemoryAllocator::findMemoryType(uint32_t typeBits, MemoryUsage usage) const {
    const uint32_t best = chooseMemoryType(mProperties, typeBits, mTypeMask, usage);
    if (best == ~0u) throw std::runtime_error("no Vulkan memory type fits the resource's requirements");
    return best;
}

VkDeviceMemory MemoryAllocator::allocateDeviceMemory(VkDeviceSize size, uint32_t memoryType, std::byte** mapped) {
    const VkMemoryAllocateInfo info{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = size, .memoryTypeIndex = memoryType};
    if (mHeapBudgets) {
        const auto budgets = heapBudgets();
        const uint32_t heap = mProperties.memoryTypes[memoryType].heapIndex;
        if (heap < budgets.size())
            if (const std::string refusal = heapBudgetRefusal(budgets[heap].first, budgets[heap].second, size); !refusal.empty())
                throw OutOfDeviceMemory("vkAllocateMemory of " + formatBytes(size) + ": " + refusal);
    }
    if (mBudget > 0 && mStats.deviceMemoryBytes + size > mBudget)
        throw OutOfDeviceMemory("the device-memory budget of " + formatBytes(mBudget) + " is exhausted (" +
                                formatBytes(mStats.deviceMemoryBytes) + " in use, " + formatBytes(size) + " more asked)");
    VkDeviceMemory memory = VK_NULL_HANDLE;
    const VkResult allocated = vkAllocateMemory(mDevice, &info, nullptr, &memory);
    if (allocated == VK_ERROR_OUT_OF_DEVICE_MEMORY || allocated == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw OutOfDeviceMemory(std::string("vkAllocateMemory of ") + formatBytes(size) + ": " + vkResultName(allocated) +
                                " (" + formatBytes(mStats.deviceMemoryBytes) + " already in use)");
    VK_CHECK(allocated);
    *mapped = nullptr;
    if (mProperties.memoryTypes[memoryType].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
        void* pointer = nullptr;
        const VkResult result = vkMapMemory(mDevice, memory, 0, VK_WHOLE_SIZE, 0, &pointer);
        if (result != VK_SUCCESS) {
            vkFreeMemory(mDevice, memory, nullptr);
            VK_CHECK(result);
        }
        *mapped = static_cast<std::byte*>(pointer);
        if (mHugePages) adviseHugePages(pointer, size);
    }
    mStats.deviceMemoryBytes += size;
    ++mStats.deviceMemoryObjects;
    return memory;
}

bool MemoryAllocator::tryAllocateFromBlock(Block& block, const VkMemoryRequirements& requirements, Allocation& out) {
    for (auto it = block.freeRanges.begin(); it != block.freeRanges.end(); ++it) {
        const VkDeviceSize rangeStart = it->first, rangeSize = it->second;
        const VkDeviceSize start = alignUp(rangeStart, requirements.alignment);
        if (start + requirements.size > rangeStart + rangeSize) continue;
        // Split the free range into the part before (alignment padding) and the part after.
        const VkDeviceSize end = start + requirements.size, rangeEnd = rangeStart + rangeSize;
        block.freeRanges.erase(it);
        if (start > rangeStart) block.freeRanges[rangeStart] = start - rangeStart;
        if (rangeEnd > end) block.freeRanges[end] = rangeEnd - end;
        out.memory = block.memory;
        out.offset = start;
        out.size = requirements.size;
        out.mapped = block.mapped ? block.mapped + start : nullptr;
        out.memoryType = block.memoryType;
        ++block.liveAllocations;
        return true;
    }
    return false;
}

Allocation MemoryAllocator::allocate(const VkMemoryRequirements& requirements, MemoryUsage usage, ResourceTiling tiling) {
    const uint32_t type = findMemoryType(requirements.memoryTypeBits, usage);
    Allocation out;
    out.coherent = (mProperties.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;

    // Under a budget, blocks are an eighth of it (at least 1 MiB) so that one block cannot take it all.
    const VkDeviceSize blockSize =
        mBudget > 0 ? std::clamp<VkDeviceSize>(alignUp(mBudget / 8, VkDeviceSize(1) << 20), VkDeviceSize(1) << 20, mBlockSize)
                    : mBlockSize;
    if (requirements.size > blockSize / 2) {
        out.memory = allocateDeviceMemory(requirements.size, type, &out.mapped);
        out.size = requirements.size;
        out.memoryType = type;
    } else {
        bool placed = false;
        for (uint32_t i = 0; i < mBlocks.size() && !placed; ++i) {
            Block* block = mBlocks[i].get();
            if (!block || block->memoryType != type || block->tiling != tiling) continue;
            if (tryAllocateFromBlock(*block, requirements, out)) out.block = i, placed = true;
        }
        if (!placed) {
            auto block = std::make_unique<Block>();
            try {
                block->memory = allocateDeviceMemory(blockSize, type, &block->mapped);
            } catch (const OutOfDeviceMemory&) {
                // No room for a whole block: the request alone may still fit.
                out.memory = allocateDeviceMemory(requirements.size, type, &out.mapped);
                out.size = requirements.size;
                out.memoryType = type;
                mStats.allocatedBytes += out.size;
                ++mStats.liveAllocations;
                return out;
            }
            block->size = blockSize;
            block->memoryType = type;
            block->tiling = tiling;
            block->freeRanges[0] = blockSize;
            tryAllocateFromBlock(*block, requirements, out);
            uint32_t index = 0;
            while (index < mBlocks.size() && mBlocks[index]) ++index;
            if (index == mBlocks.size()) mBlocks.emplace_back();
            mBlocks[index] = std::move(block);
            out.block = index;
        }
    }
    mStats.allocatedBytes += out.size;
    ++mStats.liveAllocations;
    return out;
}

void MemoryAllocator::free(const Allocation& allocation) {
    if (!allocation) return;
    mStats.allocatedBytes -= allocation.size;
    --mStats.liveAllocations;
    if (allocation.block == ~0u) {
        vkFreeMemory(mDevice, allocation.memory, nullptr);
        mStats.deviceMemoryBytes -= allocation.size;
        --mStats.deviceMemoryObjects;
        return;
    }
    Block& block = *mBlocks.at(allocation.block);
    --block.liveAllocations;
    VkDeviceSize start = allocation.offset, size = allocation.size;
    // Coalesce with the free neighbours on both sides.
    auto next = block.freeRanges.lower_bound(start);
    if (next != block.freeRanges.end() && next->first == start + size) {
        size += next->second;
        next = block.freeRanges.erase(next);
    }
    if (next != block.freeRanges.begin()) {
        auto prev = std::prev(next);
        if (prev->first + prev->second == start) {
            start = prev->first;
            size += prev->second;
            block.freeRanges.erase(prev);
        }
    }
    block.freeRanges[start] = size;
}

void MemoryAllocator::trim() {
    for (auto& block : mBlocks) {
        if (!block || block->liveAllocations != 0) continue;
        vkFreeMemory(mDevice, block->memory, nullptr);
        mStats.deviceMemoryBytes -= block->size;
        --mStats.deviceMemoryObjects;
        block.reset();
    }
}

MemoryStats MemoryAllocator::stats() const { return mStats; }

}  // namespace candela::vk
