#include "passes/visibility/msaa_expand_pass.h"

#include "passes/recording/fullscreen.h"

#include <stdexcept>

namespace candela::passes {

using namespace graph;

MsaaExpandPass::MsaaExpandPass(vk::Context& context)
    : mContext(context), mSampler(vk::createSampler(context, vk::kNearestSampler)) {}

DrawTarget MsaaExpandPass::add(RenderGraph& graph, const DrawTarget& resolved) {
    if (!(resolved.color == resolved.hdr)) throw std::logic_error("MsaaExpandPass: the target is not resolved");
    struct Data {
        TextureId hdr;
        TextureId expanded;
        const vk::Pipeline* pipeline = nullptr;
    };
    const Data& data = graph.addPass<Data>(
        "msaa_expand", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            TextureDesc desc = builder.desc(resolved.hdr);
            const uint32_t samples = builder.desc(resolved.depth).samples;
            if (samples < 2) throw std::logic_error("MsaaExpandPass: the depth is not multisampled");
            desc.samples = samples;
            d.pipeline = &mPipelines.get(mContext, samples, [&] {
                return vk::Pipeline::graphics(mContext, "fullscreen.vert", "msaa_expand.frag",
                                              {.colorFormats = {kHdrFormat}, .samples = samples});
            });
            d.hdr = builder.sample(resolved.hdr);
            d.expanded = builder.write(builder.createTexture("hdr_msaa", desc), Usage::ColorAttachment, WriteMode::Discard);
        },
        [sampler = mSampler.get()](const Data& d, PassContext& ctx) {
            drawFullscreenSampling(ctx, *d.pipeline, "hdrImage", d.hdr, sampler);
        });
    return {.color = data.expanded, .depth = resolved.depth, .hdr = data.hdr};
}

}  // namespace candela::passes
