#include "passes/diagnostics/pattern_pass.h"

#include "executor/graph_executor.h"
#include "shared/pattern.h"

namespace candela::passes {

using namespace graph;

PatternPass::PatternPass(vk::Context& context) : mPipeline(vk::Pipeline::compute(context, "pattern.comp")) {}

TextureId PatternPass::add(RenderGraph& graph, uint32_t width, uint32_t height, float exposure) const {
    struct Data {
        TextureId hdr;
    };
    const shading::PatternParams params{.extent = {width, height}, .exposure = exposure, .pad0 = 0.0f};
    const Data& data = graph.addPass<Data>(
        "pattern", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            const TextureId hdr = builder.createTexture("hdr", {.width = width, .height = height, .format = kFormat});
            d.hdr = builder.write(hdr, Usage::StorageWrite, WriteMode::Discard);
        },
        [this, params](const Data& d, PassContext& ctx) {
            const VkDescriptorSet set = vk::DescriptorWriter(mPipeline.program(), 0)
                                            .image("outImage", ctx.view(d.hdr), ctx.layout(d.hdr))
                                            .commit(ctx.context(), ctx.descriptors());
            mPipeline.bind(ctx.cmd());
            vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline.layout(), 0, 1, &set, 0, nullptr);
            mPipeline.pushConstants(ctx.cmd(), &params, sizeof(params));
            const uint32_t group = CANDELA_PATTERN_GROUP_SIZE;
            vkCmdDispatch(ctx.cmd(), (params.extent.x + group - 1) / group, (params.extent.y + group - 1) / group, 1);
        });
    return data.hdr;
}

}  // namespace candela::passes
