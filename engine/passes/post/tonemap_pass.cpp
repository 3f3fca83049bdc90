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
        TextureId depth;                           // valid: the sky drawn only where it is 0
        const vk::Pipeline* pipeline = nullptr;    // every pixel, or with `depth` the covered ones
        const vk::Pipeline* skyPipeline = nullptr; // the sky's pixels (tonemap_sky.frag)
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
            if (sky && sky->depth.valid()) d.depth = builder.read(sky->depth, Usage::DepthRead);
            const VkFormat depthFormat = d.depth.valid() ? builder.desc(d.depth).format : VK_FORMAT_UNDEFINED;
            // Program: 0 tonemap.frag, 1 tonemap_sky.frag; depth: 0 none, 1 covered pixels (stored
            // depth above the far plane's 0), 2 the sky's (stored depth 0). The key's last two
            // entries select them (they are no constants of the shaders).
            const auto pipeline = [&](uint32_t program, uint32_t depth) {
                std::vector<uint32_t> key = specialization;
                key.insert(key.end(), {program, depth});
                return &mPipelines.get(mContext, {format, key}, [&] {
                    return vk::Pipeline::graphics(mContext, "fullscreen.vert", program ? "tonemap_sky.frag" : "tonemap.frag",
                                                  {.colorFormats = {format},
                                                   .depthFormat = depth ? depthFormat : VK_FORMAT_UNDEFINED,
                                                   .depthTest = depth != 0,
                                                   .depthCompare = depth == 1 ? VK_COMPARE_OP_LESS : VK_COMPARE_OP_GREATER_OR_EQUAL,
                                                   .specialization = specialization});
                });
            };
            if (!sky) {
                d.pipeline = pipeline(0, 0);
            } else if (d.depth.valid()) {
                d.pipeline = pipeline(0, 1);
                d.skyPipeline = pipeline(1, 2);
            } else {
                d.skyPipeline = pipeline(1, 0);
            }
            d.push.params.background = settings.background ? glm::vec4(*settings.background, 1.0f) : glm::vec4(0.0f);
            d.push.params.exposureEv = settings.exposureEv;
            if (sky) {
                d.specular = builder.sample(sky->specular);
                d.push.sky = sky->params;
            }
            if (parameters) {
                const vk::Pipeline& reflected = d.skyPipeline ? *d.skyPipeline : *d.pipeline;
                parameters->apply("tonemap", "Push", reflected.program().reflection().pushConstants.members, d.push);
            }
        },
        [sampler = mSampler.get(), trilinear = mTrilinear.get()](const Data& d, PassContext& ctx) {
            ctx.beginRendering();
            const auto draw = [&](const vk::Pipeline& pipeline, bool withSky) {
                vk::DescriptorWriter writer(pipeline.program(), 0);
                writer.image("hdrImage", ctx.view(d.hdr), ctx.layout(d.hdr), sampler);
                if (withSky) writer.image("specularCube", ctx.view(d.specular), ctx.layout(d.specular), trilinear);
                recordFullscreenTriangle(ctx, pipeline, writer.commit(ctx.context(), ctx.descriptors()), &d.push,
                                         withSky ? sizeof(Push) : sizeof(shading::TonemapParams));
            };
            if (d.pipeline) draw(*d.pipeline, false);
            if (d.skyPipeline) draw(*d.skyPipeline, true);
            ctx.endRendering();
        });
    return data.target;
}

}  // namespace candela::passes
