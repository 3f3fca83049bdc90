#pragma once
// IBL precompute pass "ibl_cubemap" (compute): resamples the equirectangular environment into mip 0
// of the float environment cube (and of the specular cube: roughness 0 is the environment itself),
// then box-filters every further float-cube mip from the one above
// (shaders/ibl_cubemap.comp, ibl_cube_downsample.comp). The cube's mips are what the prefilter and
// irradiance passes read with filtered importance sampling.

#include "graph/render_graph.h"
#include "vk/pipeline.h"

#include <vector>

namespace candela::passes {

class IblCubemapPass {
public:
    explicit IblCubemapPass(vk::Context& context);

    struct Inputs {
        graph::TextureId equirect;  // RGBA32F equirectangular map, rotation 0
        VkSampler equirectSampler;  // any (read with texelFetch)
        uint32_t equirectWidth, equirectHeight;
        graph::TextureId cube;      // RGBA32F cube, faceSize, all mips written (contents discarded)
        uint32_t faceSize;
        // mipViews[m]: a 2D-array view of mip m, 6 layers (storage). Owned by the caller; alive
        // until the graph has executed.
        std::vector<VkImageView> mipViews;
        graph::TextureId specular;  // RGBA16F cube of the same face size; mip 0 written (contents discarded)
        VkImageView specularMip0View;  // 2D-array storage view of its mip 0 (caller-owned)
    };
    struct Outputs {
        graph::TextureId cube;
        graph::TextureId specular;
    };
    // Adds the pass; returns the new versions. The pass object must outlive execution.
    Outputs add(graph::RenderGraph& graph, const Inputs& inputs) const;

    // k of the k×k taps per cube texel: enough that the taps' spacing matches the source texels.
    static uint32_t supersampleFactor(uint32_t faceSize, uint32_t equirectWidth, uint32_t equirectHeight);

private:
    vk::Pipeline mResample;
    vk::Pipeline mDownsample;
};

}  // namespace candela::passes
