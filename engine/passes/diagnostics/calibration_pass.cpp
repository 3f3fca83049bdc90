#include "passes/diagnostics/calibration_pass.h"

#include "passes/recording/fullscreen.h"
#include "vk/upload.h"

#include <glm/gtc/packing.hpp>

#include <vector>

namespace candela::passes {

using namespace graph;

namespace {

// Constant texels: each mip/face filled with one half-float colour.
std::vector<uint16_t> constantTexels(uint32_t count, uint32_t channels, glm::vec4 value) {
    std::vector<uint16_t> texels(static_cast<size_t>(count) * channels);
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = glm::packHalf1x16(value[static_cast<int>(i % channels)]);
    return texels;
}

vk::Image cube(vk::Context& context, vk::Uploader& uploader, uint32_t size, uint32_t mips, glm::vec4 value,
               const char* name) {
    vk::Image image(context, {.width = size,
                              .height = size,
                              .mipLevels = mips,
                              .arrayLayers = 6,
                              .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                              .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                              .cube = true,
                              .name = name});
    for (uint32_t mip = 0; mip < mips; ++mip) {
        const uint32_t side = std::max(1u, size >> mip);
        const std::vector<uint16_t> texels = constantTexels(side * side, 4, value * (1.0f / float(mip + 1)));
        for (uint32_t face = 0; face < 6; ++face)
            uploader.image(image, std::as_bytes(std::span(texels)), mip, face, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
    return image;
}

}  // namespace

CalibrationPass::CalibrationPass(vk::Context& context) : mContext(context) {}

void CalibrationPass::createResources() {
    vk::Context& context = mContext;
    mSampler = vk::createSampler(context, {});
    vk::Uploader uploader(context);
    mIrradiance = cube(context, uploader, 8, 1, glm::vec4(0.3f, 0.35f, 0.4f, 1.0f), "calibration irradiance");
    mPrefiltered = cube(context, uploader, 32, 6, glm::vec4(0.8f, 0.8f, 0.9f, 1.0f), "calibration prefiltered");
    mLut = vk::Image(context, {.width = 32,
                               .height = 32,
                               .format = VK_FORMAT_R16G16_SFLOAT,
                               .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                               .name = "calibration lut"});
    const std::vector<uint16_t> lut = constantTexels(32 * 32, 2, glm::vec4(0.7f, 0.1f, 0.0f, 0.0f));
    uploader.image(mLut, std::as_bytes(std::span(lut)), 0, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    uploader.submitAndWait();
}

TextureId CalibrationPass::add(RenderGraph& graph, uint32_t width, uint32_t height) {
    if (!mLut) createResources();
    const vk::Pipeline* pipeline = &mPipelines.get(mContext, 0, [&] {
        return vk::Pipeline::graphics(mContext, "fullscreen.vert", "calibration.frag",
                                      {.colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT}});
    });
    struct Data {
        TextureId target;
    };
    const Data& data = graph.addPass<Data>(
        "calibration", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            const TextureId target =
                builder.createTexture("calibration", {.width = width, .height = height, .format = VK_FORMAT_R16G16B16A16_SFLOAT});
            d.target = builder.write(target, Usage::ColorAttachment, WriteMode::Discard);
        },
        [this, pipeline](const Data&, PassContext& ctx) {
            const VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            const VkDescriptorSet set = vk::DescriptorWriter(pipeline->program(), 0)
                                            .image("irradianceMap", mIrradiance.view(), layout, mSampler.get())
                                            .image("prefilteredMap", mPrefiltered.view(), layout, mSampler.get())
                                            .image("brdfLut", mLut.view(), layout, mSampler.get())
                                            .commit(ctx.context(), ctx.descriptors());
            drawFullscreenTriangle(ctx, *pipeline, set);
        });
    graph.exportTexture(data.target);
    return data.target;
}

}  // namespace candela::passes
