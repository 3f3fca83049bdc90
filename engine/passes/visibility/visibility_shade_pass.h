#pragma once
// Visibility shading (compute, docs/shading-paths.md): the pass "visibility_shade" writes the
// covered pixels of the HDR image (RGBA16F, premultiplied, alpha = coverage, as the forward
// pass's; cleared to transparent black before, "visibility_clear") from the visibility image — one
// indirect dispatch per shading list (a shading variant with one material texture set) over the
// tiles the classification listed for it (visibility_shade*.comp: the forward programs' material
// and lighting code); with MSAA one per list and k-th distinct triangle of a pixel's samples, each
// shaded once, weighted by its samples' share and summed (the resolve; k > 0 only on triangle
// edges). A list no pixel needs dispatches no workgroup. The sky is composited later (the tonemap,
// or the skybox pass).

#include "gpu_scene/gpu_scene.h"
#include "graph/render_graph.h"
#include "passes/drawing/ibl_set.h"
#include "passes/drawing/layer_map_set.h"
#include "passes/drawing/draw_target.h"
#include "passes/drawing/frame_inputs.h"
#include "passes/visibility/visibility_classify_pass.h"
#include "passes/visibility/visibility_frame.h"
#include "passes/visibility/visibility_texture_sets.h"
#include "vk/descriptors.h"
#include "vk/pipeline_cache.h"
#include "vk/sampler.h"

#include <memory>
#include <optional>

namespace candela::passes {

class VisibilityShadePass {
public:
    explicit VisibilityShadePass(vk::Context& context);

    // Writes the scene's descriptor sets (lights, draws, materials; per texture set its textures
    // and, where a material of it has layers, the layer parameters and textures: scene_bindings.h).
    // Preconditions: the GPU no longer uses the previous scene's sets; `scene`, `keys` and `sets`
    // (the scene's) outlive their use.
    void setScene(const gpu_scene::GpuScene& scene, const MaterialKeys& keys, const TextureSets& sets);

    struct Inputs {
        graph::TextureId visibility;  // VisibilityPass's, at the frame's sample count
        VisibilityTileLists tiles;
        graph::BufferId draws;        // the frame's shading::VisibilityDraw table
        graph::BufferId frameData;    // its shading::VisibilityFrame
        shading::VisibilityFrame extent;
        const VisibilityFrameTables* tables = nullptr;
        const FrameInputs* frame = nullptr;
    };
    // Adds "visibility_clear" and "visibility_shade"; returns the HDR image they write.
    graph::TextureId add(graph::RenderGraph& graph, const Inputs& in);

    // What a shading pipeline is specialized on: the list's variant, the texture slots its texture
    // set fills (TextureSets::coreSlots, layerSlots) and whether the frame has deformed vertices.
    // With MSAA (variant.samples > 1), `distinct`: which distinct triangle of a pixel's samples the
    // pipeline shades (visibility_shade.comp.glsl).
    struct ShadeKey {
        ShadingVariant variant;
        uint32_t coreSlots = ~0u, layerSlots = ~0u;
        bool deformed = true;
        uint32_t distinct = 0;
        auto operator<=>(const ShadeKey&) const = default;
    };
    // The compute pipeline of `key` (built at its first use).
    const vk::Pipeline& pipeline(const ShadeKey& key);

private:
    // The programs without pipelines whose set layouts the variants share: the core one (sets 0, 1,
    // 2 and 4 of every core variant; 0, 2 and 4 of every layered one) and the layered one (its set 1).
    const vk::Program& program(bool layered);

    vk::Context& mContext;
    glm::uvec2 mTile;  // visibilityTileSize: the dispatches' workgroup size
    vk::PipelineCache<ShadeKey> mPipelines;
    const TextureSets* mTextureSets = nullptr;
    IblSet mIblSet;
    LayerMapSet mLayerSet;
    vk::Sampler mNearest;
    std::optional<vk::Program> mCoreProgram, mLayeredProgram;
    const gpu_scene::GpuScene* mScene = nullptr;
    std::unique_ptr<vk::DescriptorAllocator> mSets;
    VkDescriptorSet mSceneSet = VK_NULL_HANDLE;
    // Set 1 per texture set, of the core and the layered program (null where no material of the
    // texture set uses that program).
    std::vector<VkDescriptorSet> mCoreMaterialSets, mLayeredMaterialSets;
};

}  // namespace candela::passes
