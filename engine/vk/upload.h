#pragma once
// Uploader: copies host data into device-local buffers and images through staging memory of
// bounded size. Copies are written into staging buffers as they are queued (a small one first,
// each new one twice the last); when the staging would pass the bound, the queued copies are
// submitted and waited for and the same staging buffers are filled again, so no upload holds more
// staging than the bound (a 2 GiB texture set or a 16384 × 8192 environment never asks for one
// allocation of its size; Vulkan guarantees only 1 GiB per allocation and buffer). Data is copied
// in pieces of at most half the bound: buffers by byte ranges, images by rows. Host-written images
// (ImageDesc::hostWritten: on CPU devices, textures the host writes in place) need no copy: the
// Uploader only moves them to their layout with the other images (hostWritten).

#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/image.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace candela::vk {

class Uploader {
public:
    // `chunkBytes`: the bound on staging memory (0: kDefaultChunkBytes), within the device's
    // maxBufferSize and maxMemoryAllocationSize.
    explicit Uploader(Context& context, VkDeviceSize chunkBytes = 0);
    ~Uploader();
    Uploader(const Uploader&) = delete;
    Uploader& operator=(const Uploader&) = delete;

    static constexpr VkDeviceSize kDefaultChunkBytes = VkDeviceSize(64) << 20;
    static constexpr VkDeviceSize kFirstStagingBytes = VkDeviceSize(64) << 10;

    // Queues a copy of `data` into `dst` at `offset`. dst needs VK_BUFFER_USAGE_TRANSFER_DST_BIT.
    // After submit the data is visible to every read dst's usage allows (vk::bufferReaders).
    void buffer(const Buffer& dst, std::span<const std::byte> data, VkDeviceSize offset = 0);
    // Queues tightly packed texels for mip `mip`, layer `layer` of `dst` (TRANSFER_DST usage).
    // With `generateMips`, mips 1.. are then filtered down from `mip` by linear blits (dst needs
    // TRANSFER_SRC usage and a format that supports linear blits). After submit the whole image
    // is in `finalLayout`, visible to the reads its usage allows there (vk::imageReaders).
    // Precondition: one image row fits half the bound.
    void image(const Image& dst, std::span<const std::byte> data, uint32_t mip, uint32_t layer, VkImageLayout finalLayout,
               bool generateMips = false);

    // Queues the move of a hostWritten image, its texels written by the host (Image::hostTexels),
    // from PREINITIALIZED to `finalLayout`, where after submit they are visible to the reads its usage
    // allows (vk::imageReaders). Preconditions: dst.desc().hostWritten; the host writes are done; once
    // per image, while it is still PREINITIALIZED (the barrier's old layout).
    void hostWritten(const Image& dst, VkImageLayout finalLayout);

    // Records and submits all queued copies and waits for them; every image reaches its final
    // layout. The staging chunk is released.
    void submitAndWait();

    // The bound on staging memory, and how many times copies were submitted so far (tests).
    VkDeviceSize chunkBytes() const { return mChunkBytes; }
    uint32_t submits() const { return mSubmits; }

private:
    struct ImageCopy {
        VkBuffer staging;
        VkImage image;
        VkImageAspectFlags aspect;
        VkOffset3D offset;
        VkExtent3D extent;
        uint32_t mip, layer;
        VkDeviceSize stagingOffset;
    };
    struct ImageFinish {  // what an image needs once all its copies are done
        VkImage image;
        VkImageAspectFlags aspect;
        VkImageLayout finalLayout;
        ReadScope readers;
        bool generateMips;
        bool fromHost;  // a hostWritten image: from PREINITIALIZED, after host writes, without copies
        uint32_t mip, layer, mipLevels;
        VkExtent3D baseExtent;
    };
    struct BufferCopy {
        VkBuffer staging;
        VkBuffer buffer;
        VkDeviceSize dstOffset, stagingOffset, size;
        ReadScope readers;
    };
    struct Staged {
        VkBuffer buffer;
        VkDeviceSize offset;
        std::byte* mapped;  // where to write the bytes
    };
    // Room for `bytes` (16-byte aligned) in the staging, flushing the queued copies first if the
    // staging would pass the bound. Precondition: bytes ≤ maxPiece().
    Staged reserve(VkDeviceSize bytes);
    // Records, submits and waits for the queued copies; with `finish`, also every image's final
    // layout (and mips).
    void flush(bool finish);

    Context* mContext;
    VkDeviceSize mChunkBytes;
    VkDeviceSize maxPiece() const { return std::max<VkDeviceSize>(mChunkBytes / 2, 16); }
    std::vector<Buffer> mStaging;    // kept until submitAndWait: refilled after each flush
    VkDeviceSize mStagingBytes = 0;  // their total size (≤ mChunkBytes)
    size_t mFill = 0;                // the one being filled
    VkDeviceSize mUsed = 0;          // bytes of it holding queued data
    uint32_t mSubmits = 0;
    std::vector<BufferCopy> mBufferCopies;
    std::vector<ImageCopy> mImageCopies;
    std::vector<ImageFinish> mImages;   // every image queued since the last submitAndWait
    std::vector<VkImage> mInTransferDst;  // images already moved to TRANSFER_DST_OPTIMAL
};

}  // namespace candela::vk
