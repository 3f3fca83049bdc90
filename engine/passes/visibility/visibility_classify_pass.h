#pragma once
// Visibility classification (compute, docs/shading-paths.md), two dispatches in one pass
// "visibility_classify": visibility_classify.comp writes, per 8×8 screen tile, the word of the
// shading lists its pixels need; visibility_tiles.comp gathers, per list, the tiles that need it
// into a tile list and writes its indirect
// dispatch arguments. VisibilityShadePass dispatches each list.
// (The tiles: 8 × 8 pixels, or 8 × 1 on CPU devices: passes/visibility/visibility_frame.h.)

#include "graph/render_graph.h"
#include "shared/visibility.h"
#include "vk/pipeline_cache.h"
#include "vk/sampler.h"

namespace candela::passes {

struct VisibilityTileLists {
    graph::BufferId lists;      // per list, extent.w words: tile x | tile y << 16
    graph::BufferId arguments;  // per list, VkDispatchIndirectCommand
};

class VisibilityClassifyPass {
public:
    explicit VisibilityClassifyPass(vk::Context& context);

    // Adds "visibility_classify" reading `visibility` (extent.samples.x samples) and the frame's `draws`
    // (shading::VisibilityDraw per draw entry) and `frameData` (shading::VisibilityFrame, whose
    // contents `extent` gives): extent.lists.x tile lists.
    VisibilityTileLists add(graph::RenderGraph& graph, graph::TextureId visibility, graph::BufferId draws,
                            graph::BufferId frameData, const shading::VisibilityFrame& extent);

private:
    vk::Context& mContext;
    vk::PipelineCache<int> mPipelines;  // 0: classify, 1: tiles, 2: classify a multisampled image
    vk::Sampler mNearest;               // the visibility image is read with texelFetch
};

}  // namespace candela::passes
