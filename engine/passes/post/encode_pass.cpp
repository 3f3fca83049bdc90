#include "passes/post/encode_pass.h"

#include "passes/recording/fullscreen.h"

namespace candela::passes {

using namespace graph;

EncodePass::EncodePass(vk::Context& context, VkFormat targetFormat)
    : mPipeline(vk::Pipeline::graphics(context, "fullscreen.vert", "encode.frag", {.colorFormats = {targetFormat}})),
      mSampler(vk::createSampler(context, vk::kNearestSampler)) {}

TextureId EncodePass::add(RenderGraph& graph, TextureId hdr, TextureId target) const {
    struct Data {
        TextureId hdr;
        TextureId target;
    };
    const Data& data = graph.addPass<Data>(
        "encode", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            d.hdr = builder.sample(hdr);
            d.target = builder.write(target, Usage::ColorAttachment, WriteMode::Discard);
        },
        [this](const Data& d, PassContext& ctx) {
            drawFullscreenSampling(ctx, mPipeline, "hdrImage", d.hdr, mSampler.get());
        });
    return data.target;
}

}  // namespace candela::passes
