// Step "aliasing": places every used transient in a heap so that transients alive at the same time
// never overlap in memory, while transients with disjoint lifetimes may share bytes.

#include "graph/compile_steps.h"

#include <algorithm>
#include <numeric>

namespace candela::graph {

namespace {

constexpr VkDeviceSize kDefaultAlignment = 256;
// Unknown formats are sized as the widest common one, so the estimate errs on the large side.
constexpr uint32_t kFallbackTexelSize = 16;

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

}  // namespace

MemoryRequirement estimateMemoryRequirement(const ResourceDecl& resource) {
    MemoryRequirement requirement;
    requirement.alignment = kDefaultAlignment;
    if (resource.kind == ResourceKind::Buffer) {
        requirement.size = alignUp(resource.buffer.size, kDefaultAlignment);
        return requirement;
    }
    const TextureDesc& desc = resource.texture;
    const uint32_t texelSize = formatTexelSize(desc.format);
    VkDeviceSize texels = 0;
    for (uint32_t mip = 0; mip < std::max(desc.mipLevels, 1u); ++mip) {
        texels += VkDeviceSize{std::max(desc.width >> mip, 1u)} * std::max(desc.height >> mip, 1u) *
                  std::max(desc.depth >> mip, 1u);
    }
    requirement.size = alignUp(texels * std::max(desc.arrayLayers, 1u) * std::max(desc.samples, 1u) *
                                   (texelSize != 0 ? texelSize : kFallbackTexelSize),
                               kDefaultAlignment);
    return requirement;
}

namespace detail {

namespace {

bool lifetimesOverlap(const Lifetime& a, const Lifetime& b) {
    return a.first <= b.last && b.first <= a.last;
}

bool rangesOverlap(VkDeviceSize offsetA, VkDeviceSize sizeA, VkDeviceSize offsetB, VkDeviceSize sizeB) {
    return offsetA < offsetB + sizeB && offsetB < offsetA + sizeA;
}

// Lowest offset in `heap` where `resource` overlaps no resident that is alive at the same time.
// Candidates are 0 and the aligned end of each such resident (first fit).
VkDeviceSize lowestFreeOffset(const Heap& heap, const CompiledGraph& compiled, uint32_t resource,
                              const MemoryRequirement& requirement) {
    const Lifetime& lifetime = compiled.lifetimes[resource];
    std::vector<uint32_t> rivals;
    std::vector<VkDeviceSize> candidates{0};
    for (uint32_t resident : heap.residents) {
        if (!lifetimesOverlap(lifetime, compiled.lifetimes[resident])) continue;
        rivals.push_back(resident);
        const Placement& placed = compiled.placements[resident];
        candidates.push_back(alignUp(placed.offset + placed.size, requirement.alignment));
    }
    std::sort(candidates.begin(), candidates.end());
    for (VkDeviceSize offset : candidates) {
        const bool free = std::none_of(rivals.begin(), rivals.end(), [&](uint32_t rival) {
            const Placement& placed = compiled.placements[rival];
            return rangesOverlap(offset, requirement.size, placed.offset, placed.size);
        });
        if (free) return offset;
    }
    return candidates.back();  // unreachable: past the last rival's end is always free
}

}  // namespace

void planAliasing(const GraphDecl& decl, const CompileOptions& options, CompiledGraph& compiled) {
    const size_t resourceCount = decl.resources.size();
    compiled.placements.assign(resourceCount, Placement{});
    compiled.heaps.clear();
    compiled.bytesRequested = 0;

    std::vector<uint32_t> transients;
    std::vector<MemoryRequirement> requirements(resourceCount);
    for (uint32_t r = 0; r < resourceCount; ++r) {
        const ResourceDecl& resource = decl.resources[r];
        if (resource.imported || !compiled.lifetimes[r].used()) continue;
        MemoryRequirement requirement = options.memoryRequirements
                                            ? options.memoryRequirements(r, resource, compiled.transientAttachments[r])
                                            : estimateMemoryRequirement(resource);
        requirement.alignment = std::max<VkDeviceSize>(requirement.alignment, 1);
        requirements[r] = requirement;
        compiled.bytesRequested += requirement.size;
        transients.push_back(r);
    }
    // Largest first: big resources define the heaps, smaller ones fill the gaps they leave.
    std::sort(transients.begin(), transients.end(), [&](uint32_t a, uint32_t b) {
        if (requirements[a].size != requirements[b].size) return requirements[a].size > requirements[b].size;
        if (compiled.lifetimes[a].first != compiled.lifetimes[b].first)
            return compiled.lifetimes[a].first < compiled.lifetimes[b].first;
        return a < b;
    });

    for (uint32_t r : transients) {
        const MemoryRequirement& requirement = requirements[r];
        const ResourceKind kind = decl.resources[r].kind;
        uint32_t bestHeap = kInvalidIndex;
        VkDeviceSize bestOffset = 0;
        VkDeviceSize bestGrowth = 0;
        for (uint32_t h = 0; options.aliasing && h < compiled.heaps.size(); ++h) {
            const Heap& heap = compiled.heaps[h];
            // Images and buffers never share (bufferImageGranularity); memory types must agree.
            if (heap.kind != kind || (heap.memoryTypeBits & requirement.memoryTypeBits) == 0) continue;
            const VkDeviceSize offset = lowestFreeOffset(heap, compiled, r, requirement);
            const VkDeviceSize end = offset + requirement.size;
            const VkDeviceSize growth = end > heap.size ? end - heap.size : 0;
            if (bestHeap == kInvalidIndex || growth < bestGrowth) {
                bestHeap = h;
                bestOffset = offset;
                bestGrowth = growth;
            }
        }
        if (bestHeap == kInvalidIndex) {
            Heap heap;
            heap.kind = kind;
            heap.memoryTypeBits = requirement.memoryTypeBits;
            compiled.heaps.push_back(heap);
            bestHeap = static_cast<uint32_t>(compiled.heaps.size() - 1);
        }
        Heap& heap = compiled.heaps[bestHeap];
        heap.size = std::max(heap.size, bestOffset + requirement.size);
        heap.alignment = std::max(heap.alignment, requirement.alignment);
        heap.memoryTypeBits &= requirement.memoryTypeBits;
        heap.residents.push_back(r);
        compiled.placements[r] = Placement{bestHeap, bestOffset, requirement.size};
    }

    for (Heap& heap : compiled.heaps) {
        std::sort(heap.residents.begin(), heap.residents.end(), [&](uint32_t a, uint32_t b) {
            if (compiled.lifetimes[a].first != compiled.lifetimes[b].first)
                return compiled.lifetimes[a].first < compiled.lifetimes[b].first;
            return a < b;
        });
    }
    compiled.bytesAllocated = std::accumulate(
        compiled.heaps.begin(), compiled.heaps.end(), VkDeviceSize{0},
        [](VkDeviceSize sum, const Heap& heap) { return sum + heap.size; });
    compiled.steps.emplace_back("aliasing");
}

}  // namespace detail

}  // namespace candela::graph
