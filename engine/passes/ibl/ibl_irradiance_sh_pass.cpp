#include "passes/ibl/ibl_irradiance_sh_pass.h"

#include "passes/recording/compute.h"
#include "shared/ibl.h"

#include <bit>

namespace candela::passes {

using namespace graph;

IblIrradianceShPass::IblIrradianceShPass(vk::Context& context)
    : mPipeline(vk::Pipeline::compute(context, "ibl_irradiance_sh.comp")), mSampler(vk::createSampler(context, {})) {}

BufferId IblIrradianceShPass::add(RenderGraph& graph, const Inputs& in) const {
    struct Data {
        TextureId source;
        BufferId coefficients;
        BufferId bright;
    };
    const Data& data = graph.addPass<Data>(
        "ibl_irradiance_sh", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            d.source = builder.sample(in.source);
            d.bright = builder.read(in.bright, Usage::StorageRead);
            d.coefficients = builder.write(in.coefficients, Usage::StorageWrite, WriteMode::Discard);
        },
        [this, projected = in.projectedFaceSize, inverseScale = 1.0f / in.sourceScale](const Data& d, PassContext& ctx) {
            const uint32_t lod = std::countr_zero(ctx.desc(d.source).width) - std::countr_zero(projected);
            const shading::IblShPush push{.faceSize = projected, .lod = float(lod), .inverseScale = inverseScale};
            const VkDescriptorSet set =
                vk::DescriptorWriter(mPipeline.program(), 0)
                    .image("source", ctx.view(d.source), ctx.layout(d.source), mSampler.get())
                    .buffer("ShCoefficients", ctx.buffer(d.coefficients))
                    .buffer("BrightTexels", ctx.buffer(d.bright))
                    .commit(ctx.context(), ctx.descriptors());
            dispatchCompute(ctx, mPipeline, set, &push, sizeof(push), 1, 1, 1);
        });
    return data.coefficients;
}

}  // namespace candela::passes
