#pragma once
// IBL precompute pass "ibl_irradiance_sh" (compute): diffuse irradiance as 9 spherical-harmonic
// coefficients projected from one mip of the float environment cube (shaders/ibl_irradiance_sh.comp).
// The buffer holds 9 vec4 (rgb used), convolved with the clamped cosine and divided by π.

#include "graph/render_graph.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"

namespace candela::passes {

class IblIrradianceShPass {
public:
    explicit IblIrradianceShPass(vk::Context& context);

    struct Inputs {
        graph::TextureId source;  // float environment cube (face size a power of two)
        uint32_t projectedFaceSize;  // face size of the mip projected (a power of two ≤ sourceFaceSize)
        graph::BufferId coefficients;  // ≥ kBytes, storage usage; contents discarded
        float sourceScale = 1.0f;      // the source holds radiance × sourceScale (IblCubemapPass::Inputs::cubeScale)
        graph::BufferId bright;        // the texels the source was clamped at (ibl_maps::BrightTexels::buffer)
    };
    // Adds the pass; returns the buffer's new version. The pass object must outlive execution.
    graph::BufferId add(graph::RenderGraph& graph, const Inputs& inputs) const;

    static constexpr VkDeviceSize kBytes = 9 * 4 * sizeof(float);

private:
    vk::Pipeline mPipeline;
    vk::Sampler mSampler;  // trilinear
};

}  // namespace candela::passes
