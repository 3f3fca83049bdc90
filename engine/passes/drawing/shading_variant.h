#pragma once
// The shading programs' variants, shared by both shading paths (the forward programs' pipelines and
// the visibility path's compute shading). A variant is the material's key (passes::MaterialKey,
// fixed at load) combined with the frame's bits (FrameVariant: lights, image-based lighting, debug
// view, specular anti-aliasing, sample count), so what a draw does not use costs nothing: each
// bit is a specialization constant (shared/specialization_ids.h). Names only, no Vulkan calls.

#include "options/debug_view.h"
#include "passes/drawing/draw_list.h"
#include "options/shading_model.h"

#include <compare>
#include <cstdint>
#include <string>
#include <vector>

namespace candela::passes {

// The frame's half of a variant: the same for every draw of the frame.
struct FrameVariant {
    options::ShadingModel model = options::ShadingModel::Pbr;
    bool lights = false;  // the scene has punctual lights
    uint32_t lightTypes = 0;  // of which types (bit 1 << CANDELA_LIGHT_*)
    bool ibl = false;     // image-based lighting
    bool irradianceSh = true;
    bool multiscatter = true;
    uint32_t referenceSamples = 0;  // > 0: the ground-truth integrator (ibl-report)
    options::DebugView debugView = options::DebugView::None;
    bool specularAa = false;
    uint32_t samples = 1;           // of the draw targets
    bool alphaToCoverage = false;   // masked draws use alpha to coverage (samples > 1 and the device has alphaToOne)
    bool operator==(const FrameVariant&) const = default;
};

// One variant of the shading programs: the specialization constants and the pipeline state.
struct ShadingVariant {
    bool normalMap = false;
    bool lights = false;
    uint32_t lightTypes = 0;  // bit 1 << CANDELA_LIGHT_* (with lights)
    bool unlit = false;
    bool alphaMask = false;
    bool blend = false;
    options::ShadingModel model = options::ShadingModel::Pbr;
    bool ibl = false;
    bool irradianceSh = true;
    bool multiscatter = true;
    uint32_t referenceSamples = 0;
    options::DebugView debugView = options::DebugView::None;
    // KHR_materials_* layers the material uses (scene::MaterialLayer bits): non-zero selects the
    // layered program (forward_layers.*), whose kLayers evaluates just these.
    uint32_t layers = 0;
    bool specularAa = false;
    uint32_t samples = 1;
    bool alphaToCoverage = false;
    scene::Topology topology = scene::Topology::Triangles;  // the pipeline's primitive topology
    auto operator<=>(const ShadingVariant&) const = default;
    // E.g. "pbr+normal-map+ibl-sh9+msaa4" (for --explain).
    std::string name() const;
};

// The variant drawing a material of `key` in a frame of `frame`: unlit materials ignore the frame's
// lighting and shading bits.
ShadingVariant shadingVariant(const MaterialKey& key, const FrameVariant& frame);

// The values of the shading programs' specialization constants for `v`, indexed by constant_id
// (shared/specialization_ids.h); the visibility shading adds its own. CANDELA_SPEC_LAYERS is there
// for the core programs too, which ignore it.
std::vector<uint32_t> specializationConstants(const ShadingVariant& v);

// The layer names of `layers` (scene::MaterialLayer bits), each preceded by "+".
std::string plusLayerNames(uint32_t layers);

}  // namespace candela::passes
