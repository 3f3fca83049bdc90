#include "passes/backdrop/transmission_background_pass.h"

#include "passes/recording/compute.h"
#include "vk/descriptors.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <bit>

namespace candela::passes {

using namespace graph;

TransmissionBackgroundPass::TransmissionBackgroundPass(vk::Context& context)
    : mContext(context), mSampler(vk::createSampler(context, {.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST})) {}

uint32_t TransmissionBackgroundPass::mipLevels(uint32_t width, uint32_t height) {
    return uint32_t(std::bit_width(std::max({width, height, 1u})));
}

TextureId TransmissionBackgroundPass::add(RenderGraph& graph, TextureId hdr) {
    const vk::Pipeline* pipeline =
        &mPipelines.get(mContext, 0, [&] { return vk::Pipeline::compute(mContext, "transmission_background.comp"); });
    struct Data {
        TextureId hdr;
        TextureId background;
    };
    const Data& data = graph.addPass<Data>(
        "transmission_background", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            const TextureDesc& source = builder.desc(hdr);
            d.hdr = builder.sample(hdr);
            const TextureId background = builder.createTexture(
                "transmission_background", {.width = source.width,
                                            .height = source.height,
                                            .mipLevels = mipLevels(source.width, source.height),
                                            .format = kFormat});
            d.background = builder.write(background, Usage::StorageReadWrite, WriteMode::Discard);
        },
        [this, pipeline](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.background);
            for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
                // Mip m − 1's writes before mip m reads them through the sampler.
                if (mip > 0)
                    vk::memoryBarrier(ctx.cmd(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
                const glm::uvec2 size(std::max(desc.width >> mip, 1u), std::max(desc.height >> mip, 1u));
                const VkDescriptorSet set =
                    vk::DescriptorWriter(pipeline->program(), 0)
                        .image("source", mip == 0 ? ctx.view(d.hdr) : ctx.mipView(d.background, mip - 1),
                               mip == 0 ? ctx.layout(d.hdr) : ctx.layout(d.background), mSampler.get())
                        .image("destination", ctx.mipView(d.background, mip), ctx.layout(d.background))
                        .commit(ctx.context(), ctx.descriptors());
                dispatchCompute(ctx, *pipeline, set, &size, sizeof(size), groupCount(size.x, 8), groupCount(size.y, 8), 1);
            }
        });
    return data.background;
}

}  // namespace candela::passes
