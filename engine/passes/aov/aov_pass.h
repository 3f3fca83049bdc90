#pragma once
// The aov pass (graphics; docs/outputs.md): the per-pixel outputs besides colour — view depth,
// shading normal, base colour and alpha, metallic and roughness, emission, the IDs of what drew each
// pixel — for either shading path. It draws the frame's draw list (every range: the same draws at
// the same levels of detail, poses and deformed vertices as the image) once more, at one sample per
// pixel whatever the frame's MSAA, with its own reverse-Z depth: each output describes the nearest
// surface at the pixel centre, never a blend of two at an edge. Only the targets a frame asks for
// are attachments (shared/aov_targets.h, in that order; the program is specialized to them); a
// frame that asks for none does not declare the pass.

#include "gpu_scene/gpu_scene.h"
#include "graph/render_graph.h"
#include "passes/drawing/draw_list.h"
#include "passes/drawing/frame_inputs.h"
#include "passes/drawing/shading_variant.h"
#include "shared/aov_targets.h"
#include "vk/descriptors.h"
#include "vk/pipeline_cache.h"

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace candela::passes {

// Each target's format (shared/aov_targets.h says what it holds).
inline constexpr std::array<VkFormat, CANDELA_AOV_TARGET_COUNT> kAovFormats = {
    VK_FORMAT_R32_SFLOAT,          VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R16G16_SFLOAT,
    VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_UINT,   VK_FORMAT_R32_UINT};

struct AovTargets {
    std::array<graph::TextureId, CANDELA_AOV_TARGET_COUNT> targets;  // invalid where not asked for
    graph::TextureId depth;  // D32, reverse Z (0: nothing drawn)

    // The images that hold the outputs asked for, each with its number: the targets asked for
    // (CANDELA_AOV_*) and, with `clipDepth`, the depth (CANDELA_AOV_CLIP_DEPTH).
    std::vector<std::pair<uint32_t, graph::TextureId>> images(bool clipDepth) const {
        std::vector<std::pair<uint32_t, graph::TextureId>> out;
        for (uint32_t t = 0; t < CANDELA_AOV_TARGET_COUNT; ++t)
            if (targets[t].valid()) out.emplace_back(t, targets[t]);
        if (clipDepth) out.emplace_back(CANDELA_AOV_CLIP_DEPTH, depth);
        return out;
    }
};

class AovPass {
public:
    // Precondition: `context` outlives the pass.
    explicit AovPass(vk::Context& context);

    // The scene the next frames draw; its descriptor sets are written at the first add() after.
    // Preconditions: the GPU no longer uses the previous scene's sets; `scene` and `keys` outlive
    // their use.
    void setScene(const gpu_scene::GpuScene& scene, const MaterialKeys& keys);

    // Adds "aov": clears new targets of width × height — each of `targets` (bit 1 << CANDELA_AOV_*)
    // and the depth — to "nothing here" (view depth +inf, IDs CANDELA_NO_ID, the rest 0) and draws
    // every draw of `list` with `frame`'s view, pose and deformed vertices. Precondition: a scene is set.
    AovTargets add(graph::RenderGraph& graph, uint32_t width, uint32_t height, uint32_t targets, const DrawList& list,
                   const FrameInputs& frame);

private:
    struct Variant {
        uint32_t targets = 0;
        bool normalMap = false;
        bool alphaTest = false;  // masked (at the cutoff) or blended (at ½) materials
        scene::Topology topology = scene::Topology::Triangles;
        auto operator<=>(const Variant&) const = default;
    };
    const vk::Pipeline& pipeline(const Variant& variant);
    // Writes the scene's sets 0 and 1 (per material) for the pass's program.
    void writeSets();

    vk::Context& mContext;
    vk::PipelineCache<Variant> mPipelines;
    const gpu_scene::GpuScene* mScene = nullptr;
    const MaterialKeys* mKeys = nullptr;
    std::unique_ptr<vk::DescriptorAllocator> mSets;
    VkDescriptorSet mSceneSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> mMaterialSets;  // per scene material
};

}  // namespace candela::passes
