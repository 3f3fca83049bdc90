#pragma once
// LayerMapSet: descriptor set 3 of the forward pass's layered program — the maps the material
// layers read (the sheen albedo LUT, the Charlie-prefiltered environment, the background behind
// transmissive draws), declared in the pass's
// setup from the frame's handles and written in its execute callback from what the pass context
// resolves them to. What a frame lacks is bound to a 1×1 placeholder this object owns; a variant
// that reads a map only exists when the frame has it. The core program has no set 3.

#include "graph/render_graph.h"
#include "vk/image.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"

namespace candela::graph {
class PassContext;
}

namespace candela::passes {

// The layer maps of one frame (invalid handles: not in this frame).
struct LayerMaps {
    graph::TextureId sheenLut;   // R32F E(N·V, sheen roughness) (ibl_maps::SheenLut)
    graph::TextureId sheenCube;  // RGBA16F cube, mip m Charlie-prefiltered at sheen roughness m / (levels − 1)
    graph::TextureId transmission;  // RGBA16F, the opaque image with its box-filtered mips (TransmissionBackgroundPass)
};

class LayerMapSet {
public:
    // Creates and uploads the placeholders (waits for the upload).
    explicit LayerMapSet(vk::Context& context);

    // Declares the fragment shader's reads of every valid handle of `maps` (null: none). Returns
    // the handles as declared, for write().
    static LayerMaps declare(graph::PassBuilder& builder, const LayerMaps* maps);
    // Allocates set 3 of the layered `program` from the frame's descriptor pool and writes the
    // bindings it declares (a variant specialized to its layers declares only the maps they read).
    // Precondition: the program has a set 3 with at least one binding.
    VkDescriptorSet write(const graph::PassContext& ctx, const vk::Program& program, const LayerMaps& declared) const;

private:
    vk::Sampler mLinear;  // clamp to edge, trilinear
    vk::Image mPlaceholderCube;
    vk::Image mPlaceholderLut;
    vk::Image mPlaceholderBackground;  // transparent black
};

}  // namespace candela::passes
