#pragma once
// Readback pass (transfer): copies mip 0, layer 0 of a texture into a buffer, tightly packed, so the
// host can read it after the frame's fence. The buffer is normally imported (host-visible) with a
// final state of HOST_READ, which makes the pass an output of the graph.

#include "graph/render_graph.h"

#include <span>
#include <string>
#include <vector>

namespace candela::passes {

// Returns the buffer's new version.
graph::BufferId addReadbackPass(graph::RenderGraph& graph, graph::TextureId source, graph::BufferId destination);
// Adds pass `name` copying each of `sources` into `destination`, tightly packed rows, image i at
// byte offsets[i] (packedOffsets of their sizes). Returns the buffer's new version.
graph::BufferId addReadbackPass(graph::RenderGraph& graph, std::string name, std::span<const graph::TextureId> sources,
                                graph::BufferId destination);
// Where addReadbackPass puts images of `bytes[i]` bytes: each at a multiple of 16 bytes after the
// one before; one more element, the bytes they take in all.
std::vector<VkDeviceSize> packedOffsets(std::span<const VkDeviceSize> bytes);

// The state to import a readback buffer with so the host may read it after the graph.
graph::ResourceState hostReadState();

}  // namespace candela::passes
