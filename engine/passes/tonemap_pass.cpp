#include "passes/tonemap_pass.h"

#include "passes/fullscreen.h"
#include "shared/tonemap.h"

#include <cmath>

namespace candela::passes {

using namespace graph;

namespace {
bool isSrgbFormat(VkFormat format) {
    return format == VK_FORMAT_R8G8B8A8_SRGB || format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
}

}  // namespace

TonemapPass::TonemapPass(vk::Context& context)
    : mContext(context),
      mSampler(vk::createSampler(context, vk::kNearestSampler)) {}

TextureId TonemapPass::add(RenderGraph& graph, TextureId hdr, TextureId target, const TonemapSettings& settings,
                           shader::ParameterRegistry* parameters) {
    struct Data {
        TextureId hdr;
        TextureId target;
        const vk::Pipeline* pipeline = nullptr;
        shading::TonemapParams params{};
    };
    const Data& data = graph.addPass<Data>(
        "tonemap", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            d.hdr = builder.sample(hdr);
            d.target = builder.write(target, Usage::ColorAttachment, WriteMode::Discard);
            const VkFormat format = builder.desc(target).format;
            const std::vector<uint32_t> specialization{static_cast<uint32_t>(settings.op), isSrgbFormat(format) ? 0u : 1u,
                                                       settings.dither ? 1u : 0u, settings.background ? 1u : 0u};
            d.pipeline = &mPipelines.get(mContext, {format, specialization}, [&] {
                return vk::Pipeline::graphics(mContext, "fullscreen.vert", "tonemap.frag",
                                              {.colorFormats = {format}, .specialization = specialization});
            });
            d.params.background = settings.background ? glm::vec4(*settings.background, 1.0f) : glm::vec4(0.0f);
            d.params.exposureEv = settings.exposureEv;
            if (parameters)
                parameters->apply("tonemap", "Push", d.pipeline->program().reflection().pushConstants.members, d.params);
        },
        [sampler = mSampler.get()](const Data& d, PassContext& ctx) {
            drawFullscreenSampling(ctx, *d.pipeline, "hdrImage", d.hdr, sampler, &d.params, sizeof(d.params));
        });
    return data.target;
}

}  // namespace candela::passes
