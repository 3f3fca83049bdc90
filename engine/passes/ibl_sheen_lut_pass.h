#pragma once
// Pass "ibl_sheen_lut" (compute): the sheen lobe's directional albedo E(N·V, sheen roughness) for
// KHR_materials_sheen (shaders/ibl_sheen_lut.comp), R32F, N·V and perceptual roughness from 0 to 1
// across the texel centres (shared/ibl.h brdfLutUv). It depends on nothing but its size.

#include "graph/render_graph.h"
#include "vk/pipeline.h"

namespace candela::passes {

class IblSheenLutPass {
public:
    explicit IblSheenLutPass(vk::Context& context);

    // Adds the pass writing all of `lut` (kFormat, square; contents discarded). Returns its new
    // version. The pass object must outlive execution.
    graph::TextureId add(graph::RenderGraph& graph, graph::TextureId lut) const;

    static constexpr VkFormat kFormat = VK_FORMAT_R32_SFLOAT;

private:
    vk::Pipeline mPipeline;
};

}  // namespace candela::passes
