#include "passes/ibl_sheen_lut_pass.h"

#include "passes/compute.h"
#include "shared/ibl.h"

namespace candela::passes {

using namespace graph;

IblSheenLutPass::IblSheenLutPass(vk::Context& context) : mPipeline(vk::Pipeline::compute(context, "ibl_sheen_lut.comp")) {}

TextureId IblSheenLutPass::add(RenderGraph& graph, TextureId lut) const {
    struct Data {
        TextureId lut;
    };
    const Data& data = graph.addPass<Data>(
        "ibl_sheen_lut", PassType::Compute,
        [&](PassBuilder& builder, Data& d) { d.lut = builder.write(lut, Usage::StorageWrite, WriteMode::Discard); },
        [this](const Data& d, PassContext& ctx) {
            const uint32_t size = ctx.desc(d.lut).width;
            const shading::IblLutPush push{.size = size, .samples = 0};
            const VkDescriptorSet set = vk::DescriptorWriter(mPipeline.program(), 0)
                                            .image("lut", ctx.view(d.lut), ctx.layout(d.lut))
                                            .commit(ctx.context(), ctx.descriptors());
            const uint32_t groups = groupCount(size, CANDELA_IBL_GROUP);
            dispatchCompute(ctx, mPipeline, set, &push, sizeof(push), groups, groups, 1);
        });
    return data.lut;
}

}  // namespace candela::passes
