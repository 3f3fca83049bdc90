#pragma once
// Readback pass (transfer): copies mip 0, layer 0 of a texture into a buffer, tightly packed, so the
// host can read it after the frame's fence. The buffer is normally imported (host-visible) with a
// final state of HOST_READ, which makes the pass an output of the graph.

#include "graph/render_graph.h"

namespace candela::passes {

// Returns the buffer's new version.
graph::BufferId addReadbackPass(graph::RenderGraph& graph, graph::TextureId source, graph::BufferId destination);

// The state to import a readback buffer with so the host may read it after the graph.
graph::ResourceState hostReadState();

}  // namespace candela::passes
