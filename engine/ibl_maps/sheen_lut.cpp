#include "ibl_maps/sheen_lut.h"

#include "ibl_maps/ibl_maps.h"
#include "passes/ibl/ibl_sheen_lut_pass.h"

namespace candela::ibl_maps {

using namespace graph;

SheenLut::SheenLut(vk::Context& context) : mContext(context) {}

SheenLut::~SheenLut() = default;

TextureId SheenLut::addToGraph(RenderGraph& graph, ImportBindings& imports) {
    if (!mImage) {
        mImage = vk::Image(mContext, {.width = kSize, .height = kSize, .format = passes::IblSheenLutPass::format(mContext),
                                      .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                               VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                      .name = "ibl_sheen_lut"});
        mPass = std::make_unique<passes::IblSheenLutPass>(mContext);
    }
    const TextureId lut = graph.importTexture("ibl_sheen_lut",
                                              {.width = kSize, .height = kSize, .format = passes::IblSheenLutPass::format(mContext)},
                                              mComputed ? IblMaps::kRestState : ResourceState{}, IblMaps::kRestState);
    imports.bind(lut, mImage.handle(), mImage.view(), {});
    mAdded = !mComputed;
    return mComputed ? lut : mPass->add(graph, lut);
}

void SheenLut::frameCompleted(const RenderGraph& graph) {
    if (!mAdded) return;
    mAdded = false;
    const std::optional<uint32_t> pass = graph.findPass("ibl_sheen_lut");
    mComputed = pass && graph.compiled().passes[*pass].cullReason == CullReason::None;
}

}  // namespace candela::ibl_maps
