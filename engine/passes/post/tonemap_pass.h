#pragma once
// Tonemap pass (graphics): exposure, tone mapping operator, background compositing and sRGB
// encoding of the HDR frame into an 8-bit target (full-screen triangle) — with the sky composited
// under the image first when it is given (tonemap_sky.frag), instead of a skybox pass: one pass
// over the image fewer where nothing reads the HDR image with its sky.

#include "core/worker_pool.h"
#include "graph/render_graph.h"
#include "options/tonemap_operator.h"
#include "shader/parameter_registry.h"
#include "shared/tonemap.h"
#include "vk/pipeline_cache.h"
#include "vk/sampler.h"

#include <glm/glm.hpp>

#include <optional>
#include <utility>
#include <vector>

namespace candela::passes {

struct TonemapSettings {
    float exposureEv = 0.0f;  // exposure in stops: radiance × 2^EV
    options::Tonemap op = options::Tonemap::PbrNeutral;
    // Solid background in linear display RGB; nullopt keeps transparency (alpha = coverage).
    std::optional<glm::vec3> background;
    bool dither = false;
};

class TonemapPass {
public:
    explicit TonemapPass(vk::Context& context);

    // Where a pass draws the sky: not at all; under every pixel; or only where nothing was drawn
    // (the scene's depth still 0, the far plane's: the pass draws twice, the covered pixels
    // without the sky and the others with it, each depth-tested, so that the rasterizer leaves the
    // sky's program out of covered blocks, which on llvmpipe a branch would not) — there reading
    // the image under it, or not where it holds its clear value (no blended draw, which leaves the
    // depth as it was, and no geometry at a finite far plane: FramePlan::skyOverClearImage).
    enum class SkyDraw : uint8_t { None, Everywhere, WhereUncovered, WhereUncoveredImageClear };

    // Adds the pass: samples `hdr` (RGBA16F, alpha = coverage), writes all of `target` (same size;
    // an _SRGB format is encoded by the hardware, a UNORM one by the shader). Returns its new version.
    // With `parameters`, the user's values for its push constants apply ("tonemap", "Push").
    // With `sky`, the sky (the specular cube, shared/sky.glsl) is composited under `hdr` first, as
    // its `draw` says (not None); where uncovered, `depth` is the scene's reverse-Z depth at the
    // target's size, one sample (else unused). Throws std::logic_error for such a draw without it.
    struct Sky {
        graph::TextureId specular;
        shading::TonemapSky params;
        SkyDraw draw = SkyDraw::Everywhere;
        graph::TextureId depth;
    };
    graph::TextureId add(graph::RenderGraph& graph, graph::TextureId hdr, graph::TextureId target,
                         const TonemapSettings& settings, shader::ParameterRegistry* parameters = nullptr,
                         const Sky* sky = nullptr);

    // Queues on `workers` the builds of the pipelines add() takes for a `target` of `targetFormat`
    // with `settings` and `sky` (the depth where uncovered: kDepthFormat), so that a first frame
    // finds them built (PipelineCache::prepare). Nothing for those built or queued already.
    // Precondition: `workers` outlives this pass's builds (PipelineCache::prepare).
    void prepare(WorkerPool& workers, VkFormat targetFormat, const TonemapSettings& settings, SkyDraw sky);
    // Waits for the builds prepare() queued (benchmarks).
    void finishBuilds() { mPipelines.finish(); }
    // The format of the target the last add() wrote (a presentable image's, or a capture's); none
    // before the first.
    std::optional<VkFormat> lastTargetFormat() const { return mLastTargetFormat; }

private:
    // A pipeline of the pass: its key in mPipelines and how it is built.
    struct Variant {
        std::pair<VkFormat, std::vector<uint32_t>> key;
        const char* fragment;
        vk::GraphicsPipelineDesc desc;
    };
    // The pipelines add() draws with: where uncovered, the covered pixels' then the sky's, else the
    // one. `depthFormat`: the scene's depth, for WhereUncovered.
    static std::vector<Variant> variants(VkFormat targetFormat, const TonemapSettings& settings, SkyDraw sky,
                                         VkFormat depthFormat);
    // The pipeline of `variant`.
    static vk::Pipeline build(vk::Context& context, const Variant& variant);

    vk::Context& mContext;
    // Pipelines by target format and specialization (operator, sRGB encode, dither, background; sky).
    vk::PipelineCache<std::pair<VkFormat, std::vector<uint32_t>>> mPipelines;
    vk::Sampler mSampler;     // nearest (the HDR image)
    vk::Sampler mTrilinear;   // the specular cube
    std::optional<VkFormat> mLastTargetFormat;
};

}  // namespace candela::passes
