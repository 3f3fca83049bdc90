#include "passes/ibl/ibl_cubemap_pass.h"

#include "passes/recording/compute.h"
#include "shared/ibl.h"

#include <algorithm>
#include <cmath>

namespace candela::passes {

using namespace graph;

namespace {
bool halfCube(const vk::Context& context) { return context.choices().floatCube == VK_FORMAT_R16G16B16A16_SFLOAT; }
}  // namespace

float IblCubemapPass::halfFloatScale(float brightest) {
    if (!(brightest > CANDELA_HALF_MAX) || !std::isfinite(brightest)) return 1.0f;
    return std::exp2(-std::ceil(std::log2(brightest / CANDELA_HALF_MAX)));
}

float IblCubemapPass::floatCubeScale(const vk::Context& context, float brightest) {
    return halfCube(context) ? halfFloatScale(brightest) : 1.0f;
}

IblCubemapPass::IblCubemapPass(vk::Context& context)
    : mResample(vk::Pipeline::compute(context, halfCube(context) ? "ibl_cubemap_half.comp" : "ibl_cubemap.comp")),
      mDownsample(vk::Pipeline::compute(context, halfCube(context) ? "ibl_cube_downsample_half.comp"
                                                                   : "ibl_cube_downsample.comp")),
      mSampler(vk::createSampler(context, vk::kNearestSampler)),
      mBorders(context) {}

uint32_t IblCubemapPass::supersampleFactor(uint32_t faceSize, uint32_t equirectWidth, uint32_t equirectHeight) {
    // Solid angle of a cube texel (4π / 6N², on average) over an equirect texel at the equator (2π² / WH).
    const double ratio = double(equirectWidth) * equirectHeight / (3.0 * 3.14159265358979 * double(faceSize) * faceSize);
    return std::clamp(static_cast<uint32_t>(std::ceil(std::sqrt(ratio))), 1u, 8u);
}

IblCubemapPass::Outputs IblCubemapPass::add(RenderGraph& graph, const Inputs& in) const {
    struct Data {
        TextureId equirect;
        TextureId cube;
        TextureId specular;
    };
    const Data& data = graph.addPass<Data>(
        "ibl_cubemap", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            d.equirect = builder.sample(in.equirect);
            d.cube = builder.write(in.cube, Usage::StorageReadWrite, WriteMode::Discard);
            d.specular = builder.write(in.specular, Usage::StorageWrite, WriteMode::Discard);
        },
        [this, cubeScale = in.cubeScale, equirectInverseScale = 1.0f / in.equirectScale,
         clampLuminance = in.clampLuminance](const Data& d, PassContext& ctx) {
            const TextureDesc& equirect = ctx.desc(d.equirect);
            const TextureDesc& cube = ctx.desc(d.cube);
            const shading::IblCubemapPush push{
                .faceSize = cube.width,
                .supersample = supersampleFactor(cube.width, equirect.width, equirect.height),
                .cubeScale = cubeScale,
                .equirectInverseScale = equirectInverseScale,
                .clampLuminance = clampLuminance};
            const VkDescriptorSet set =
                vk::DescriptorWriter(mResample.program(), 0)
                    .image("equirect", ctx.view(d.equirect), ctx.layout(d.equirect), mSampler.get())
                    .image("cubeMip0", ctx.mipView(d.cube, 0), ctx.layout(d.cube))
                    .image("specularMip0", ctx.mipView(d.specular, 0), ctx.layout(d.specular))
                    .commit(ctx.context(), ctx.descriptors());
            const uint32_t groups = groupCount(cube.width, CANDELA_IBL_GROUP);
            dispatchCompute(ctx, mResample, set, &push, sizeof(push), groups, groups, 6);
            for (uint32_t mip = 1; mip < cube.mipLevels; ++mip) {
                computeWriteToReadBarrier(ctx.cmd());
                const shading::IblDownsamplePush down{.dstFaceSize = std::max(cube.width >> mip, 1u)};
                const VkDescriptorSet mipSet = vk::DescriptorWriter(mDownsample.program(), 0)
                                                   .image("srcMip", ctx.mipView(d.cube, mip - 1), ctx.layout(d.cube))
                                                   .image("dstMip", ctx.mipView(d.cube, mip), ctx.layout(d.cube))
                                                   .commit(ctx.context(), ctx.descriptors());
                const uint32_t mipGroups = groupCount(down.dstFaceSize, CANDELA_IBL_GROUP);
                dispatchCompute(ctx, mDownsample, mipSet, &down, sizeof(down), mipGroups, mipGroups, 6);
            }
            mBorders.record(ctx, ctx.view(d.cube), ctx.layout(d.cube));
        });
    return {data.cube, data.specular};
}

}  // namespace candela::passes
