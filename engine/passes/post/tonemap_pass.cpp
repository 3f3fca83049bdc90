#include "passes/post/tonemap_pass.h"

#include "passes/drawing/draw_target.h"
#include "passes/recording/fullscreen.h"
#include "shared/specialization_ids.h"
#include "shared/tonemap.h"

#include <cmath>
#include <stdexcept>

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

std::vector<TonemapPass::Variant> TonemapPass::variants(VkFormat format, const TonemapSettings& settings, SkyDraw sky,
                                                      VkFormat depthFormat) {
    const std::vector<uint32_t> specialization =
        shader::specializationValues({{CANDELA_SPEC_TONEMAP_OPERATOR, static_cast<uint32_t>(settings.op)},
                                      {CANDELA_SPEC_TONEMAP_ENCODE_SRGB, !isSrgbFormat(format)},
                                      {CANDELA_SPEC_TONEMAP_DITHER, settings.dither},
                                      {CANDELA_SPEC_TONEMAP_BACKGROUND, settings.background.has_value()}});
    // Program: 0 tonemap.frag, 1 tonemap_sky.frag; depth: 0 none, 1 covered pixels (stored depth
    // above the far plane's 0), 2 the sky's (stored depth 0). The key's last three entries select
    // them and the depth's format (they are no constants of the shaders).
    const auto variant = [&](uint32_t program, uint32_t depth, bool imageClear = false) {
        std::vector<uint32_t> values = specialization;
        shader::setSpecialization(values, CANDELA_SPEC_TONEMAP_IMAGE_CLEAR, imageClear);
        std::vector<uint32_t> key = values;
        key.insert(key.end(), {program, depth, uint32_t(depth ? depthFormat : VK_FORMAT_UNDEFINED)});
        return Variant{.key = {format, std::move(key)},
                       .fragment = program ? "tonemap_sky.frag" : "tonemap.frag",
                       .desc = {.colorFormats = {format},
                                .depthFormat = depth ? depthFormat : VK_FORMAT_UNDEFINED,
                                .depthTest = depth != 0,
                                .depthCompare = depth == 1 ? VK_COMPARE_OP_LESS : VK_COMPARE_OP_GREATER_OR_EQUAL,
                                .specialization = std::move(values)}};
    };
    switch (sky) {
        case SkyDraw::None: return {variant(0, 0)};
        case SkyDraw::Everywhere: return {variant(1, 0)};
        case SkyDraw::WhereUncovered: return {variant(0, 1), variant(1, 2)};
        case SkyDraw::WhereUncoveredImageClear: return {variant(0, 1), variant(1, 2, true)};
    }
    return {};
}

vk::Pipeline TonemapPass::build(vk::Context& context, const Variant& variant) {
    return vk::Pipeline::graphics(context, "fullscreen.vert", variant.fragment, variant.desc);
}

void TonemapPass::prepare(WorkerPool& workers, VkFormat targetFormat, const TonemapSettings& settings, SkyDraw sky) {
    for (Variant& v : variants(targetFormat, settings, sky, kDepthFormat)) {
        const auto key = v.key;
        mPipelines.prepare(workers, key, [context = &mContext, v = std::move(v)] { return build(*context, v); },
                           WorkerPool::Priority::Soon);
    }
}

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
            mLastTargetFormat = format;
            const SkyDraw skyDraw = sky ? sky->draw : SkyDraw::None;
            if (skyDraw == SkyDraw::WhereUncovered || skyDraw == SkyDraw::WhereUncoveredImageClear) {
                if (!sky->depth.valid()) throw std::logic_error("TonemapPass: a sky where uncovered without the depth");
                d.depth = builder.read(sky->depth, Usage::DepthRead);
            }
            std::vector<const vk::Pipeline*> pipelines;
            for (const Variant& v : variants(format, settings, skyDraw, d.depth.valid() ? builder.desc(d.depth).format : VK_FORMAT_UNDEFINED))
                pipelines.push_back(&mPipelines.get(mContext, v.key, [&] { return build(mContext, v); }));
            if (skyDraw == SkyDraw::None) d.pipeline = pipelines[0];
            else if (skyDraw == SkyDraw::Everywhere) d.skyPipeline = pipelines[0];
            else d.pipeline = pipelines[0], d.skyPipeline = pipelines[1];  // where uncovered
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
            d.push.params.exposureScale = std::exp2(d.push.params.exposureEv);  // after the user's EV
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
