#pragma once
// TransientPool: the Vulkan images, buffers and heap memory behind a compiled graph's transient
// resources, placed as the aliasing step decided. One pool per frame slot (frames in flight never
// share transient memory). Objects are reused across frames while the graph's transient set is
// unchanged, and handed to deferred deletion when it changes.

#include "graph/compiled_graph.h"
#include "vk/buffer.h"
#include "vk/image.h"

#include <string>
#include <vector>

namespace candela::graph {

// Vulkan usage flags a resource needs, from every access the declared graph makes of it; for a
// transient attachment (CompiledGraph::transientAttachments) also TRANSIENT_ATTACHMENT.
VkImageUsageFlags imageUsageOf(const GraphDecl& decl, uint32_t resource, bool transientAttachment);
VkBufferUsageFlags bufferUsageOf(const GraphDecl& decl, uint32_t resource);

// A MemoryRequirementsFn asking the device (vkGetDevice{Image,Buffer}MemoryRequirements: no
// object is created) for each transient of `decl`; a transient attachment's memory types are
// narrowed to lazily allocated ones where the device has them. `decl` must outlive the function's use.
MemoryRequirementsFn deviceMemoryRequirements(vk::Context& context, const GraphDecl& decl);

class TransientPool {
public:
    explicit TransientPool(vk::Context& context) : mContext(&context) {}
    ~TransientPool() { release(); }
    TransientPool(const TransientPool&) = delete;
    TransientPool& operator=(const TransientPool&) = delete;

    // Makes sure every used transient of `compiled` exists, bound to its placement in heap memory.
    void realize(const GraphDecl& decl, const CompiledGraph& compiled);

    VkImage image(uint32_t resource) const { return mImages.at(resource).handle(); }
    // The usage the transient image `resource` was created with.
    VkImageUsageFlags imageUsage(uint32_t resource) const { return mImages.at(resource).desc().usage; }
    VkImageView view(uint32_t resource) const { return mImages.at(resource).view(); }
    // A view of one mip, all layers (see PassContext::mipView); null if the image has no such mip or
    // no per-mip views (made for 2D transients with storage usage).
    VkImageView mipView(uint32_t resource, uint32_t mip) const;
    VkBuffer buffer(uint32_t resource) const { return mBuffers.at(resource).handle(); }

    // Heap bytes currently held, and how many times the pool was (re)built.
    VkDeviceSize heapBytes() const;
    uint32_t rebuilds() const { return mRebuilds; }

private:
    void release();

    vk::Context* mContext;
    std::string mSignature;
    std::vector<vk::Allocation> mHeaps;
    std::vector<vk::Image> mImages;    // indexed by resource; empty for non-transients
    std::vector<std::vector<vk::ImageView>> mMipViews;  // indexed by resource, then mip
    std::vector<vk::Buffer> mBuffers;  // indexed by resource
    uint32_t mRebuilds = 0;
};

}  // namespace candela::graph
