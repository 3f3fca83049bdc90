#include "render/readback.h"

#include "passes/post/readback_pass.h"
#include "vk/swapchain_choices.h"

#include <glm/gtc/packing.hpp>

#include <cstring>
#include <utility>

namespace candela {

graph::BufferId Readback::import(Frame& frame, VkDeviceSize bytes) {
    if (!mBuffer || mBuffer.size() != bytes)
        mBuffer = vk::Buffer(mContext, {.size = bytes,
                                        .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        .memory = vk::MemoryUsage::Readback,
                                        .name = "readback"});
    const graph::BufferId readback =
        frame.graph->importBuffer("readback", {.size = bytes}, graph::ResourceState{}, passes::hostReadState());
    frame.imports.bind(readback, mBuffer.handle());
    return readback;
}

std::vector<uint8_t> Readback::rgba8(size_t texels, VkFormat format) {
    mBuffer.invalidate();
    return vk::presentTexelsToRgba8(format, static_cast<const std::byte*>(mBuffer.mapped()), texels);
}

std::vector<float> Readback::rgba32f(size_t texels) {
    mBuffer.invalidate();
    std::vector<float> out(texels * 4);
    const auto* half = reinterpret_cast<const uint16_t*>(mBuffer.mapped());
    for (size_t i = 0; i < out.size(); ++i) out[i] = glm::unpackHalf1x16(half[i]);
    return out;
}

}  // namespace candela
