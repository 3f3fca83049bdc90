#pragma once
// What every pass that draws or shades the scene reads in one frame, on either shading path (the
// forward draws, the visibility raster and its compute shading): the push constants, the frame's
// variant bits, the IBL and layer maps, and the per-frame buffers of an animated pose and of
// deformed vertices. Made once per frame (makeFrameInputs); each pass declares the reads it needs
// (declareFrameReads) and, in its execute callback, binds them through scene_bindings.h.

#include "gpu_scene/gpu_scene.h"
#include "graph/render_graph.h"
#include "options/debug_view.h"
#include "options/draw_selection.h"
#include "passes/ibl/ibl_handles.h"
#include "passes/drawing/layer_map_set.h"
#include "options/shading_model.h"
#include "passes/drawing/shading_variant.h"
#include "scene/camera.h"
#include "shared/ibl.h"
#include "shared/scene_data.h"
#include "shared/visibility.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace candela::passes {

// A draw's vertex offset when it is drawn from the scene's own vertices (not deformed this frame);
// the visibility shading reads the same value from its draw table.
inline constexpr int32_t kRestVertices = CANDELA_REST_VERTICES;

// The per-frame buffers of an animated pose, each read instead of the scene's own; each is invalid
// when nothing it holds animates: the draws' shading::DrawData (a node moves), the light data (a
// light moves, shows, hides or has an animated property), the material data and the material layer
// data (KHR_animation_pointer animates a material).
struct PosedBuffers {
    graph::BufferId draws;
    graph::BufferId lights;
    graph::BufferId materials;
    graph::BufferId materialLayers;
};

// This frame's deformed vertices (the skin_morph pass's output) and, per scene draw, the vertex
// offset that maps its indices into them (kRestVertices: drawn from the scene's own).
struct DeformedVertices {
    graph::BufferId vertices;
    std::vector<int32_t> vertexOffset;
};

// Image-based lighting of one frame: the maps to read (set 2) and how to read them.
struct IblInputs {
    IblHandles maps;
    shading::IblParams params;
    bool irradianceSh = true;
    bool multiscatter = true;
    // > 0: ground truth instead of the split sum (`ibl-report`): the reflectance equation
    // integrated per pixel with this many samples per lobe from the specular cube's mip 0.
    uint32_t referenceSamples = 0;
};

// What a frame's draws are lit by and read; the optional parts are absent when null.
struct FrameInputsDesc {
    const scene::ViewSetup& view;
    options::ShadingModel model = options::ShadingModel::Pbr;
    const IblInputs* ibl = nullptr;
    options::DebugView debugView = options::DebugView::None;
    options::ShadingOptions shading;
    uint32_t samples = 1;  // of the draw targets
    // Masked draws use alpha to coverage (samples > 1; the frame plan's AlphaMasking, which asks
    // the device for alphaToOne: render/frame_plan.h).
    bool alphaToCoverage = false;
    const PosedBuffers* posed = nullptr;
    const DeformedVertices* deformed = nullptr;
    const LayerMaps* layerMaps = nullptr;  // the sheen LUT and cube, for the layered programs
};

// What every draw and shading pass of one frame shares.
struct FrameInputs {
    shading::FramePush push{};
    FrameVariant variant;
    std::optional<IblHandles> ibl;
    LayerMaps layerMaps;
    PosedBuffers posed;        // invalid handles where the frame has none
    graph::BufferId deformed;  // invalid without deformed vertices
    std::vector<int32_t> vertexOffset;  // per scene draw (DeformedVertices); empty: rest vertices

    // The vertex offset of scene draw `draw` (kRestVertices: the scene's own vertices).
    int32_t vertexOffsetOf(uint32_t draw) const { return vertexOffset.empty() ? kRestVertices : vertexOffset[draw]; }
};

// The inputs of a frame of `desc` drawing `scene`. The push constants hold the view, the light
// count and the IBL parameters (the user's edits are applied by the caller).
FrameInputs makeFrameInputs(const FrameInputsDesc& desc, const gpu_scene::GpuScene& scene);

// What selects a frame's forward variant bits besides its lights: makeFrameInputs reads them from
// the frame's inputs, FrameBuilder::firstFrameVariant from the settings before a first frame.
struct FrameVariantSource {
    options::ShadingModel model = options::ShadingModel::Pbr;
    bool ibl = false;               // an environment's maps light the frame
    bool irradianceSh = true;       // with them: their irradiance is SH9
    bool multiscatter = true;       // with them: multiple-scattering compensation
    uint32_t referenceSamples = 0;  // with them: the ground truth's samples
    options::DebugView debugView = options::DebugView::None;
    bool specularAa = false;
    uint32_t samples = 1;
    bool alphaToCoverage = false;  // asked by the frame plan (used with samples > 1 only)
};
// The variant bits `source` gives a frame lit by `lights` of types `lightTypes` (bit 1 <<
// CANDELA_LIGHT_* of each): the IBL bits only with an environment, alpha to coverage only with MSAA.
FrameVariant frameVariantOf(const FrameVariantSource& source, bool lights, uint32_t lightTypes);

// FrameVariant::lightTypes of a frame drawing `lights`: bit 1 << CANDELA_LIGHT_* of each.
uint32_t lightTypeBits(std::span<const shading::LightData> lights);

// Which of the frame's per-frame buffers a pass reads and in which shader stages (0: the pass
// type's default stages).
struct FrameReads {
    bool lights = true;
    bool materials = true;
    bool materialLayers = false;             // only passes with a layered program read them
    VkPipelineStageFlags2 sceneStages = 0;  // of the draws, materials and material layers
    VkPipelineStageFlags2 lightStages = 0;
    graph::Usage deformedUsage = graph::Usage::Vertex;
};
// The per-frame buffers as a pass declared them.
struct DeclaredFrameBuffers {
    PosedBuffers posed;
    graph::BufferId deformed;
};
// Declares the reads `reads` asks for of `frame`'s valid per-frame buffers in the pass `builder`
// belongs to. Returns the handles as declared (invalid where not read), for the execute callback.
DeclaredFrameBuffers declareFrameReads(graph::PassBuilder& builder, const FrameInputs& frame, const FrameReads& reads);

}  // namespace candela::passes
