#pragma once
// IBL precompute pass "ibl_prefilter" (compute): mips 1… of the specular cube — mip m is the
// environment convolved with the GGX lobe of perceptual roughness m / (levels − 1), by GGX
// importance sampling with filtered importance sampling from the float cube's mips
// (shaders/ibl_filter_cube.comp weighted by n·l; samples from
// engine/passes/ibl/ibl_sample_tables.h). Mip 0 (roughness 0, the environment itself) is written by
// the cubemap pass. With Lobe::Charlie it is "ibl_sheen_prefilter": every mip of the sheen cube
// (KHR_materials_sheen), mip m the environment convolved with the sheen lobe of roughness m /
// (levels − 1), sampled exactly as that lobe (equal weights); mip 0 too, since the sheen has no
// mirror limit.

#include "graph/render_graph.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"

#include <vector>

namespace candela::passes {

class IblPrefilterPass {
public:
    enum class Lobe { Ggx, Charlie };
    explicit IblPrefilterPass(vk::Context& context, Lobe lobe = Lobe::Ggx);

    // Builds and uploads the sample tables of every mip (waits for the upload): `samples` at mip 1,
    // 4× more at each coarser mip, at most kMaxSamples. Call before add() whenever the arguments
    // change; precondition: the GPU no longer uses the previous tables.
    void prepare(uint32_t levels, uint32_t samples, uint32_t sourceFaceSize, uint32_t sourceMips, bool filtered,
                 float lodBias);

    struct Inputs {
        graph::TextureId source;    // float environment cube (sampled with all its mips)
        // RGBA16F cube, one mip per level (GGX: mip 0 already written); an imported one needs its
        // mip views bound.
        graph::TextureId specular;
        float sourceScale = 1.0f;  // the source holds radiance × sourceScale (IblCubemapPass::Inputs::cubeScale)
        // The texels the source was clamped at (ibl_maps::BrightTexels::buffer, storage): added per texel
        // with the lobe of each mip.
        graph::BufferId bright;
    };
    static constexpr uint32_t kMaxSamples = 4096;

    // Adds the pass; returns the specular cube's new version. The pass object must outlive execution.
    graph::TextureId add(graph::RenderGraph& graph, const Inputs& inputs) const;

private:
    uint32_t firstMip() const { return mLobe == Lobe::Ggx ? 1u : 0u; }
    struct MipRange {
        uint32_t first, count;
        float inverseWeight;
    };
    vk::Context& mContext;
    Lobe mLobe;
    vk::Pipeline mPipeline;
    vk::Sampler mSampler;  // bilinear within the nearest mip: filtered importance sampling picks the mip
    vk::Buffer mTable;
    vk::Buffer mLobes;              // lobeTable of every mip, CANDELA_IBL_LOBE_TABLE_SIZE each, index = mip
    std::vector<MipRange> mRanges;  // index = mip; mip 0 unused
};

}  // namespace candela::passes
