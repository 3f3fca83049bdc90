#pragma once
// skin_morph pass (compute): writes this frame's deformed vertices — morph targets at their
// non-zero weights, then skinning by the joint matrices — of every deformed draw into a new
// transient buffer, which the forward pass reads as its vertex buffer for those draws. Declared
// only for a pose with deformed draws; a static scene's graph never has it.

#include "gpu_scene/gpu_scene.h"
#include "passes/deform/skin_morph_dispatch.h"
#include "graph/render_graph.h"
#include "pose/scene_pose.h"
#include "shared/skin_morph.h"
#include "vk/pipeline_cache.h"

#include <optional>
#include <vector>

namespace candela::passes {

// What one frame's skin_morph pass does for a pose: a job per deformed draw, the frame data
// (the joint matrices of every skin in a row, then the non-zero morph weights, as 32-bit words:
// shared/skin_morph.h), and where each draw's deformed vertices land. Pure CPU.
struct SkinMorphFrame {
    std::vector<SkinMorphJob> jobs;
    std::vector<uint32_t> frameData;
    uint32_t activeTargets = 0;  // non-zero morph weights in frameData
    uint32_t vertexCount = 0;    // of the deformed-vertex buffer
    uint32_t skinnedDraws = 0;
    // Per pose draw: the vertex offset that maps its (absolute) indices into the deformed buffer;
    // INT32_MIN for draws drawn from the scene's own vertices.
    std::vector<int32_t> vertexOffset;
};
// Precondition: `pose` poses the scene `scene` was uploaded from.
SkinMorphFrame skinMorphFrame(const gpu_scene::GpuScene& scene, const pose::ScenePose& pose);

class SkinMorphPass {
public:
    // Splits its draws by the limits of context.caps() (skin_morph_dispatch.h), or by `limits`
    // when given (tests: a small range or group count on a device that has larger ones).
    explicit SkinMorphPass(vk::Context& context, const std::optional<SkinMorphLimits>& limits = std::nullopt);

    struct Inputs {
        const gpu_scene::GpuScene* scene = nullptr;  // base vertices and deformation records (persistent)
        std::vector<SkinMorphJob> jobs;          // one per deformed draw; disjoint target ranges
        uint32_t vertexCount = 0;                // of the deformed-vertex buffer: Σ jobs' vertexCount
        graph::BufferId frameData;               // this frame's joint matrices and non-zero weights, CPU-written
    };
    // Adds the pass; returns the written deformed-vertex buffer (vertexCount × scene::Vertex).
    // The pass object and the scene must outlive the graph's execution. Throws UserError when a draw
    // cannot be split to fit the limits (skinMorphDispatches), or the frame data passes
    // maxStorageBufferRange.
    graph::BufferId add(graph::RenderGraph& graph, const Inputs& inputs);

private:
    vk::Context& mContext;
    SkinMorphLimits mLimits;
    vk::PipelineCache<int> mPipelines;  // the one pipeline, built at the first add()
};

}  // namespace candela::passes
