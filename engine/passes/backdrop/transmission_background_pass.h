#pragma once
// Pass "transmission_background" (compute): what lies behind the transmissive draws — the opaque
// image (forward pass and skybox) copied into an RGBA16F texture of the same size with a full mip
// chain, each mip the 2×2 box of the one above (shaders/transmission_background.comp). The
// transmissive draws read it at the mip of their roughness (KHR_materials_transmission's blur).
// Added only when a transmissive material is in the frame (Renderer).

#include "graph/render_graph.h"
#include "vk/pipeline_cache.h"
#include "vk/sampler.h"

namespace candela::passes {

class TransmissionBackgroundPass {
public:
    explicit TransmissionBackgroundPass(vk::Context& context);

    // Adds the pass reading `hdr` (sampled) and writing a new transient "transmission_background".
    // Returns it. The pass object must outlive execution.
    graph::TextureId add(graph::RenderGraph& graph, graph::TextureId hdr);

    static constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    // Mips of a width × height background: down to 1 × 1.
    static uint32_t mipLevels(uint32_t width, uint32_t height);

private:
    vk::Context& mContext;
    vk::PipelineCache<int> mPipelines;  // the one pipeline, built at the first add()
    vk::Sampler mSampler;  // bilinear, clamp to edge, mip 0 of the bound view
};

}  // namespace candela::passes
