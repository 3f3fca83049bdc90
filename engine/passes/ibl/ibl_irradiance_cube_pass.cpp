#include "passes/ibl/ibl_irradiance_cube_pass.h"

#include "passes/ibl/ibl_sample_tables.h"
#include "passes/recording/compute.h"
#include "shared/ibl.h"
#include "shared/specialization_ids.h"
#include "vk/upload.h"

#include <span>

namespace candela::passes {

using namespace graph;

IblIrradianceCubePass::IblIrradianceCubePass(vk::Context& context)
    : mContext(context),
      mPipeline(vk::Pipeline::compute(context, "ibl_filter_cube.comp", shader::specializationValues({{CANDELA_SPEC_FILTER_WEIGHT_BY_COSINE, 0}}))),
      mSampler(vk::createSampler(context, {})) {}

void IblIrradianceCubePass::prepare(uint32_t samples, uint32_t sourceFaceSize, uint32_t sourceMips, bool filtered,
                 float lodBias) {
    const SampleTable table = irradianceSamples(samples, sourceFaceSize, sourceMips, filtered, lodBias);
    mSampleCount = static_cast<uint32_t>(table.samples.size());
    mInverseWeight = 1.0f / table.totalWeight;
    mTable = vk::Buffer(mContext, {.size = table.samples.size() * sizeof(glm::vec4),
                                   .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   .name = "ibl_irradiance_samples"});
    const std::vector<float> lobe = lobeTable(FilterLobe::Cosine, 1.0f);
    mLobe = vk::Buffer(mContext, {.size = lobe.size() * sizeof(float),
                                  .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  .name = "ibl_irradiance_lobe"});
    vk::Uploader upload(mContext);
    upload.buffer(mTable, std::as_bytes(std::span(table.samples)));
    upload.buffer(mLobe, std::as_bytes(std::span(lobe)));
    upload.submitAndWait();
}

TextureId IblIrradianceCubePass::add(RenderGraph& graph, const Inputs& in) const {
    struct Data {
        TextureId source;
        TextureId irradiance;
        BufferId bright;
    };
    const Data& data = graph.addPass<Data>(
        "ibl_irradiance_cube", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            d.source = builder.sample(in.source);
            d.bright = builder.read(in.bright, Usage::StorageRead);
            d.irradiance = builder.write(in.irradiance, Usage::StorageWrite, WriteMode::Discard);
        },
        [this, inverseScale = 1.0f / in.sourceScale](const Data& d, PassContext& ctx) {
            const uint32_t faceSize = ctx.desc(d.irradiance).width;
            const shading::IblFilterPush push{.faceSize = faceSize,
                                              .firstSample = 0,
                                              .sampleCount = mSampleCount,
                                              .inverseWeight = mInverseWeight * inverseScale,
                                              .firstLobe = 0};
            const VkDescriptorSet set =
                vk::DescriptorWriter(mPipeline.program(), 0)
                    .image("source", ctx.view(d.source), ctx.layout(d.source), mSampler.get())
                    .image("dstMip", ctx.mipView(d.irradiance, 0), ctx.layout(d.irradiance))
                    .buffer("SampleTable", mTable.handle())
                    .buffer("BrightTexels", ctx.buffer(d.bright))
                    .buffer("LobeTable", mLobe.handle())
                    .commit(ctx.context(), ctx.descriptors());
            const uint32_t groups = groupCount(faceSize, CANDELA_IBL_GROUP);
            dispatchCompute(ctx, mPipeline, set, &push, sizeof(push), groups, groups, 6);
        });
    return data.irradiance;
}

}  // namespace candela::passes
