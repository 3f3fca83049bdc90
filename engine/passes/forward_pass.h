#pragma once
// Forward pass (graphics): draws a GpuScene into an HDR target (RGBA16F, alpha = coverage,
// premultiplied) with a reverse-Z depth buffer — opaque and alpha-masked draws first, then
// alpha-blended ones sorted back to front. Each draw uses a pipeline variant chosen by
// specialization constants, so what a draw does not use costs nothing. Draws of transmissive
// materials (KHR_materials_transmission) see what lies behind them: when a frame has one, "forward"
// draws the opaque draws only and addTransmissive() adds "forward_transmission", which draws the
// transmissive and the blended draws back to front over the opaque image, reading its copy
// (TransmissionBackgroundPass).

#include "graph/render_graph.h"
#include "passes/debug_view.h"
#include "passes/draw_selection.h"
#include "passes/draw_target.h"
#include "passes/forward_ibl_set.h"
#include "passes/forward_layer_set.h"
#include "passes/ibl_handles.h"
#include "shader/parameter_registry.h"
#include "shared/ibl.h"
#include "shared/scene_data.h"
#include "scene/camera.h"
#include "scene/gpu_scene.h"
#include "vk/descriptors.h"
#include "vk/pipeline_cache.h"

#include <climits>
#include <functional>
#include <optional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace candela::passes {

enum class ShadingModel : uint32_t { Pbr = 0, PbrSchlickGgx = 1, BlinnPhong = 2 };

class ForwardPass {
public:
    explicit ForwardPass(vk::Context& context);

    // Binds the scene's buffers and textures into persistent descriptor sets (sets 0 and 1). The
    // scene is uploaded once and changes only while the GPU is idle, so it is no graph resource.
    // Call once per GpuScene; precondition: the GPU no longer uses the previous scene's sets.
    void setScene(const scene::GpuScene& scene);

    using Output = DrawTarget;

    // Image-based lighting of one frame: the maps to read (set 2, written every frame from what the
    // pass context resolves them to) and how to read them.
    struct Ibl {
        IblHandles maps;
        shading::IblParams params;
        bool irradianceSh = true;
        bool multiscatter = true;
        // > 0: ground truth instead of the split sum (`ibl-report`): the reflectance equation
        // integrated per pixel with this many samples per lobe from the specular cube's mip 0.
        uint32_t referenceSamples = 0;
    };
    // An animated scene's draws in this frame's pose: where each is (one per scene draw, same
    // order; hidden ones are skipped) and the buffer holding their shading::DrawData, which the
    // pass reads instead of the scene's static draw buffer (set 0 is then written per frame).
    struct PosedDraws {
        std::span<const scene::Draw> draws;
        graph::BufferId data;
        graph::BufferId lights;  // this frame's light data when a light moves with the pose; else invalid
    };
    // This frame's deformed vertices (the skin_morph pass's output) and, per scene draw, the
    // vertex offset that maps its indices into them (kRestVertices: drawn from the scene's own).
    struct DeformedVertices {
        graph::BufferId vertices;
        std::vector<int32_t> vertexOffset;
    };
    static constexpr int32_t kRestVertices = INT32_MIN;
    // Adds the pass drawing the current scene as seen from `view`, lit by the scene's lights and,
    // when `ibl` is given, the environment; posed by `posed` and drawn from `deformed` vertices
    // where given; the layered program reads `layerMaps` (the sheen LUT and cube) where given.
    // `selection` culls draws and picks their levels of detail; `shading` turns specular
    // anti-aliasing on or off. Creates the targets at `size` (MSAA at size.samples > 1, with
    // alpha to coverage for alpha-masked draws) and returns them as written.
    // With `parameters`, the user's values for the per-frame push constants apply ("forward", "Push").
    Output add(graph::RenderGraph& graph, const DrawTargetSize& size, const scene::ViewSetup& view,
               ShadingModel model, const Ibl* ibl = nullptr, shader::ParameterRegistry* parameters = nullptr,
               DebugView debugView = DebugView::None, const PosedDraws* posed = nullptr,
               const DeformedVertices* deformed = nullptr, const LayerMaps* layerMaps = nullptr,
               const DrawSelection& selection = {}, const ShadingOptions& shading = {});
    // Whether the last add() left transmissive draws (and the blended ones) for addTransmissive().
    bool hasTransmissiveDraws() const { return !mBehind.empty(); }
    // Adds "forward_transmission": the draws the last add() left, over its `opaque` targets (after
    // whatever drew into them since, e.g. the skybox), reading `background` (the opaque image with
    // its mips) behind the transmissive ones. Returns the targets' new versions. Precondition:
    // hasTransmissiveDraws().
    Output addTransmissive(graph::RenderGraph& graph, const Output& opaque, graph::TextureId background);
    // The reflection of the forward shaders without layers (every variant shares sets 0 and 2 and
    // the push constants; the layered program adds to set 1).
    const shader::ShaderReflection& reflection() { return pipeline(Variant{}).program().reflection(); }
    // The reflection of the layered program (its MaterialLayers buffer), when the current scene
    // has a material with a layer; null otherwise.
    const shader::ShaderReflection* layeredReflection();

