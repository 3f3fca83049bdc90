#pragma once
// Command recording helpers: a one-shot command buffer submitted and waited for (uploads, tests),
// and small recording utilities shared by passes.

#include "vk/handle.h"

namespace candela::vk {

// Records one command buffer on the graphics queue, submits it and waits for completion.
// Owns its pool and fence; begin() may be called again after submitAndWait().
class OneShotCommands {
public:
    explicit OneShotCommands(Context& context);
    VkCommandBuffer begin();
    // Ends the command buffer, submits it to the graphics queue and waits for it to complete.
    void submitAndWait();

private:
    Context* mContext;
    CommandPool mPool;
    Fence mFence;
    VkCommandBuffer mCmd = VK_NULL_HANDLE;
};

// Where and how a resource is read after a copy into it: the destination scope of the barrier that
// ends an upload, so each upload waits for exactly the readers it can have instead of every stage.
struct ReadScope {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
};
// The reads an image with `usage` can see in `layout`: shader sampling (vertex, fragment and
// compute shaders) in SHADER_READ_ONLY_OPTIMAL; shader sampling and storage reads in GENERAL;
// copies and blits in TRANSFER_SRC_OPTIMAL. Throws InternalError when the usage allows no read in
// that layout (or the layout is another).
ReadScope imageReaders(VkImageUsageFlags usage, VkImageLayout layout);
// The reads a buffer with `usage` can serve: vertex and index fetch, indirect arguments, uniform
// and storage reads in vertex, fragment and compute shaders, copy sources.
ReadScope bufferReaders(VkBufferUsageFlags usage);

// One pipeline barrier on a whole image (all mips and layers).
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStages,
                  VkAccessFlags2 srcAccess, VkImageLayout oldLayout, VkPipelineStageFlags2 dstStages,
                  VkAccessFlags2 dstAccess, VkImageLayout newLayout);

// One global memory barrier (no image layout change): makes `srcAccess` in `srcStages` visible to
// `dstAccess` in `dstStages`, e.g. transfer writes to host reads before a readback.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);

// Fills mips baseMip+1 .. mipLevels-1 of one layer by successive linear blits from baseMip, then
// moves mips baseMip .. mipLevels-1 of that layer to `finalLayout`, visible to `readers`.
// Precondition: those mips are in TRANSFER_DST_OPTIMAL with baseMip written by transfer; the image
// has TRANSFER_SRC|DST usage and its format supports linear blits.
void recordMipChain(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkExtent3D baseExtent,
                    uint32_t baseMip, uint32_t mipLevels, uint32_t layer, VkImageLayout finalLayout,
                    const ReadScope& readers);

// Sets viewport and scissor to the whole of `extent`.
void setViewportAndScissor(VkCommandBuffer cmd, VkExtent2D extent);

Fence createFence(Context& context, bool signaled);
Semaphore createSemaphore(Context& context);
CommandPool createCommandPool(Context& context, uint32_t family, VkCommandPoolCreateFlags flags);

}  // namespace candela::vk
