#pragma once
// Readback: the host-visible buffer a frame's readback pass copies its result into, and the
// conversions from what the GPU wrote to what a capture returns (half floats to floats, BGRA
// swapchain bytes to RGBA).

#include "render/frame.h"
#include "vk/buffer.h"

#include <cstdint>
#include <vector>

namespace candela {

class Readback {
public:
    // Precondition: `context` outlives the readback.
    explicit Readback(vk::Context& context) : mContext(context) {}

    // Imports the readback buffer, (re)created for `bytes`, into `frame` (final state: host read).
    graph::BufferId import(Frame& frame, VkDeviceSize bytes);
    // After the frame completed: the buffer's first `texels` RGBA8 texels (BGRA ones swapped to RGBA).
    std::vector<uint8_t> rgba8(size_t texels, bool bgra);
    // After the frame completed: the buffer's first `texels` RGBA16F texels as 32-bit floats.
    std::vector<float> rgba32f(size_t texels);

private:
    vk::Context& mContext;
    vk::Buffer mBuffer;
};

}  // namespace candela
