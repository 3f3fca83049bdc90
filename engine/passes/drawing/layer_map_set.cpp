#include "passes/drawing/layer_map_set.h"

#include "executor/graph_executor.h"
#include "passes/ibl/ibl_sheen_lut_pass.h"
#include "vk/descriptors.h"
#include "vk/upload.h"

#include <array>
#include <cstddef>
#include <span>

namespace candela::passes {

using namespace graph;

LayerMapSet::LayerMapSet(vk::Context& context) : mLinear(vk::createSampler(context, {})) {
    constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    mPlaceholderCube = vk::Image(context, {.width = 1, .height = 1, .arrayLayers = 6, .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                          .usage = usage, .cube = true, .name = "layer_placeholder_cube"});
    mPlaceholderLut = vk::Image(context, {.format = IblSheenLutPass::format(context), .usage = usage, .name = "layer_placeholder_lut"});
    mPlaceholderBackground =
        vk::Image(context, {.format = VK_FORMAT_R16G16B16A16_SFLOAT, .usage = usage, .name = "layer_placeholder_background"});
    static const std::array<std::byte, 8> zeros{};
    vk::Uploader upload(context);
    for (uint32_t face = 0; face < 6; ++face)
        upload.image(mPlaceholderCube, std::span(zeros), 0, face, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    upload.image(mPlaceholderLut, std::span(zeros).first(graph::formatTexelSize(mPlaceholderLut.desc().format)), 0, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    upload.image(mPlaceholderBackground, std::span(zeros), 0, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    upload.submitAndWait();
}

LayerMaps LayerMapSet::declare(PassBuilder& builder, const LayerMaps* maps) {
    if (!maps) return {};
    LayerMaps out;
    if (maps->sheenLut.valid()) out.sheenLut = builder.sample(maps->sheenLut);
    if (maps->sheenCube.valid()) out.sheenCube = builder.sample(maps->sheenCube);
    if (maps->transmission.valid()) out.transmission = builder.sample(maps->transmission);
    return out;
}

VkDescriptorSet LayerMapSet::write(const PassContext& ctx, const vk::Program& program, const LayerMaps& d) const {
    const auto image = [&](vk::DescriptorWriter& writer, const char* name, TextureId handle, const vk::Image& fallback) {
        if (!program.declares(3, name)) return;  // a variant without the layer that reads it
        if (handle.valid()) writer.image(name, ctx.view(handle), ctx.layout(handle), mLinear.get());
        else writer.image(name, fallback.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, mLinear.get());
    };
    vk::DescriptorWriter writer(program, 3);
    image(writer, "sheenLut", d.sheenLut, mPlaceholderLut);
    image(writer, "sheenCube", d.sheenCube, mPlaceholderCube);
    image(writer, "transmissionBackground", d.transmission, mPlaceholderBackground);
    return writer.commit(ctx.context(), ctx.descriptors());
}

}  // namespace candela::passes
