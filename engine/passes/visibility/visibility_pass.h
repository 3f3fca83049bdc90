#pragma once
// Visibility pass (graphics, docs/shading-paths.md): the opaque and alpha-masked ranges of a
// frame's draw list rasterized into reverse-Z depth and a visibility image (R32G32_UINT: draw
// entry + 1 and primitive per pixel, 0 where nothing is drawn), at the frame's sample count. Opaque
// draws run a fragment shader that only writes the IDs; masked draws test the base colour's alpha
// first (factor × COLOR_0 × texture, against the cutoff) — the only material input the pass reads.
// The compute shading (VisibilityShadePass) then shades each covered pixel once.

#include "gpu_scene/gpu_scene.h"
#include "graph/render_graph.h"
#include "passes/drawing/draw_list.h"
#include "passes/drawing/draw_target.h"
#include "passes/drawing/frame_inputs.h"
#include "passes/visibility/visibility_texture_sets.h"
#include "vk/descriptors.h"
#include "vk/pipeline_cache.h"

#include <memory>
#include <span>

namespace candela::passes {

inline constexpr VkFormat kVisibilityFormat = VK_FORMAT_R32G32_UINT;

struct VisibilityTargets {
    graph::TextureId visibility;  // R32G32_UINT
    graph::TextureId depth;       // D32, reverse-Z, the same sample count
};

class VisibilityPass {
public:
    explicit VisibilityPass(vk::Context& context);

    // Writes the scene's descriptor sets (draws, materials; the base colour texture of each of its
    // texture sets, for masked draws). Preconditions: the GPU no longer uses the previous scene's
    // sets; `scene` and `sets` (the scene's, textureSetsOf) outlive their use.
    void setScene(const gpu_scene::GpuScene& scene, const TextureSets& sets);

    // Adds "visibility": clears new targets of `size` and draws `items` (opaque, then masked) with
    // `frame`'s view, pose and deformed vertices, through the draw recorder (draw_recorder.h).
    VisibilityTargets add(graph::RenderGraph& graph, const DrawTargetSize& size, std::span<const DrawListItem> items,
                          const MaterialKeys& keys, const FrameInputs& frame, DrawStats* recorded = nullptr);

private:
    struct Variant {
        bool masked = false;
        uint32_t samples = 1;
        bool alphaToCoverage = false;  // masked draws at MSAA (FrameVariant::alphaToCoverage)
        auto operator<=>(const Variant&) const = default;
    };
    const vk::Pipeline& pipeline(const Variant& variant);

    vk::Context& mContext;
    vk::PipelineCache<Variant> mPipelines;
    const gpu_scene::GpuScene* mScene = nullptr;
    const TextureSets* mTextureSets = nullptr;
    std::unique_ptr<vk::DescriptorAllocator> mSets;
    VkDescriptorSet mOpaqueSceneSet = VK_NULL_HANDLE, mMaskedSceneSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> mBaseColorSets;  // per texture set
};

}  // namespace candela::passes
