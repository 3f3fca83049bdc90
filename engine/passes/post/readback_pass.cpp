#include "passes/post/readback_pass.h"

#include "executor/graph_executor.h"
#include "vk/image.h"

namespace candela::passes {

using namespace graph;

ResourceState hostReadState() { return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED}; }

std::vector<VkDeviceSize> packedOffsets(std::span<const VkDeviceSize> bytes) {
    std::vector<VkDeviceSize> out{0};
    for (VkDeviceSize b : bytes) out.push_back((out.back() + b + 15) / 16 * 16);
    if (!bytes.empty()) out.back() = out[out.size() - 2] + bytes.back();
    return out;
}

BufferId addReadbackPass(RenderGraph& graph, std::string name, std::span<const TextureId> sources, BufferId destination) {
    struct Data {
        std::vector<TextureId> sources;
        BufferId destination;
    };
    const Data& data = graph.addPass<Data>(
        std::move(name), PassType::Transfer,
        [&](PassBuilder& builder, Data& d) {
            for (TextureId source : sources) d.sources.push_back(builder.read(source, Usage::TransferSrc));
            d.destination = builder.write(destination, Usage::TransferDst, WriteMode::Discard);
        },
        [](const Data& d, PassContext& ctx) {
            std::vector<VkDeviceSize> bytes;
            for (TextureId source : d.sources) {
                const TextureDesc& desc = ctx.desc(source);
                bytes.push_back(VkDeviceSize(desc.width) * desc.height * formatTexelSize(desc.format));
            }
            const std::vector<VkDeviceSize> offsets = packedOffsets(bytes);
            for (size_t i = 0; i < d.sources.size(); ++i) {
                const TextureDesc& desc = ctx.desc(d.sources[i]);
                const VkBufferImageCopy region{.bufferOffset = offsets[i],
                                               .imageSubresource = {vk::aspectOf(desc.format), 0, 0, 1},
                                               .imageExtent = {desc.width, desc.height, 1}};
                vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(d.sources[i]), ctx.layout(d.sources[i]), ctx.buffer(d.destination), 1, &region);
            }
        });
    return data.destination;
}

BufferId addReadbackPass(RenderGraph& graph, TextureId source, BufferId destination) {
    struct Data {
        TextureId source;
        BufferId destination;
    };
    const Data& data = graph.addPass<Data>(
        "readback", PassType::Transfer,
        [&](PassBuilder& builder, Data& d) {
            d.source = builder.read(source, Usage::TransferSrc);
            d.destination = builder.write(destination, Usage::TransferDst, WriteMode::Discard);
        },
        [](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.source);
            const VkBufferImageCopy region{.bufferOffset = 0,
                                           .imageSubresource = {vk::aspectOf(desc.format), 0, 0, 1},
                                           .imageExtent = {desc.width, desc.height, 1}};
            vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(d.source), ctx.layout(d.source),
                                   ctx.buffer(d.destination), 1, &region);
        });
    return data.destination;
}

}  // namespace candela::passes
