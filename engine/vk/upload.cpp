#include "vk/upload.h"

#include "core/errors.h"
#include "vk/commands.h"
#include "vk/context.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace candela::vk {

Uploader::Uploader(Context& context, VkDeviceSize chunkBytes)
    : mContext(&context),
      mChunkBytes(std::min({chunkBytes ? chunkBytes : kDefaultChunkBytes, context.caps().limits.maxBufferSize,
                            context.caps().limits.maxMemoryAllocationSize})) {}

Uploader::~Uploader() = default;

Uploader::Staged Uploader::reserve(VkDeviceSize bytes) {
    for (;;) {
        // 16-byte alignment satisfies every texel size's copy offset rule.
        for (; mFill < mStaging.size(); ++mFill, mUsed = 0) {
            const VkDeviceSize offset = (mUsed + 15) & ~VkDeviceSize(15);
            if (offset + bytes > mStaging[mFill].size()) continue;
            mUsed = offset + bytes;
            return {mStaging[mFill].handle(), offset, mStaging[mFill].mapped() + offset};
        }
        // None has room: a new one, twice the last (the first small), at least the request, within
        // the bound; else submit what is queued and fill the same ones again.
        const VkDeviceSize size = std::max(bytes, mStaging.empty() ? kFirstStagingBytes : 2 * mStaging.back().size());
        if (mStagingBytes + size <= mChunkBytes || mStaging.empty()) {
            mStaging.emplace_back(*mContext, BufferDesc{.size = std::min(size, std::max(mChunkBytes - mStagingBytes, bytes)),
                                                        .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                                        .memory = MemoryUsage::Upload,
                                                        .name = "upload staging"});
            mStagingBytes += mStaging.back().size();
            continue;
        }
        const bool anyFits = std::any_of(mStaging.begin(), mStaging.end(), [&](const Buffer& b) { return b.size() >= bytes; });
        flush(false);
        if (!anyFits) {
            // The buffers made so far are all smaller than the piece: make room for a larger one.
            mStaging.clear();  // their memory returns at the next collection
            mStagingBytes = 0;
        }
    }
}

void Uploader::buffer(const Buffer& dst, std::span<const std::byte> data, VkDeviceSize offset) {
    for (VkDeviceSize done = 0; done < data.size();) {
        const VkDeviceSize bytes = std::min<VkDeviceSize>(data.size() - done, maxPiece());
        const Staged at = reserve(bytes);
        std::memcpy(at.mapped, data.data() + done, bytes);
        mBufferCopies.push_back({at.buffer, dst.handle(), offset + done, at.offset, bytes, bufferReaders(dst.usage())});
        done += bytes;
    }
}

void Uploader::image(const Image& dst, std::span<const std::byte> data, uint32_t mip, uint32_t layer,
                     VkImageLayout finalLayout, bool generateMips) {
    if (data.empty()) throw InternalError("Uploader: no texels for an image");
    const ImageDesc& d = dst.desc();
    const VkExtent3D extent{std::max(1u, d.width >> mip), std::max(1u, d.height >> mip), std::max(1u, d.depth >> mip)};
    if (d.hostWritten) throw InternalError("Uploader: image '" + std::string(d.name ? d.name : "unnamed") + "' is host-written");
    mImages.push_back({dst.handle(), dst.aspect(), finalLayout, imageReaders(d.usage, finalLayout), generateMips, false, mip,
                       layer, d.mipLevels, {d.width, d.height, d.depth}});
    // Whole rows per piece: as many as fit the chunk.
    const uint64_t rows = uint64_t(extent.height) * extent.depth;
    const VkDeviceSize rowBytes = data.size() / rows;
    if (rowBytes * rows != data.size())
        throw InternalError("Uploader: " + std::to_string(data.size()) + " bytes are not whole rows of the image");
    if (rowBytes > maxPiece())
        throw InternalError("Uploader: an image row of " + formatBytes(rowBytes) + " exceeds the staging piece of " +
                            formatBytes(maxPiece()));
    const uint32_t rowsPerPiece = static_cast<uint32_t>(std::min<VkDeviceSize>(maxPiece() / rowBytes, extent.height));
    for (uint32_t z = 0; z < extent.depth; ++z)
        for (uint32_t y = 0; y < extent.height;) {
            const uint32_t count = std::min(rowsPerPiece, extent.height - y);
            const Staged at = reserve(rowBytes * count);
            std::memcpy(at.mapped, data.data() + (VkDeviceSize(z) * extent.height + y) * rowBytes, rowBytes * count);
            mImageCopies.push_back({at.buffer, dst.handle(), dst.aspect(), {0, int32_t(y), int32_t(z)},
                                    {extent.width, count, 1}, mip, layer, at.offset});
            y += count;
        }
}

