#pragma once
// Skybox pass "skybox" (graphics): draws the environment behind the scene into the HDR target —
// a full-screen triangle at the far plane, depth-tested against the forward pass's depth (read
// only), so only uncovered pixels shade, and blended under what is there, so partly covered
// (alpha-blended) pixels keep their coverage (shaders/skybox.frag). Reads the specular cube at the
// blur level's mip.

#include "graph/render_graph.h"
#include "passes/drawing/draw_target.h"
#include "shader/parameter_registry.h"
#include "scene/camera.h"
#include "shared/ibl.h"
#include "vk/pipeline_cache.h"
#include "vk/sampler.h"

#include <tuple>

namespace candela::passes {

class SkyboxPass {
public:
    explicit SkyboxPass(vk::Context& context);

    struct Inputs {
        // As the forward pass left it (depth: 0 = nothing drawn). Without a depth (the visibility
        // path's single-sample image over a multisampled depth) the sky is drawn under every pixel:
        // covered ones (coverage 1) take none of it.
        DrawTarget target;
        graph::TextureId specular;  // specular cube (IblHandles::specular)
        shading::IblParams params;  // skyboxLod: the mip shown
    };
    // Adds the pass drawing into the target's colour (and resolving it, with MSAA); returns the
    // target's new versions. The pass object must outlive execution.
    // With `parameters`, the user's values for its push constants apply ("skybox", "Push").
    DrawTarget add(graph::RenderGraph& graph, const scene::ViewSetup& view, const Inputs& inputs,
                         shader::ParameterRegistry* parameters = nullptr);

private:
    vk::Context& mContext;
    // Pipelines by (colour format, depth format, samples) of the targets.
    vk::PipelineCache<std::tuple<VkFormat, VkFormat, uint32_t>> mPipelines;
    vk::Sampler mSampler;  // trilinear
};

}  // namespace candela::passes
