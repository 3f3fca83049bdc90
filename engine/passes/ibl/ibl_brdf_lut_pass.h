#pragma once
// IBL precompute pass "ibl_brdf_lut" (compute): the split-sum BRDF LUT, RG16F (RGBA16F on devices without RG16F storage), A and B of
// E_ss = f0·A + B for N·V and perceptual roughness from 0 to 1 (shaders/ibl_brdf_lut.comp). It
// depends only on its own size and sample count, not on the environment.

#include "graph/render_graph.h"
#include "vk/pipeline.h"

namespace candela::passes {

class IblBrdfLutPass {
public:
    explicit IblBrdfLutPass(vk::Context& context);

    // Adds the pass writing all of `lut` (format(), square; contents discarded) with `samples` GGX
    // samples per texel. Returns its new version. The pass object must outlive execution.
    graph::TextureId add(graph::RenderGraph& graph, graph::TextureId lut, uint32_t samples) const;

    // The LUT's format on `context`'s device: RG16F, or RGBA16F where RG16F cannot be stored to
    // (DeviceChoices::brdfLut).
    static VkFormat format(const vk::Context& context);

private:
    vk::Pipeline mPipeline;
};

// Adds compute pass `name` running `pipeline` (set 0: the storage image "lut"; push constants
// shading::IblLutPush {size, samples}) over every texel of the square `lut`, whose contents it
// discards; returns the new version. The LUT passes (BRDF, sheen) share it. `pipeline` must outlive
// the graph's execution.
graph::TextureId addLutPass(graph::RenderGraph& graph, const char* name, const vk::Pipeline& pipeline, graph::TextureId lut,
                            uint32_t samples);

}  // namespace candela::passes
