#pragma once
// MSAA expand pass (graphics, "msaa_expand"): writes a resolved single-sample HDR image into every
// sample of a new multisampled colour target, so that forward draws at the frame's sample count can
// draw over it and resolve again. The visibility path resolves inside its shading; its frames with
// blended or transmissive draws at MSAA take this pass to get back an image to draw over (their
// edges then antialiased by the forward pass's samples, against the visibility pass's multisampled
// depth). Writing one value to all samples and resolving gives that value back: the expansion
// changes no pixel by itself.

#include "graph/render_graph.h"
#include "passes/drawing/draw_target.h"
#include "vk/pipeline_cache.h"
#include "vk/sampler.h"

namespace candela::passes {

class MsaaExpandPass {
public:
    explicit MsaaExpandPass(vk::Context& context);

    // Adds the pass: reads `resolved.hdr` (single-sample), writes a new "hdr_msaa" at the sample
    // count of `resolved.depth`. Returns the target to draw over: that colour, the same depth, and
    // `resolved.hdr` as what its draws resolve into. Precondition: resolved.depth has > 1 sample and
    // resolved.color == resolved.hdr.
    DrawTarget add(graph::RenderGraph& graph, const DrawTarget& resolved);

private:
    vk::Context& mContext;
    vk::PipelineCache<uint32_t> mPipelines;  // by sample count
    vk::Sampler mSampler;
};

}  // namespace candela::passes