    // What the last add() selected, and (once the frame is recorded) the state changes of both
    // of its draw passes.
    const DrawStats& drawStats() const { return mStats; }
    // What the last add() used and left out, one line each, for `--explain`.
    const std::vector<std::string>& explanation() const { return mExplanation; }

    static constexpr VkFormat kHdrFormat = passes::kHdrFormat;
    static constexpr VkFormat kDepthFormat = passes::kDepthFormat;

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
        // KHR_materials_* layers the material uses (scene::MaterialLayer bits): non-zero selects the
        // layered program (forward_layers.*), whose kLayers evaluates just these.
        uint32_t layers = 0;
        bool specularAa = false;  // specular anti-aliasing (kSpecularAa)
        uint32_t samples = 1;     // of the targets
        bool alphaToCoverage = false;  // alpha-masked draws at samples > 1 where the device has alphaToOne
        auto operator<=>(const Variant&) const = default;
        std::string name() const;
    };
    // What execute needs of one draw, taken at setup (the scene's draw or its posed copy).
    struct DrawItem {
        const vk::Pipeline* pipeline;
        float depth;  // view distance, for sorting blended draws
        uint32_t firstIndex, indexCount, material;
        bool flipWinding, doubleSided;
        int32_t vertexOffset;  // kRestVertices: the scene's vertex buffer; else into the deformed one
        uint32_t drawData;     // index of its (first instance's) entry in the draw buffer
        uint32_t instances;    // instanced draws: how many (else 1)
        bool layered;          // drawn by the layered program (binds set 3)
    };
    // What every forward pass of one frame reads, taken by add().
    struct FrameInputs {
        shading::ForwardPush push{};
        std::optional<IblHandles> ibl;
        LayerMaps layerMaps;
        graph::BufferId posedDraws, posedLights, deformed;  // invalid where the frame has none
    };
    // Adds a graphics pass `name` recording `items` into the targets `targets` declares, reading
    // mFrame's inputs. Returns the targets as written.
    const DrawTarget& addDrawPass(graph::RenderGraph& graph, std::string name, std::vector<DrawItem> items,
                                  const std::function<DrawTarget(graph::PassBuilder&)>& targets);
    const vk::Pipeline& pipeline(const Variant& variant);
    static vk::GraphicsPipelineDesc desc(const Variant& variant);
    Variant variantOf(const scene::Draw& draw, ShadingModel model, const Ibl* ibl, DebugView debugView,
                      const ShadingOptions& shading, uint32_t samples) const;

    vk::Context& mContext;
    vk::PipelineCache<Variant> mPipelines;
    ForwardIblSet mIblSet;
    ForwardLayerSet mLayerSet;
    const scene::GpuScene* mScene = nullptr;
    std::unique_ptr<vk::DescriptorAllocator> mSets;
    VkDescriptorSet mSceneSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> mMaterialSets;
    std::vector<std::string> mExplanation;
    FrameInputs mFrame;
    std::vector<DrawItem> mBehind;  // the draws add() left for addTransmissive()
    DrawStats mStats;
};

}  // namespace candela::passes
