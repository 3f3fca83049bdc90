#pragma once
// Calibration pass (graphics): see shaders/calibration.frag.glsl. Benchmarks run it in the same
// process at the same resolution and report their figures as ratios to its time. Its textures are
// small constants created at its first add().

#include "graph/render_graph.h"
#include "vk/image.h"
#include "vk/pipeline_cache.h"
#include "vk/sampler.h"

namespace candela::passes {

class CalibrationPass {
public:
    explicit CalibrationPass(vk::Context& context);

    // Adds the pass writing a new exported RGBA16F texture of width × height.
    graph::TextureId add(graph::RenderGraph& graph, uint32_t width, uint32_t height);

private:
    void createResources();  // the sampler and the constant textures (waits for their upload)

    vk::Context& mContext;
    vk::PipelineCache<int> mPipelines;  // the one pipeline, built at the first add()
    vk::Sampler mSampler;
    vk::Image mIrradiance;   // 8×8 cube, RGBA16F
    vk::Image mPrefiltered;  // 32×32 cube, 6 mips, RGBA16F
    vk::Image mLut;          // 32×32, RG16F
};

}  // namespace candela::passes
