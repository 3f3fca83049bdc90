#pragma once
// skin_morph pass (compute): writes this frame's deformed vertices — morph targets at their
// non-zero weights, then skinning by the joint matrices — of every deformed draw into a new
// transient buffer, which the forward pass reads as its vertex buffer for those draws. Declared
// only for a pose with deformed draws; a static scene's graph never has it.

#include "gpu_scene/gpu_scene.h"
#include "graph/render_graph.h"
#include "pose/scene_pose.h"
#include "shared/skin_morph.h"
#include "vk/pipeline_cache.h"

#include <vector>

namespace candela::passes {

// What one frame's skin_morph pass does for a pose: a dispatch per deformed draw, the joint
// matrices of every skin in a row, the non-zero morph weights, and where each draw's deformed
// vertices land. Pure CPU.
struct SkinMorphFrame {
    std::vector<shading::SkinMorphPush> jobs;
    std::vector<glm::mat4> joints;
    std::vector<shading::ActiveMorphTarget> activeTargets;
    uint32_t vertexCount = 0;   // of the deformed-vertex buffer
    uint32_t skinnedDraws = 0;
    // Per pose draw: the vertex offset that maps its (absolute) indices into the deformed buffer;
    // INT32_MIN for draws drawn from the scene's own vertices.
    std::vector<int32_t> vertexOffset;
};
// Precondition: `pose` poses the scene `scene` was uploaded from.
SkinMorphFrame skinMorphFrame(const scene::GpuScene& scene, const scene::ScenePose& pose);

class SkinMorphPass {
public:
    explicit SkinMorphPass(vk::Context& context);

    struct Inputs {
        const scene::GpuScene* scene = nullptr;      // base vertices, deltas, influences (persistent)
        std::vector<shading::SkinMorphPush> jobs;    // one dispatch each; disjoint target ranges
        uint32_t vertexCount = 0;                    // of the deformed-vertex buffer: Σ jobs' vertexCount
        graph::BufferId joints;                      // this frame's joint matrices (mat4), CPU-written
        graph::BufferId activeTargets;               // this frame's non-zero weights (ActiveMorphTarget)
    };
    // Adds the pass; returns the written deformed-vertex buffer (vertexCount × scene::Vertex).
    // The pass object and the scene must outlive the graph's execution.
    graph::BufferId add(graph::RenderGraph& graph, const Inputs& inputs);

private:
    vk::Context& mContext;
    vk::PipelineCache<int> mPipelines;  // the one pipeline, built at the first add()
};

}  // namespace candela::passes
