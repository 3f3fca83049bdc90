#pragma once
// Tonemap pass (graphics): exposure, tone mapping operator, background compositing and sRGB
// encoding of the HDR frame into an 8-bit target (full-screen triangle).

#include "graph/render_graph.h"
#include "shader/parameter_registry.h"
#include "vk/pipeline_cache.h"
#include "vk/sampler.h"

#include <glm/glm.hpp>

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace candela::passes {

enum class Tonemap : uint32_t { PbrNeutral = 0, Aces = 1, Agx = 2, Reinhard = 3, Linear = 4 };

// Parses "pbr-neutral", "aces", "agx", "reinhard", "linear"; nullopt for anything else.
std::optional<Tonemap> parseTonemap(std::string_view name);
const char* tonemapName(Tonemap op);

struct TonemapSettings {
    float exposureEv = 0.0f;  // exposure in stops: radiance × 2^EV
    Tonemap op = Tonemap::PbrNeutral;
    // Solid background in linear display RGB; nullopt keeps transparency (alpha = coverage).
    std::optional<glm::vec3> background;
    bool dither = false;
};

class TonemapPass {
public:
    explicit TonemapPass(vk::Context& context);

    // Adds the pass: samples `hdr` (RGBA16F, alpha = coverage), writes all of `target` (same size;
    // an _SRGB format is encoded by the hardware, a UNORM one by the shader). Returns its new version.
    // With `parameters`, the user's values for its push constants apply ("tonemap", "Push").
    graph::TextureId add(graph::RenderGraph& graph, graph::TextureId hdr, graph::TextureId target,
                         const TonemapSettings& settings, shader::ParameterRegistry* parameters = nullptr);

private:
    vk::Context& mContext;
    // Pipelines by target format and specialization (operator, sRGB encode, dither, background).
    vk::PipelineCache<std::pair<VkFormat, std::vector<uint32_t>>> mPipelines;
    vk::Sampler mSampler;
};

}  // namespace candela::passes
