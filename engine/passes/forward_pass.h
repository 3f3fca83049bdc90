#pragma once
// Forward pass (graphics): draws a GpuScene into an HDR target (RGBA16F, alpha = coverage,
// premultiplied) with a reverse-Z depth buffer — opaque and alpha-masked draws first, then
// alpha-blended ones sorted back to front. Each draw uses a pipeline variant chosen by
// specialization constants, so what a draw does not use costs nothing.

#include "graph/render_graph.h"
#include "passes/debug_view.h"
#include "shader/parameter_registry.h"
#include "ibl/ibl_maps.h"
#include "shared/ibl.h"
#include "scene/camera.h"
#include "scene/gpu_scene.h"
#include "vk/descriptors.h"
#include "vk/pipeline.h"

#include <map>
#include <optional>
#include <string_view>
#include <memory>
#include <string>
#include <vector>

namespace candela::passes {

enum class ShadingModel : uint32_t { Pbr = 0, PbrSchlickGgx = 1, BlinnPhong = 2 };


class ForwardPass {
public:
    explicit ForwardPass(vk::Context& context);

    // Binds the scene's buffers and textures into persistent descriptor sets. Call once per
    // GpuScene; precondition: the GPU no longer uses the previous scene's sets.
    void setScene(const scene::GpuScene& scene);

    struct Output {
        graph::TextureId hdr;
        graph::TextureId depth;
    };
    // Writes the image-based-lighting descriptor set (set 2) from `maps` (its placeholders when it
    // has no environment). Call at start and whenever maps.setEnvironment returned true;
    // precondition: the GPU no longer uses the previous set.
    void setIblMaps(const ibl::IblMaps& maps);

    // Image-based lighting of one frame: the imported maps to read and how to read them.
    struct Ibl {
        ibl::IblMaps::GraphMaps maps;
        shading::IblParams params;
        bool irradianceSh = true;
        bool multiscatter = true;
        // > 0: ground truth instead of the split sum (`ibl-report`): the reflectance equation
        // integrated per pixel with this many samples per lobe from the specular cube's mip 0.
        uint32_t referenceSamples = 0;
    };
    // Adds the pass drawing the current scene as seen from `view`, lit by the scene's lights and,
    // when `ibl` is given, the environment. Returns the written targets.
    // With `parameters`, the user's values for the per-frame push constants apply ("forward", "Push").
    Output add(graph::RenderGraph& graph, uint32_t width, uint32_t height, const scene::ViewSetup& view,
               ShadingModel model, const Ibl* ibl = nullptr, shader::ParameterRegistry* parameters = nullptr,
               DebugView debugView = DebugView::None);
    // The reflection of the forward shaders (every variant shares the layout).
    const shader::ShaderReflection& reflection() { return pipeline(Variant{}).program().reflection(); }

    // What the last add() used and left out, one line each, for `--explain`.
    const std::vector<std::string>& explanation() const { return mExplanation; }

    static constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

private:
    struct Variant {
        bool normalMap = false;
        bool lights = false;
        bool unlit = false;
        bool alphaMask = false;
        bool blend = false;
        ShadingModel model = ShadingModel::Pbr;
        bool ibl = false;
        bool irradianceSh = true;
        bool multiscatter = true;
        uint32_t referenceSamples = 0;
        DebugView debugView = DebugView::None;
        auto operator<=>(const Variant&) const = default;
        std::string name() const;
    };
    struct DrawItem {
        uint32_t draw;
        const vk::Pipeline* pipeline;
        float depth;  // view distance, for sorting blended draws
    };
    const vk::Pipeline& pipeline(const Variant& variant);
    Variant variantOf(const scene::Draw& draw, ShadingModel model, const Ibl* ibl, DebugView debugView) const;

    vk::Context& mContext;
    std::map<Variant, vk::Pipeline> mPipelines;
    const scene::GpuScene* mScene = nullptr;
    std::unique_ptr<vk::DescriptorAllocator> mSets;
    VkDescriptorSet mSceneSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> mMaterialSets;
    std::unique_ptr<vk::DescriptorAllocator> mIblSets;
    VkDescriptorSet mIblSet = VK_NULL_HANDLE;
    std::vector<std::string> mExplanation;
};

}  // namespace candela::passes
