#pragma once
// IblSet: descriptor set 2 of the forward pass (image-based lighting), declared in the pass's
// setup from the frame's IBL handles and written in its execute callback from what the pass context
// resolves them to. Every forward variant's layout has every IBL binding (the ground truth's
// program also its inputs); what a frame lacks (no environment, the irradiance form not in use, no
// ground truth) is bound to a 1×1 placeholder this object owns and the variant in use never reads.

#include "graph/render_graph.h"
#include "passes/ibl/ibl_handles.h"
#include "vk/buffer.h"
#include "vk/image.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"

namespace candela::graph {
class PassContext;
}

namespace candela::passes {

class IblSet {
public:
    // Creates and uploads the placeholders (waits for the upload).
    explicit IblSet(vk::Context& context);

    // Declares the reads (by the fragment shader) of every valid handle of `ibl` (null: none) in the
    // pass `builder` belongs to. Returns the handles as declared, for write().
    // `stages`: the shader stages reading the buffers (the fragment stage of the forward draws, the
    // compute stage of the visibility path's shading).
    static IblHandles declare(graph::PassBuilder& builder, const IblHandles* ibl,
                              VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    // Allocates set 2 of `program` from the frame's descriptor pool and writes it: the declared maps
    // as `ctx` resolves them, placeholders for the invalid handles.
    VkDescriptorSet write(const graph::PassContext& ctx, const vk::Program& program, const IblHandles& declared) const;

private:
    vk::Sampler mTrilinear;  // clamp to edge
    vk::Sampler mNearest;    // the ground truth reads texels exactly
    vk::Image mPlaceholderCube;
    vk::Image mPlaceholderLut;
    vk::Buffer mPlaceholderSh;
    vk::Image mPlaceholderEquirect;
    vk::Buffer mPlaceholderTexels;
};

}  // namespace candela::passes
