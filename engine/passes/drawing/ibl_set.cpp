#include "passes/drawing/ibl_set.h"

#include "executor/graph_executor.h"
#include "passes/ibl/ibl_brdf_lut_pass.h"
#include "passes/ibl/ibl_irradiance_sh_pass.h"
#include "vk/descriptors.h"
#include "vk/upload.h"

#include <array>
#include <cstddef>
#include <span>

namespace candela::passes {

using namespace graph;

namespace {
constexpr VkFormat kCubeFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kEquirectFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkImageUsageFlags kUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

std::span<const std::byte> zeros(size_t bytes) {
    static const std::array<std::byte, 256> buffer{};
    return {buffer.data(), bytes};
}
}  // namespace

IblSet::IblSet(vk::Context& context)
    : mTrilinear(vk::createSampler(context, {})),
      mNearest(vk::createSampler(context, vk::kNearestSampler)) {
    mPlaceholderCube = vk::Image(context, {.width = 1, .height = 1, .arrayLayers = 6, .format = kCubeFormat,
                                          .usage = kUsage, .cube = true, .name = "ibl_placeholder_cube"});
    mPlaceholderLut = vk::Image(context, {.format = IblBrdfLutPass::format(context), .usage = kUsage, .name = "ibl_placeholder_lut"});
    mPlaceholderSh = vk::Buffer(context, {.size = IblIrradianceShPass::kBytes,
                                          .usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          .name = "ibl_placeholder_sh"});
    mPlaceholderEquirect = vk::Image(context, {.format = kEquirectFormat, .usage = kUsage, .name = "ibl_placeholder_equirect"});
    mPlaceholderTexels = vk::Buffer(context, {.size = 16,
                                              .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                              .name = "ibl_placeholder_reference_texels"});
    vk::Uploader upload(context);
    for (uint32_t face = 0; face < 6; ++face)
        upload.image(mPlaceholderCube, zeros(8), 0, face, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    upload.image(mPlaceholderLut, zeros(formatTexelSize(mPlaceholderLut.desc().format)), 0, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    upload.buffer(mPlaceholderSh, zeros(IblIrradianceShPass::kBytes));
    upload.image(mPlaceholderEquirect, zeros(16), 0, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    upload.buffer(mPlaceholderTexels, zeros(16));
    upload.submitAndWait();
}

IblHandles IblSet::declare(PassBuilder& builder, const IblHandles* ibl, VkPipelineStageFlags2 stages) {
    if (!ibl) return {};
    const IblHandles& in = *ibl;
    IblHandles out;
    if (in.specular.valid()) out.specular = builder.sample(in.specular);
    if (in.irradianceCube.valid()) out.irradianceCube = builder.sample(in.irradianceCube);
    if (in.sh.valid()) out.sh = builder.read(in.sh, Usage::Uniform, stages);
    if (in.lut.valid()) out.lut = builder.sample(in.lut);
    if (in.referenceEquirect.valid()) out.referenceEquirect = builder.sample(in.referenceEquirect);
    if (in.referenceTexels.valid()) out.referenceTexels = builder.read(in.referenceTexels, Usage::StorageRead, stages);
    return out;
}

VkDescriptorSet IblSet::write(const PassContext& ctx, const vk::Program& program, const IblHandles& d) const {
    const VkImageLayout placeholder = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const auto image = [&](vk::DescriptorWriter& writer, const char* name, TextureId handle, const vk::Image& fallback,
                           VkSampler sampler) {
        if (handle.valid()) writer.image(name, ctx.view(handle), ctx.layout(handle), sampler);
        else writer.image(name, fallback.view(), placeholder, sampler);
    };
    vk::DescriptorWriter writer(program, 2);
    image(writer, "specularCube", d.specular, mPlaceholderCube, mTrilinear.get());
    image(writer, "irradianceCube", d.irradianceCube, mPlaceholderCube, mTrilinear.get());
    image(writer, "brdfLut", d.lut, mPlaceholderLut, mTrilinear.get());
    writer.buffer("IrradianceSh", d.sh.valid() ? ctx.buffer(d.sh) : mPlaceholderSh.handle());
    // The ground truth's inputs: declared by its program only.
    if (program.declares(2, "referenceEquirect")) {
        image(writer, "referenceEquirect", d.referenceEquirect, mPlaceholderEquirect, mNearest.get());
        writer.buffer("ReferenceTexels", d.referenceTexels.valid() ? ctx.buffer(d.referenceTexels) : mPlaceholderTexels.handle());
    }
    return writer.commit(ctx.context(), ctx.descriptors());
}

}  // namespace candela::passes
