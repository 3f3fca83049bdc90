#include "passes/diagnostics/brdf_probe_pass.h"

#include "executor/graph_executor.h"
#include "shared/specialization_ids.h"

namespace candela::passes {

using namespace graph;

BrdfProbePass::BrdfProbePass(vk::Context& context, Brdf brdf)
    : mPipeline(vk::Pipeline::compute(context, "brdf_probe.comp", shader::specializationValues({{CANDELA_SPEC_PROBE_LAYERS, brdf == Brdf::Layers}}))) {}

TextureId BrdfProbePass::add(RenderGraph& graph, const shading::BrdfProbeParams& params) const {
    struct Data {
        TextureId probe;
    };
    const Data& data = graph.addPass<Data>(
        "brdf_probe", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            const TextureId probe = builder.createTexture("brdf_probe", {.width = kWidth, .height = kHeight, .format = kFormat});
            d.probe = builder.write(probe, Usage::StorageWrite, WriteMode::Discard);
        },
        [this, params](const Data& d, PassContext& ctx) {
            const VkDescriptorSet set = vk::DescriptorWriter(mPipeline.program(), 0)
                                            .image("outImage", ctx.view(d.probe), ctx.layout(d.probe))
                                            .commit(ctx.context(), ctx.descriptors());
            mPipeline.bind(ctx.cmd());
            vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline.layout(), 0, 1, &set, 0, nullptr);
            mPipeline.pushConstants(ctx.cmd(), &params, sizeof(params));
            const uint32_t group = CANDELA_BRDF_PROBE_GROUP_SIZE;
            vkCmdDispatch(ctx.cmd(), (kWidth + group - 1) / group, (kHeight + group - 1) / group, 1);
        });
    return data.probe;
}

}  // namespace candela::passes
