#pragma once
// ShadingSummary: what a frame's draws ask of the shading programs, which both paths share — the
// draws and instances, the draws of each shading variant, whether the pose moves them, and which
// program features the scene leaves out (the light loop, normal mapping, the unlit variant, the
// material layers). Made once per frame from the draw list (summarizeShading) and put into words
// for --explain (explainShading); tests assert its fields. Names and counts only, no Vulkan calls.

#include "options/draw_selection.h"
#include "passes/drawing/draw_list.h"
#include "passes/drawing/shading_variant.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace candela::passes {

struct ShadingSummary {
    uint32_t draws = 0;
    uint32_t instances = 0;                    // instances in instanced draws (0: none instanced)
    std::map<std::string, uint32_t> variants;  // draws per shading variant (ShadingVariant::name())
    bool posed = false;                        // draw matrices of this frame's pose (animated)
    uint32_t hiddenDraws = 0;                  // hidden or scaled to nothing: not drawn
    bool lights = false;                       // the scene has punctual lights (else no light loop)
    bool normalMaps = false;                   // a material has a normal texture (else no TBN work)
    bool unlit = false;                        // a material is KHR_materials_unlit, or points or lines unshaded (else no unlit variant)
    std::string lodDecision;                   // whether the levels of detail were built, and why ("": built at load)
    // The materials that pay for layers (the layered program), in material order.
    struct LayeredMaterial {
        std::string name;
        uint32_t layers = 0;  // shared/shading_tables.h's CANDELA_LAYER_* bits
        bool operator==(const LayeredMaterial&) const = default;
    };
    std::vector<LayeredMaterial> layered;
};

// The summary of the frame's `list` drawn with `frame`'s variant bits: `keys` are the scene's
// material keys, `lightCount` its punctual lights as uploaded, `posed` whether the draws take the
// pose's matrices.
ShadingSummary summarizeShading(const DrawList& list, const MaterialKeys& keys, const scene::Scene& scene,
                                uint32_t lightCount, const FrameVariant& frame, bool posed);

// The summary in words, one line each (`--explain`), with the draw selection's line
// (describeSelection) second.
std::vector<std::string> explainShading(const ShadingSummary& summary, const DrawList& list,
                                        const options::DrawSelection& selection);

}  // namespace candela::passes
