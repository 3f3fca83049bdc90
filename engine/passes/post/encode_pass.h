#pragma once
// Encode pass (graphics): draws a full-screen triangle that clamps the HDR image to [0,1] into an
// 8-bit sRGB target (the format's encoding applies the sRGB transfer function).

#include "graph/render_graph.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"

namespace candela::passes {

class EncodePass {
public:
    // `targetFormat` is the format of the textures this pass will write (an _SRGB format for PNG).
    EncodePass(vk::Context& context, VkFormat targetFormat);

    // Adds the pass: samples `hdr`, writes all of `target` (same size); returns target's new version.
    graph::TextureId add(graph::RenderGraph& graph, graph::TextureId hdr, graph::TextureId target) const;

private:
    vk::Pipeline mPipeline;
    vk::Sampler mSampler;
};

}  // namespace candela::passes
