#pragma once
// Clear pass (transfer): a new transient texture cleared to transparent black (vkCmdClearColorImage),
// for a pass that then writes only part of it — the visibility path's shading writes the covered
// pixels of the HDR image, and the background stays clear.

#include "graph/render_graph.h"

#include <string>

namespace candela::passes {

// Adds pass `name` creating texture `texture` of `desc` and clearing it; returns the cleared version.
graph::TextureId addClearPass(graph::RenderGraph& graph, std::string name, std::string texture, const graph::TextureDesc& desc);

}  // namespace candela::passes
