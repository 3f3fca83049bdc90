#include "passes/post/tonemap_pass.h"

#include "passes/recording/fullscreen.h"
#include "shared/specialization_ids.h"
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
      mSampler(vk::createSampler(context, vk::kNearestSampler)), mTrilinear(vk::createSampler(context, {})) {}

TextureId TonemapPass::add(RenderGraph& graph, TextureId hdr, TextureId target, const TonemapSettings& settings,
                           shader::ParameterRegistry* parameters, const Sky* sky) {
    // The push constants: TonemapParams, then the sky's (tonemap_sky.frag).
    struct Push {
        shading::TonemapParams params;
        shading::TonemapSky sky;
    };
    struct Data {
        TextureId hdr;
        TextureId target;
        TextureId specular;
        const vk::Pipeline* pipeline = nullptr;
        Push push{};
    };
    const Data& data = graph.addPass<Data>(
        "tonemap", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            d.hdr = builder.sample(hdr);
            d.target = builder.write(target, Usage::ColorAttachment, WriteMode::Discard);
            const VkFormat format = builder.desc(target).format;
            const std::vector<uint32_t> specialization =
                shader::specializationValues({{CANDELA_SPEC_TONEMAP_OPERATOR, static_cast<uint32_t>(settings.op)},
                                              {CANDELA_SPEC_TONEMAP_ENCODE_SRGB, !isSrgbFormat(format)},
                                              {CANDELA_SPEC_TONEMAP_DITHER, settings.dither},
                                              {CANDELA_SPEC_TONEMAP_BACKGROUND, settings.background.has_value()}});
            // The key's last entry selects the program (it is no constant of the shaders).
            std::vector<uint32_t> key = specialization;
            key.push_back(sky ? 1u : 0u);
            d.pipeline = &mPipelines.get(mContext, {format, key}, [&] {
                return vk::Pipeline::graphics(mContext, "fullscreen.vert", sky ? "tonemap_sky.frag" : "tonemap.frag",
                                              {.colorFormats = {format}, .specialization = specialization});
            });
            d.push.params.background = settings.background ? glm::vec4(*settings.background, 1.0f) : glm::vec4(0.0f);
            d.push.params.exposureEv = settings.exposureEv;
            if (sky) {
                d.specular = builder.sample(sky->specular);
                d.push.sky = sky->params;
            }
            if (parameters)
                parameters->apply("tonemap", "Push", d.pipeline->program().reflection().pushConstants.members, d.push);
        },
        [sampler = mSampler.get(), trilinear = mTrilinear.get()](const Data& d, PassContext& ctx) {
            const uint32_t pushSize = d.specular.valid() ? sizeof(Push) : sizeof(shading::TonemapParams);
            vk::DescriptorWriter writer(d.pipeline->program(), 0);
            writer.image("hdrImage", ctx.view(d.hdr), ctx.layout(d.hdr), sampler);
            if (d.specular.valid()) writer.image("specularCube", ctx.view(d.specular), ctx.layout(d.specular), trilinear);
            drawFullscreenTriangle(ctx, *d.pipeline, writer.commit(ctx.context(), ctx.descriptors()), &d.push, pushSize);
        });
    return data.target;
}

}  // namespace candela::passes
