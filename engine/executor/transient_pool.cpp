#include "executor/transient_pool.h"

#include "vk/check.h"
#include "vk/context.h"

#include <sstream>

namespace candela::graph {
namespace {

template <class Fn>
void forEachAccess(const GraphDecl& decl, uint32_t resource, Fn&& fn) {
    for (const PassDecl& pass : decl.passes) {
        for (const AccessDecl& a : pass.reads)
            if (a.resource == resource) fn(a.usage);
        for (const AccessDecl& a : pass.writes)
            if (a.resource == resource) fn(a.usage);
    }
}

vk::ImageDesc imageDescOf(const GraphDecl& decl, uint32_t resource, bool transientAttachment) {
    const ResourceDecl& r = decl.resources[resource];
    return {.width = r.texture.width,
            .height = r.texture.height,
            .depth = r.texture.depth,
            .mipLevels = r.texture.mipLevels,
            .arrayLayers = r.texture.arrayLayers,
            .format = r.texture.format,
            .usage = imageUsageOf(decl, resource, transientAttachment),
            .cube = r.texture.cube,
            .name = r.name.c_str(),
            .samples = r.texture.samples};
}

}  // namespace

VkImageUsageFlags imageUsageOf(const GraphDecl& decl, uint32_t resource, bool transientAttachment) {
    VkImageUsageFlags flags = 0;
    forEachAccess(decl, resource, [&](Usage usage) {
        switch (usage) {
            case Usage::Sampled: flags |= VK_IMAGE_USAGE_SAMPLED_BIT; break;
            case Usage::StorageRead:
            case Usage::StorageWrite:
            case Usage::StorageReadWrite: flags |= VK_IMAGE_USAGE_STORAGE_BIT; break;
            case Usage::ColorAttachment:
            case Usage::ResolveAttachment: flags |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT; break;
            case Usage::DepthAttachment:
            case Usage::DepthRead: flags |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT; break;
            case Usage::TransferSrc: flags |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT; break;
            case Usage::TransferDst: flags |= VK_IMAGE_USAGE_TRANSFER_DST_BIT; break;
            default: break;
        }
    });
    // Its contents never leave the one render pass using it (CompiledGraph::transientAttachments):
    // its memory may be lazily allocated (on tile-based GPUs it then takes no memory at all). The
    // graph made sure every declared use is an attachment use, as TRANSIENT_ATTACHMENT requires.
    constexpr VkImageUsageFlags kAttachments =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    if (transientAttachment && flags != 0 && (flags & ~kAttachments) == 0) flags |= VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    return flags;
}

VkBufferUsageFlags bufferUsageOf(const GraphDecl& decl, uint32_t resource) {
    VkBufferUsageFlags flags = 0;
    forEachAccess(decl, resource, [&](Usage usage) {
        switch (usage) {
            case Usage::StorageRead:
            case Usage::StorageWrite:
            case Usage::StorageReadWrite: flags |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; break;
            case Usage::TransferSrc: flags |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT; break;
            case Usage::TransferDst: flags |= VK_BUFFER_USAGE_TRANSFER_DST_BIT; break;
            case Usage::Uniform: flags |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT; break;
            case Usage::Vertex: flags |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT; break;
            case Usage::Index: flags |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT; break;
            case Usage::Indirect: flags |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT; break;
            default: break;
        }
    });
    return flags;
}

MemoryRequirementsFn deviceMemoryRequirements(vk::Context& context, const GraphDecl& decl) {
    return [&context, &decl](uint32_t resource, const ResourceDecl& r, bool transientAttachment) {
        VkMemoryRequirements2 requirements{.sType = VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
        if (r.kind == ResourceKind::Texture) {
            const VkImageCreateInfo info = vk::imageCreateInfo(imageDescOf(decl, resource, transientAttachment));
            const VkDeviceImageMemoryRequirements query{.sType = VK_STRUCTURE_TYPE_DEVICE_IMAGE_MEMORY_REQUIREMENTS,
                                                        .pCreateInfo = &info};
            vkGetDeviceImageMemoryRequirements(context.device(), &query, &requirements);
        } else {
            const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                          .size = r.buffer.size,
                                          .usage = bufferUsageOf(decl, resource),
                                          .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
            const VkDeviceBufferMemoryRequirements query{.sType = VK_STRUCTURE_TYPE_DEVICE_BUFFER_MEMORY_REQUIREMENTS,
                                                         .pCreateInfo = &info};
            vkGetDeviceBufferMemoryRequirements(context.device(), &query, &requirements);
        }
        // Transients always live in device-local memory: restrict the types accordingly; transient
        // attachments to lazily allocated memory where the device has it (tile-based GPUs).
        const uint32_t typeBits = requirements.memoryRequirements.memoryTypeBits;
        const VkPhysicalDeviceMemoryProperties& props = context.allocator().properties();
        // Only the types the allocator may use (a device profile may hide lazily allocated ones).
        const uint32_t usable = typeBits & context.allocator().typeMask();
        const auto typesWith = [&](VkMemoryPropertyFlags wanted) {
            uint32_t bits = 0;
            for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
                if ((usable & (1u << i)) && (props.memoryTypes[i].propertyFlags & wanted) == wanted) bits |= 1u << i;
            return bits;
        };
        uint32_t types = typesWith(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        if (r.kind == ResourceKind::Texture &&
            (imageUsageOf(decl, resource, transientAttachment) & VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT))
            if (const uint32_t lazy = typesWith(VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT)) types = lazy;
        return MemoryRequirement{requirements.memoryRequirements.size, requirements.memoryRequirements.alignment,
                                 types ? types : usable};
    };
}

void TransientPool::realize(const GraphDecl& decl, const CompiledGraph& compiled) {
    std::ostringstream signature;
    for (uint32_t r = 0; r < decl.resources.size(); ++r) {
        const Placement& p = compiled.placements[r];
        if (p.heap == kInvalidIndex) continue;
        const ResourceDecl& d = decl.resources[r];
        signature << r << ':' << static_cast<int>(d.kind) << ':' << d.texture.width << 'x' << d.texture.height << 'x'
                  << d.texture.depth << ':' << d.texture.mipLevels << ':' << d.texture.arrayLayers << ':'
                  << d.texture.format << ':' << d.texture.cube << ':' << d.texture.samples << ':' << d.buffer.size << ':'
                  << (d.kind == ResourceKind::Texture ? imageUsageOf(decl, r, compiled.transientAttachments[r])
                                                      : bufferUsageOf(decl, r))
                  << '@'
                  << p.heap << '+' << p.offset << ';';
    }
    for (const Heap& h : compiled.heaps) signature << 'H' << static_cast<int>(h.kind) << ':' << h.size << ':' << h.memoryTypeBits << ';';
    if (signature.str() == mSignature && mImages.size() == decl.resources.size()) return;

    release();
    ++mRebuilds;
    mSignature = signature.str();
    mImages.resize(decl.resources.size());
    mMipViews.resize(decl.resources.size());
    mBuffers.resize(decl.resources.size());
    for (const Heap& heap : compiled.heaps) {
        const VkMemoryRequirements requirements{heap.size, heap.alignment, heap.memoryTypeBits};
        try {
            mHeaps.push_back(mContext->allocator().allocate(
                requirements, vk::MemoryUsage::GpuOnly,
                heap.kind == ResourceKind::Texture ? vk::ResourceTiling::Optimal : vk::ResourceTiling::Linear));
        } catch (const vk::OutOfDeviceMemory& e) {
            // Name what the heap was for: the transients placed in it.
            std::string residents;
            for (uint32_t r = 0; r < decl.resources.size(); ++r)
                if (compiled.placements[r].heap == mHeaps.size())
                    residents += (residents.empty() ? "" : ", ") + decl.resources[r].name;
            release();
            throw vk::OutOfDeviceMemory("cannot allocate the render graph's transient heap of " + formatBytes(heap.size) +
                                    " (for " + residents + "): " + e.what());
        }
    }
    for (uint32_t r = 0; r < decl.resources.size(); ++r) {
        const Placement& p = compiled.placements[r];
        if (p.heap == kInvalidIndex) continue;
        const vk::Allocation& heap = mHeaps[p.heap];
        const vk::ExternalMemory memory{heap.memory, heap.offset + p.offset, p.size, heap.memoryType};
        const ResourceDecl& d = decl.resources[r];
        if (d.kind == ResourceKind::Texture) {
            mImages[r] = vk::Image(*mContext, imageDescOf(decl, r, compiled.transientAttachments[r]), memory);
            // Per-mip views serve storage writes of one mip at a time (PassContext::mipView).
            if ((mImages[r].desc().usage & VK_IMAGE_USAGE_STORAGE_BIT) && d.texture.depth == 1)
                mMipViews[r] = mImages[r].createMipViews();
        } else
            mBuffers[r] = vk::Buffer(*mContext, {.size = d.buffer.size, .usage = bufferUsageOf(decl, r), .name = d.name.c_str()},
                                     memory);
    }
}

VkDeviceSize TransientPool::heapBytes() const {
    VkDeviceSize total = 0;
    for (const vk::Allocation& a : mHeaps) total += a.size;
    return total;
}

VkImageView TransientPool::mipView(uint32_t resource, uint32_t mip) const {
    const std::vector<vk::ImageView>& views = mMipViews.at(resource);
    return mip < views.size() ? views[mip].get() : VK_NULL_HANDLE;
}

void TransientPool::release() {
    mMipViews.clear();
    mImages.clear();
    mBuffers.clear();
    vk::Context* context = mContext;
    for (const vk::Allocation& allocation : mHeaps)
        context->defer([context, allocation] { context->allocator().free(allocation); });
    mHeaps.clear();
    mSignature.clear();
}

}  // namespace candela::graph
