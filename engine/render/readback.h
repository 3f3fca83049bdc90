#pragma once
// Readback: the host-visible buffer a frame's readback pass copies its result into, and the
// conversions from what the GPU wrote to what a capture returns (half floats to floats, swapchain
// texels to RGBA8).

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
    // After the frame completed: the buffer's first `texels` texels, written in `format` (RGBA8, or
    // a swapchain format: vk::kPresentFormats), as RGBA8 (vk::presentTexelsToRgba8).
    std::vector<uint8_t> rgba8(size_t texels, VkFormat format);
    // After the frame completed: the buffer's first `texels` RGBA16F texels as 32-bit floats.
    std::vector<float> rgba32f(size_t texels);

private:
    vk::Context& mContext;
    vk::Buffer mBuffer;
};

}  // namespace candela
