#pragma once
// Uploader: copies host data into device-local buffers and images through staging buffers, in one
// batch (one command buffer, one submit, one wait).

#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/image.h"

#include <cstddef>
#include <span>
#include <vector>

namespace candela::vk {

class Uploader {
public:
    explicit Uploader(Context& context) : mContext(&context) {}

    // Queues a copy of `data` into `dst` at `offset`. dst needs VK_BUFFER_USAGE_TRANSFER_DST_BIT.
    // After submit the data is visible to every read dst's usage allows (vk::bufferReaders).
    void buffer(const Buffer& dst, std::span<const std::byte> data, VkDeviceSize offset = 0);
    // Queues tightly packed texels for mip `mip`, layer `layer` of `dst` (TRANSFER_DST usage).
    // With `generateMips`, mips 1.. are then filtered down from `mip` by linear blits (dst needs
    // TRANSFER_SRC usage and a format that supports linear blits). After submit the whole image
    // is in `finalLayout`, visible to the reads its usage allows there (vk::imageReaders).
    void image(const Image& dst, std::span<const std::byte> data, uint32_t mip, uint32_t layer, VkImageLayout finalLayout,
               bool generateMips = false);

    // Records and submits all queued copies and waits for them. Staging memory is released.
    void submitAndWait();

private:
    struct ImageCopy {
        VkImage image;
        VkImageAspectFlags aspect;
        VkExtent3D extent;
        uint32_t mip, layer;
        VkDeviceSize stagingOffset;
        VkImageLayout finalLayout;
        ReadScope readers;
        bool generateMips;
        uint32_t mipLevels;
        VkExtent3D baseExtent;
    };
    struct BufferCopy {
        VkBuffer buffer;
        VkDeviceSize dstOffset, stagingOffset, size;
        ReadScope readers;
    };
    VkDeviceSize stage(std::span<const std::byte> data);

    Context* mContext;
    std::vector<std::byte> mStaging;
    std::vector<BufferCopy> mBufferCopies;
    std::vector<ImageCopy> mImageCopies;
};

}  // namespace candela::vk
