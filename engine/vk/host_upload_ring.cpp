#include "vk/host_upload_ring.h"

#include <cstring>

namespace candela::vk {

HostUploadRing::HostUploadRing(Context& context, uint32_t slots) : mContext(context), mBuffers(slots) {}

VkBuffer HostUploadRing::write(uint32_t slot, size_t index, std::span<const std::byte> bytes, VkDeviceSize size,
                               const char* name) {
    std::vector<Buffer>& buffers = mBuffers[slot];
    if (buffers.size() <= index) buffers.resize(index + 1);
    Buffer& buffer = buffers[index];
    if (!buffer || buffer.size() < bytes.size())
        buffer = Buffer(mContext, {.size = size, .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, .memory = MemoryUsage::Stream, .name = name});
    if (!bytes.empty()) std::memcpy(buffer.mapped(), bytes.data(), bytes.size());
    buffer.flush();
    return buffer.handle();
}

}  // namespace candela::vk
