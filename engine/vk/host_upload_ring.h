#pragma once
// HostUploadRing: buffers the CPU writes for one frame (an animated scene's posed draws, joint
// matrices, morph weights), one set per frame slot so that a frame in flight keeps its data while
// the next one is written. A slot's buffers are reused, grown when a frame needs more.

#include "vk/buffer.h"

#include <cstddef>
#include <span>
#include <vector>

namespace candela::vk {

class HostUploadRing {
public:
    // Precondition: `context` outlives the ring.
    HostUploadRing(Context& context, uint32_t slots);

    // Copies `bytes` into buffer `index` of `slot` (a storage buffer of at least `size` bytes,
    // created or grown as needed, named `name`), flushes it and returns it. The submit that follows
    // makes the host writes visible to the device. Preconditions: the slot's previous frame has
    // completed (FrameRing::begin waited for it); bytes.size() <= size; slot < slots.
    VkBuffer write(uint32_t slot, size_t index, std::span<const std::byte> bytes, VkDeviceSize size, const char* name);

private:
    Context& mContext;
    std::vector<std::vector<Buffer>> mBuffers;  // per slot, per upload of its frame
};

}  // namespace candela::vk
