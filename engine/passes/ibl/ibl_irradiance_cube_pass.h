#pragma once
// IBL precompute pass "ibl_irradiance_cube" (compute): diffuse irradiance E(n)/π as a small RGBA16F
// cube, by cosine importance sampling with filtered importance sampling from the float environment
// cube (shaders/ibl_filter_cube.comp, equal weights).

#include "graph/render_graph.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"

namespace candela::passes {

class IblIrradianceCubePass {
public:
    explicit IblIrradianceCubePass(vk::Context& context);

    // Builds and uploads the sample table (waits). Call before add() whenever the arguments change;
    // precondition: the GPU no longer uses the previous table.
    void prepare(uint32_t samples, uint32_t sourceFaceSize, uint32_t sourceMips, bool filtered,
                 float lodBias);

    struct Inputs {
        graph::TextureId source;  // float environment cube
        // RGBA16F cube, one mip, contents discarded; an imported one needs its mip view bound.
        graph::TextureId irradiance;
        float sourceScale = 1.0f;  // the source holds radiance × sourceScale (IblCubemapPass::Inputs::cubeScale)
        graph::BufferId bright;    // the texels the source was clamped at (ibl_maps::BrightTexels::buffer)
    };
    // Adds the pass; returns the irradiance cube's new version. The pass object must outlive execution.
    graph::TextureId add(graph::RenderGraph& graph, const Inputs& inputs) const;

private:
    vk::Context& mContext;
    vk::Pipeline mPipeline;
    vk::Sampler mSampler;  // trilinear
    vk::Buffer mTable;
    vk::Buffer mLobe;  // lobeTable(FilterLobe::Cosine)
    uint32_t mSampleCount = 0;
    float mInverseWeight = 0.0f;
};

}  // namespace candela::passes
