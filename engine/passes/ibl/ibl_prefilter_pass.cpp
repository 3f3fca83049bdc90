#include "passes/ibl/ibl_prefilter_pass.h"

#include "passes/ibl/ibl_sample_tables.h"
#include "passes/recording/compute.h"
#include "shared/ibl.h"
#include "shared/specialization_ids.h"
#include "vk/upload.h"

#include <algorithm>
#include <span>

namespace candela::passes {

using namespace graph;

IblPrefilterPass::IblPrefilterPass(vk::Context& context, Lobe lobe)
    : mContext(context),
      mLobe(lobe),
      mPipeline(vk::Pipeline::compute(context, "ibl_filter_cube.comp", shader::specializationValues({{CANDELA_SPEC_FILTER_WEIGHT_BY_COSINE, lobe == Lobe::Ggx}}))),
      mSampler(vk::createSampler(context, {.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST})) {}

void IblPrefilterPass::prepare(uint32_t levels, uint32_t samples, uint32_t sourceFaceSize, uint32_t sourceMips,
                               bool filtered, float lodBias) {
    std::vector<glm::vec4> all;
    std::vector<float> lobes(size_t(levels) * CANDELA_IBL_LOBE_TABLE_SIZE, 0.0f);
    mRanges.assign(levels, {});
    // Each coarser level has 4× fewer texels and a wider lobe: 4× the samples keeps every level's
    // cost equal and its noise down where small bright sources are spread widest.
    uint32_t count = samples;
    for (uint32_t mip = firstMip(); mip < levels; ++mip, count = std::min(count * 4, kMaxSamples)) {
        const float roughness = float(mip) / float(levels - 1);
        const SampleTable table = mLobe == Lobe::Ggx
                                      ? prefilterSamples(roughness, count, sourceFaceSize, sourceMips, filtered, lodBias)
                                      : charlieSamples(roughness, count, sourceFaceSize, sourceMips, filtered, lodBias);
        mRanges[mip] = {static_cast<uint32_t>(all.size()), static_cast<uint32_t>(table.samples.size()),
                        table.totalWeight > 0.0f ? 1.0f / table.totalWeight : 0.0f};
        all.insert(all.end(), table.samples.begin(), table.samples.end());
        const std::vector<float> lobe = lobeTable(mLobe == Lobe::Ggx ? FilterLobe::Ggx : FilterLobe::Charlie, roughness);
        std::copy(lobe.begin(), lobe.end(), lobes.begin() + ptrdiff_t(mip) * CANDELA_IBL_LOBE_TABLE_SIZE);
    }
    if (all.empty()) all.emplace_back(0.0f);
    mTable = vk::Buffer(mContext, {.size = all.size() * sizeof(glm::vec4),
                                   .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   .name = "ibl_prefilter_samples"});
    mLobes = vk::Buffer(mContext, {.size = lobes.size() * sizeof(float),
                                   .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   .name = "ibl_prefilter_lobes"});
    vk::Uploader upload(mContext);
    upload.buffer(mTable, std::as_bytes(std::span(all)));
    upload.buffer(mLobes, std::as_bytes(std::span(lobes)));
    upload.submitAndWait();
}

TextureId IblPrefilterPass::add(RenderGraph& graph, const Inputs& in) const {
    struct Data {
        TextureId source;
        TextureId specular;
        BufferId bright;
    };
    const Data& data = graph.addPass<Data>(
        mLobe == Lobe::Ggx ? "ibl_prefilter" : "ibl_sheen_prefilter", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            d.source = builder.sample(in.source);
            d.bright = builder.read(in.bright, Usage::StorageRead);
            // GGX keeps mip 0 (the cubemap pass's); Charlie writes every mip.
            d.specular = builder.write(in.specular, Usage::StorageWrite,
                                       mLobe == Lobe::Ggx ? WriteMode::Preserve : WriteMode::Discard);
            // Switched off, the cull step would bypass it (its write preserves mip 0) and leave the
            // rough mips, which only it writes, undefined.
            if (mLobe == Lobe::Ggx)
                builder.cannotBeDisabled("it writes the specular map's rough levels (mips 1 and up), which nothing else "
                                         "writes; without it what rough surfaces reflect is undefined (a cheaper "
                                         "prefilter: --ibl-prefilter-samples)");
        },
        [this, inverseScale = 1.0f / in.sourceScale](const Data& d, PassContext& ctx) {
            const uint32_t faceSize = ctx.desc(d.specular).width;
            for (uint32_t mip = firstMip(); mip < ctx.desc(d.specular).mipLevels && mip < mRanges.size(); ++mip) {
                const shading::IblFilterPush push{.faceSize = std::max(faceSize >> mip, 1u),
                                                  .firstSample = mRanges[mip].first,
                                                  .sampleCount = mRanges[mip].count,
                                                  .inverseWeight = mRanges[mip].inverseWeight * inverseScale,
                                                  .firstLobe = mip * CANDELA_IBL_LOBE_TABLE_SIZE};
                const VkDescriptorSet set =
                    vk::DescriptorWriter(mPipeline.program(), 0)
                        .image("source", ctx.view(d.source), ctx.layout(d.source), mSampler.get())
                        .image("dstMip", ctx.mipView(d.specular, mip), ctx.layout(d.specular))
                        .buffer("SampleTable", mTable.handle())
                        .buffer("BrightTexels", ctx.buffer(d.bright))
                        .buffer("LobeTable", mLobes.handle())
                        .commit(ctx.context(), ctx.descriptors());
                const uint32_t groups = groupCount(push.faceSize, CANDELA_IBL_GROUP);
                dispatchCompute(ctx, mPipeline, set, &push, sizeof(push), groups, groups, 6);
            }
        });
    return data.specular;
}

}  // namespace candela::passes
