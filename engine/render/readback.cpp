#include "render/readback.h"

#include "passes/post/readback_pass.h"
#include "vk/swapchain_choices.h"

#include <glm/gtc/packing.hpp>

#include <cstring>
#include <stdexcept>
#include <utility>

namespace candela {

graph::BufferId Readback::import(Frame& frame, VkDeviceSize bytes, std::string name) {
    if (!mBuffer || mBuffer.size() != bytes)
        mBuffer = vk::Buffer(mContext, {.size = bytes,
                                        .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        .memory = vk::MemoryUsage::Readback,
                                        .name = name.c_str()});
    const graph::BufferId readback =
        frame.graph->importBuffer(std::move(name), {.size = bytes}, graph::ResourceState{}, passes::hostReadState());
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

std::vector<ReadbackSource> Readback::addOutputs(Frame& frame, options::PixelOutputs outputs, size_t texels) {
    std::vector<ReadbackSource> sources;
    std::vector<graph::TextureId> images;
    std::vector<VkDeviceSize> bytes;
    for (const auto& [target, image] : frame.aov->images(outputs.has(options::PixelOutput::ClipDepth))) {
        const VkFormat format = frame.graph->declaration().resources[image.index].texture.format;
        sources.push_back({target, format});
        images.push_back(image);
        bytes.push_back(VkDeviceSize(texels) * graph::formatTexelSize(format));
    }
    passes::addReadbackPass(*frame.graph, "readback_outputs", images, import(frame, passes::packedOffsets(bytes).back(), "readback_outputs"));
    return sources;
}

std::vector<CapturedOutput> Readback::outputs(options::PixelOutputs outputs, std::span<const ReadbackSource> sources, size_t texels) {
    mBuffer.invalidate();
    std::vector<VkDeviceSize> bytes;
    for (const ReadbackSource& source : sources) bytes.push_back(VkDeviceSize(texels) * graph::formatTexelSize(source.format));
    const std::vector<VkDeviceSize> offsets = passes::packedOffsets(bytes);
    const auto* base = static_cast<const std::byte*>(mBuffer.mapped());
    std::vector<CapturedOutput> out;
    for (const auto& [output, name] : options::kPixelOutputNames) {
        if (output == options::PixelOutput::Color || !outputs.has(output)) continue;
        const options::PixelOutputLayout layout = options::pixelOutputLayout(output);
        size_t s = 0;
        while (s < sources.size() && sources[s].target != layout.target) ++s;
        if (s == sources.size()) throw std::logic_error(std::string("Readback: no image holds output ") + name);
        const VkFormat format = sources[s].format;
        const uint32_t texelSize = graph::formatTexelSize(format);
        const bool half = format == VK_FORMAT_R16G16B16A16_SFLOAT || format == VK_FORMAT_R16G16_SFLOAT;
        const std::byte* texel = base + offsets[s];
        CapturedOutput captured{.output = output, .channels = layout.channels};
        (layout.integer ? captured.ids.resize(texels * layout.channels) : captured.floats.resize(texels * layout.channels));
        for (size_t i = 0; i < texels; ++i, texel += texelSize)
            for (uint32_t c = 0; c < layout.channels; ++c) {
                const size_t at = i * layout.channels + c, channel = layout.firstChannel + c;
                if (half) {
                    uint16_t h;
                    std::memcpy(&h, texel + 2 * channel, 2);
                    captured.floats[at] = glm::unpackHalf1x16(h);
                } else if (layout.integer) {
                    std::memcpy(&captured.ids[at], texel + 4 * channel, 4);
                } else {
                    std::memcpy(&captured.floats[at], texel + 4 * channel, 4);
                }
            }
        out.push_back(std::move(captured));
    }
    return out;
}

}  // namespace candela
