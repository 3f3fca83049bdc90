#pragma once
// BRDF probe pass (compute): evaluates the forward pass's BRDF (shaders/shared/brdf.h) — or, as the
// layered probe, the BRDF with a material layer (shaders/shared/brdf_layers.h) — once per
// combination of the probe grid (shaders/shared/brdf_probe.h) into a new RGBA32F transient, so that
// tests can compare the GPU's own evaluation with a double-precision CPU reference.

#include "graph/render_graph.h"
#include "shared/brdf_probe.h"
#include "vk/pipeline.h"

namespace candela::passes {

class BrdfProbePass {
public:
    enum class Brdf { Core, Layers };
    explicit BrdfProbePass(vk::Context& context, Brdf brdf = Brdf::Core);

    // Adds the pass to `graph`; returns the written probe image (kWidth × kHeight, kFormat). Texel
    // (x, y) holds brdfTimesCosine(shading::brdfProbeSample({x, y})) · params.intensity in rgb (for
    // Brdf::Layers: with the specular layer of `params`) and its linear index y · kWidth + x in
    // alpha. The pass object must outlive the graph's execution.
    graph::TextureId add(graph::RenderGraph& graph, const shading::BrdfProbeParams& params) const;

    static constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    static constexpr uint32_t kWidth = CANDELA_BRDF_PROBE_WIDTH;
    static constexpr uint32_t kHeight = CANDELA_BRDF_PROBE_HEIGHT;

private:
    vk::Pipeline mPipeline;
};

}  // namespace candela::passes
