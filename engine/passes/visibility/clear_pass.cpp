#include "passes/visibility/clear_pass.h"

#include "executor/graph_executor.h"

namespace candela::passes {

using namespace graph;

TextureId addClearPass(RenderGraph& graph, std::string name, std::string texture, const TextureDesc& desc) {
    struct Data {
        TextureId texture;
    };
    const Data& data = graph.addPass<Data>(
        std::move(name), PassType::Transfer,
        [&](PassBuilder& builder, Data& d) {
            d.texture = builder.write(builder.createTexture(std::move(texture), desc), Usage::TransferDst, WriteMode::Discard);
        },
        [](const Data& d, PassContext& ctx) {
            const VkClearColorValue clear{};
            const VkImageSubresourceRange range{.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT, .levelCount = 1, .layerCount = 1};
            vkCmdClearColorImage(ctx.cmd(), ctx.image(d.texture), ctx.layout(d.texture), &clear, 1, &range);
        });
    return data.texture;
}

}  // namespace candela::passes
