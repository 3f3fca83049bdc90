#pragma once
// Pattern pass (compute): writes the procedural HDR test pattern (shaders/shared/pattern.h) into a
// new RGBA16F transient: the frame of a render without a scene (pattern → encode), which the GPU
// tests compare with a CPU evaluation of the same function.

#include "graph/render_graph.h"
#include "vk/pipeline.h"

namespace candela::passes {

class PatternPass {
public:
    explicit PatternPass(vk::Context& context);

    // Adds the pass to `graph`; returns the written HDR texture (width × height, RGBA16F).
    // The pass object must outlive the graph's execution.
    graph::TextureId add(graph::RenderGraph& graph, uint32_t width, uint32_t height, float exposure) const;

    static constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

private:
    vk::Pipeline mPipeline;
};

}  // namespace candela::passes