void Uploader::hostWritten(const Image& dst, VkImageLayout finalLayout) {
    const ImageDesc& d = dst.desc();
    if (!d.hostWritten) throw InternalError("Uploader: image '" + std::string(d.name ? d.name : "unnamed") + "' is not host-written");
    mImages.push_back({dst.handle(), dst.aspect(), finalLayout, imageReaders(d.usage, finalLayout), false, true, 0, 0,
                       d.mipLevels, {d.width, d.height, d.depth}});
}

void Uploader::flush(bool finish) {
    if (mBufferCopies.empty() && mImageCopies.empty() && !finish) return;
    for (Buffer& staging : mStaging) staging.flush();
    OneShotCommands commands(*mContext);
    VkCommandBuffer cmd = commands.begin();
    for (const BufferCopy& c : mBufferCopies) {
        const VkBufferCopy region{c.stagingOffset, c.dstOffset, c.size};
        vkCmdCopyBuffer(cmd, c.staging, c.buffer, 1, &region);
    }
    // An image is moved to TRANSFER_DST once (from UNDEFINED: its old contents are replaced), at
    // the first submit that copies into it; later submits copy into it as it is.
    for (const ImageCopy& c : mImageCopies)
        if (std::find(mInTransferDst.begin(), mInTransferDst.end(), c.image) == mInTransferDst.end()) {
            mInTransferDst.push_back(c.image);
            imageBarrier(cmd, c.image, c.aspect, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        }
    for (const ImageCopy& c : mImageCopies) {
        const VkBufferImageCopy region{.bufferOffset = c.stagingOffset,
                                       .imageSubresource = {c.aspect, c.mip, c.layer, 1},
                                       .imageOffset = c.offset,
                                       .imageExtent = c.extent};
        vkCmdCopyBufferToImage(cmd, c.staging, c.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    }
    if (finish) {
        std::vector<VkImage> done;
        for (const ImageFinish& f : mImages) {
            if (std::find(done.begin(), done.end(), f.image) != done.end()) continue;
            done.push_back(f.image);
            if (f.fromHost) {
                // Host writes before the submit are visible to it (the submit's memory domain operation).
                imageBarrier(cmd, f.image, f.aspect, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT,
                             VK_IMAGE_LAYOUT_PREINITIALIZED, f.readers.stages, f.readers.access, f.finalLayout);
                continue;
            }
            if (f.generateMips && f.mipLevels > f.mip + 1) {
                recordMipChain(cmd, f.image, f.aspect, f.baseExtent, f.mip, f.mipLevels, f.layer, f.finalLayout, f.readers);
                continue;
            }
            // Copies of earlier submits were waited for; this barrier orders the last ones.
            imageBarrier(cmd, f.image, f.aspect, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, f.readers.stages, f.readers.access, f.finalLayout);
        }
    }
    // One global barrier for the buffers copied in this submit, to every read any of them can serve.
    ReadScope bufferReads;
    for (const BufferCopy& c : mBufferCopies) {
        bufferReads.stages |= c.readers.stages;
        bufferReads.access |= c.readers.access;
    }
    if (bufferReads.stages != VK_PIPELINE_STAGE_2_NONE)
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, bufferReads.stages,
                      bufferReads.access);
    commands.submitAndWait();
    ++mSubmits;
    // The staging is free again (the copies completed): filled again from the first buffer.
    mFill = 0;
    mUsed = 0;
    mBufferCopies.clear();
    mImageCopies.clear();
}

void Uploader::submitAndWait() {
    if (mImages.empty() && mBufferCopies.empty()) return;
    flush(true);
    mImages.clear();
    mInTransferDst.clear();
    mStaging.clear();
    mStagingBytes = 0;
}

}  // namespace candela::vk
