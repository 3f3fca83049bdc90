#include "vk/upload.h"

#include "core/errors.h"
#include "vk/commands.h"

#include <algorithm>
#include <cstring>

namespace candela::vk {

VkDeviceSize Uploader::stage(std::span<const std::byte> data) {
    // 16-byte alignment satisfies every texel size's copy offset rule.
    const VkDeviceSize offset = (mStaging.size() + 15) & ~VkDeviceSize(15);
    mStaging.resize(offset + data.size());
    std::memcpy(mStaging.data() + offset, data.data(), data.size());
    return offset;
}

void Uploader::buffer(const Buffer& dst, std::span<const std::byte> data, VkDeviceSize offset) {
    if (data.empty()) return;
    mBufferCopies.push_back({dst.handle(), offset, stage(data), data.size(), bufferReaders(dst.usage())});
}

void Uploader::image(const Image& dst, std::span<const std::byte> data, uint32_t mip, uint32_t layer,
                     VkImageLayout finalLayout, bool generateMips) {
    const ImageDesc& d = dst.desc();
    const VkExtent3D extent{std::max(1u, d.width >> mip), std::max(1u, d.height >> mip), std::max(1u, d.depth >> mip)};
    mImageCopies.push_back({dst.handle(), dst.aspect(), extent, mip, layer, stage(data), finalLayout,
                            imageReaders(d.usage, finalLayout), generateMips, d.mipLevels, {d.width, d.height, d.depth}});
}

void Uploader::submitAndWait() {
    if (mStaging.empty()) return;
    Buffer staging(*mContext, {.size = mStaging.size(),
                               .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               .memory = MemoryUsage::Upload,
                               .name = "upload staging"});
    std::memcpy(staging.mapped(), mStaging.data(), mStaging.size());
    staging.flush();

    OneShotCommands commands(*mContext);
    VkCommandBuffer cmd = commands.begin();
    for (const BufferCopy& c : mBufferCopies) {
        const VkBufferCopy region{c.stagingOffset, c.dstOffset, c.size};
        vkCmdCopyBuffer(cmd, staging.handle(), c.buffer, 1, &region);
    }
    std::vector<VkImage> images;
    for (const ImageCopy& c : mImageCopies)
        if (std::find(images.begin(), images.end(), c.image) == images.end()) {
            images.push_back(c.image);
            imageBarrier(cmd, c.image, c.aspect, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        }
    for (const ImageCopy& c : mImageCopies) {
        const VkBufferImageCopy region{.bufferOffset = c.stagingOffset,
                                       .imageSubresource = {c.aspect, c.mip, c.layer, 1},
                                       .imageExtent = c.extent};
        vkCmdCopyBufferToImage(cmd, staging.handle(), c.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    }
    for (VkImage image : images) {
        const ImageCopy& c = *std::find_if(mImageCopies.begin(), mImageCopies.end(),
                                           [&](const ImageCopy& x) { return x.image == image; });
        if (c.generateMips && c.mipLevels > c.mip + 1) {
            recordMipChain(cmd, c.image, c.aspect, c.baseExtent, c.mip, c.mipLevels, c.layer, c.finalLayout,
                           c.readers);
            continue;
        }
        imageBarrier(cmd, image, c.aspect, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, c.readers.stages, c.readers.access, c.finalLayout);
    }
    // One global barrier for the buffers, to every read any of them can serve.
    ReadScope bufferReads;
    for (const BufferCopy& c : mBufferCopies) {
        bufferReads.stages |= c.readers.stages;
        bufferReads.access |= c.readers.access;
    }
    if (bufferReads.stages != VK_PIPELINE_STAGE_2_NONE)
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, bufferReads.stages,
                      bufferReads.access);
    commands.submitAndWait();
    mStaging.clear();
    mBufferCopies.clear();
    mImageCopies.clear();
}

}  // namespace candela::vk
