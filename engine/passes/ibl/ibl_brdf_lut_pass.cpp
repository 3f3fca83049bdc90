#include "passes/ibl/ibl_brdf_lut_pass.h"

#include "passes/recording/compute.h"
#include "shared/ibl.h"

namespace candela::passes {

using namespace graph;

IblBrdfLutPass::IblBrdfLutPass(vk::Context& context)
    : mPipeline(vk::Pipeline::compute(context, format(context) == VK_FORMAT_R16G16_SFLOAT ? "ibl_brdf_lut.comp"
                                                                                           : "ibl_brdf_lut_rgba16f.comp")) {}

VkFormat IblBrdfLutPass::format(const vk::Context& context) { return context.choices().brdfLut; }

TextureId addLutPass(RenderGraph& graph, const char* name, const vk::Pipeline& pipeline, TextureId lut, uint32_t samples) {
    struct Data {
        TextureId lut;
    };
    const Data& data = graph.addPass<Data>(
        name, PassType::Compute,
        [&](PassBuilder& builder, Data& d) { d.lut = builder.write(lut, Usage::StorageWrite, WriteMode::Discard); },
        [&pipeline, samples](const Data& d, PassContext& ctx) {
            const uint32_t size = ctx.desc(d.lut).width;
            const shading::IblLutPush push{.size = size, .samples = samples};
            const VkDescriptorSet set = vk::DescriptorWriter(pipeline.program(), 0)
                                            .image("lut", ctx.view(d.lut), ctx.layout(d.lut))
                                            .commit(ctx.context(), ctx.descriptors());
            const uint32_t groups = groupCount(size, CANDELA_IBL_GROUP);
            dispatchCompute(ctx, pipeline, set, &push, sizeof(push), groups, groups, 1);
        });
    return data.lut;
}

TextureId IblBrdfLutPass::add(RenderGraph& graph, TextureId lut, uint32_t samples) const {
    return addLutPass(graph, "ibl_brdf_lut", mPipeline, lut, samples);
}

}  // namespace candela::passes
