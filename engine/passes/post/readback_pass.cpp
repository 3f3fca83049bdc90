#include "passes/post/readback_pass.h"

#include "executor/graph_executor.h"
#include "vk/image.h"

namespace candela::passes {

using namespace graph;

ResourceState hostReadState() { return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED}; }

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
