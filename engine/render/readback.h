#pragma once
// Readback: the host-visible buffer a frame's readback pass copies its result into, and the
// conversions from what the GPU wrote to what a capture returns (half floats to floats, swapchain
// texels to RGBA8, the aov targets to each per-pixel output's channels).

#include "options/pixel_output.h"
#include "render/frame.h"
#include "vk/buffer.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace candela {

// One per-pixel output besides colour as a capture returns it: rows top first, `channels` values
// a pixel (options::pixelOutputLayout), 32-bit floats or, for IDs, 32-bit unsigned integers.
struct CapturedOutput {
    options::PixelOutput output = options::PixelOutput::Depth;
    uint32_t channels = 0;
    std::vector<float> floats;    // !pixelOutputLayout(output).integer
    std::vector<uint32_t> ids;    // pixelOutputLayout(output).integer
};

// An image a readback buffer holds: which aov target (CANDELA_AOV_*, or CANDELA_AOV_CLIP_DEPTH)
// in which format.
struct ReadbackSource {
    uint32_t target = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
};

class Readback {
public:
    // Precondition: `context` outlives the readback.
    explicit Readback(vk::Context& context) : mContext(context) {}

    // Imports the readback buffer, (re)created for `bytes`, into `frame` (final state: host read).
    graph::BufferId import(Frame& frame, VkDeviceSize bytes, std::string name = "readback");
    // After the frame completed: the buffer's first `texels` texels, written in `format` (RGBA8, or
    // a swapchain format: vk::kPresentFormats), as RGBA8 (vk::presentTexelsToRgba8).
    std::vector<uint8_t> rgba8(size_t texels, VkFormat format);
    // After the frame completed: the buffer's first `texels` RGBA16F texels as 32-bit floats.
    std::vector<float> rgba32f(size_t texels);
    // Adds "readback_outputs": the aov targets the outputs besides colour of `outputs` lie in (and
    // the clip depth), of `texels` texels each, into this buffer, one after the other. Returns what
    // the buffer will hold, for outputs(). Precondition: frame.aov is set.
    std::vector<ReadbackSource> addOutputs(Frame& frame, options::PixelOutputs outputs, size_t texels);
    // After the frame completed: each output of `outputs` but colour, out of the buffer holding
    // `sources` (images of `texels` texels, packed as passes::packedOffsets places them).
    // Precondition: the sources hold each such output's target.
    std::vector<CapturedOutput> outputs(options::PixelOutputs outputs, std::span<const ReadbackSource> sources, size_t texels);

private:
    vk::Context& mContext;
    vk::Buffer mBuffer;
};

}  // namespace candela
