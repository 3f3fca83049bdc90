#pragma once
// Pass "ibl_sheen_lut" (compute): the sheen lobe's directional albedo E(N·V, sheen roughness) for
// KHR_materials_sheen (shaders/ibl_sheen_lut.comp), R32F (RGBA16F on devices that cannot filter R32F), N·V and perceptual roughness from 0 to 1
// across the texel centres (shared/ibl.h brdfLutUv). It depends on nothing but its size.

#include "graph/render_graph.h"
#include "vk/pipeline.h"

namespace candela::passes {

class IblSheenLutPass {
public:
    explicit IblSheenLutPass(vk::Context& context);

    // Adds the pass writing all of `lut` (format(), square; contents discarded). Returns its new
    // version. The pass object must outlive execution.
    graph::TextureId add(graph::RenderGraph& graph, graph::TextureId lut) const;

    // The LUT's format on `context`'s device: R32F, or RGBA16F where R32F is not linearly
    // filterable (DeviceChoices::sheenLut).
    static VkFormat format(const vk::Context& context);

private:
    vk::Pipeline mPipeline;
};

}  // namespace candela::passes
