#include "passes/ibl/ibl_sheen_lut_pass.h"

#include "passes/ibl/ibl_brdf_lut_pass.h"

namespace candela::passes {

IblSheenLutPass::IblSheenLutPass(vk::Context& context)
    : mPipeline(vk::Pipeline::compute(context, format(context) == VK_FORMAT_R32_SFLOAT ? "ibl_sheen_lut.comp"
                                                                                        : "ibl_sheen_lut_rgba16f.comp")) {}

VkFormat IblSheenLutPass::format(const vk::Context& context) { return context.choices().sheenLut; }

graph::TextureId IblSheenLutPass::add(graph::RenderGraph& graph, graph::TextureId lut) const {
    return addLutPass(graph, "ibl_sheen_lut", mPipeline, lut, 0);
}

}  // namespace candela::passes
