#pragma once
// IBL precompute pass "ibl_cubemap" (compute): resamples the equirectangular environment into mip 0
// of the float environment cube, its bright texels clamped (ibl_maps/bright_texels.h), and of the
// specular cube as it is (roughness 0 is the environment itself),
// then box-filters every further float-cube mip from the one above
// (shaders/ibl_cubemap.comp, ibl_cube_downsample.comp). The cube's mips are what the prefilter and
// irradiance passes read with filtered importance sampling.

#include "graph/render_graph.h"
#include "passes/ibl/ibl_cube_borders.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"

#include <limits>

namespace candela::passes {

class IblCubemapPass {
public:
    explicit IblCubemapPass(vk::Context& context);

    struct Inputs {
        graph::TextureId equirect;  // equirectangular map (half floats), rotation 0: radiance × equirectScale
        // Float cube (DeviceChoices::floatCube), all mips written (contents discarded); an imported
        // one needs its mip views bound.
        graph::TextureId cube;
        graph::TextureId specular;  // RGBA16F cube of the same face size; mip 0 written (contents discarded)
        // The float cube holds radiance × cubeScale (a power of two: exact): below 1 when a
        // half-float cube (floatCubeScale) would overflow. The specular cube holds radiance.
        float cubeScale = 1.0f;
        float equirectScale = 1.0f;  // halfFloatScale of the environment
        // The float cube's source texels are clamped to this luminance, in the equirect's units
        // (radiance × equirectScale): ibl_maps::BrightTexels::threshold. Infinity: none.
        float clampLuminance = std::numeric_limits<float>::infinity();
    };
    struct Outputs {
        graph::TextureId cube;
        graph::TextureId specular;
    };
    // Adds the pass; returns the new versions. The pass object must outlive execution.
    Outputs add(graph::RenderGraph& graph, const Inputs& inputs) const;

    // k of the k×k taps per cube texel: enough that the taps' spacing matches the source texels.
    static uint32_t supersampleFactor(uint32_t faceSize, uint32_t equirectWidth, uint32_t equirectHeight);
    // Inputs::cubeScale for an environment whose brightest texel is `brightest`: 1 with an RGBA32F
    // float cube; with the RGBA16F fallback, the largest power of two ≤ 1 that keeps it under the
    // half-float maximum (dark texels then lose precision below 2^-24 × 1/scale instead of the
    // brightest overflowing).
    static float floatCubeScale(const vk::Context& context, float brightest);
    // The largest power of two ≤ 1 that keeps `brightest` × it under the half-float maximum.
    static float halfFloatScale(float brightest);

private:
    vk::Pipeline mResample;
    vk::Pipeline mDownsample;
    vk::Sampler mSampler;  // for the equirect's descriptor (the shader reads it with texelFetch)
    CubeBorderDraw mBorders;
};

}  // namespace candela::passes
