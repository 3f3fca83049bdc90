#pragma once
// The draw list: what one frame draws of the scene, built once per frame and consumed by the
// passes that draw it (forward, forward_transmission). It selects draws (frustum culling), picks
// each one's level of detail, and sorts the survivors into ranges by a sort key, as Filament's
// RenderPass does: one sorted list whose ranges the passes take (`range`, `backToFront`).
//
// Which program and variant a draw uses is split in two: the material key (what a material asks
// of the forward program; fixed when the scene is loaded, MaterialKeys) and the frame's variant
// bits (lights, IBL, debug view, MSAA; the forward pass combines the two per frame). Plain data and
// pure functions, no Vulkan calls.

#include "options/draw_selection.h"
#include "passes/drawing/draw_stats.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <array>
#include <compare>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace candela::passes {

// The ranges of a draw list, in drawing order. Opaque, masked and point-and-line draws are sorted by
// material key, then material (fewest state changes); transmissive and blended ones back to front.
enum class DrawRange : uint8_t {
    Opaque,          // alpha mode OPAQUE (triangles)
    Masked,          // alpha mode MASK (alpha test, or alpha to coverage) (triangles)
    PointsAndLines,  // opaque and masked points and lines: drawn forward on both paths (the visibility buffer holds triangles)
    Transmissive,    // KHR_materials_transmission: drawn over the opaque image, which they see through
    Blended,         // alpha mode BLEND
};
inline constexpr size_t kDrawRangeCount = 5;
const char* drawRangeName(DrawRange range);

// What a material asks of the forward program, whatever the frame: the material half of a
// pipeline variant.
struct MaterialKey {
    bool unlit = false;      // KHR_materials_unlit
    bool normalMap = false;  // has a normal texture (and is lit)
    bool alphaMask = false;
    bool blend = false;
    // KHR_materials_* layers (scene::MaterialLayer bits) drawn by the layered program; 0: the core
    // program draws the material.
    uint32_t layers = 0;
    bool transmissive = false;  // has a transmission layer
    // The draw's topology (a pipeline each): a material's key is for triangles, draws of points and
    // lines have keys of their own (MaterialKeys::keyOf).
    scene::Topology topology = scene::Topology::Triangles;
    auto operator<=>(const MaterialKey&) const = default;
};
// The key of `material` on triangles.
MaterialKey materialKeyOf(const scene::Material& material);
// The key of `material` drawn by `draw`: its topology; unlit when the draw is unshaded.
MaterialKey materialKeyOf(const scene::Material& material, const scene::Draw& draw);

// The distinct material keys of a scene and each material's; made once per scene.
struct MaterialKeys {
    std::vector<MaterialKey> keys;     // in first-use order of the materials, then of the point and line draws
    std::vector<uint32_t> ofMaterial;  // per scene material: its index into `keys` on triangles
    // The keys of materials on points and lines, by (material, topology, unshaded): every material a
    // point or line draw may wear (KHR_materials_variants' included).
    std::map<std::tuple<uint32_t, scene::Topology, bool>, uint32_t> ofShapedMaterial;
    static MaterialKeys of(const scene::Scene& scene);
    const MaterialKey& operator[](uint32_t material) const { return keys[ofMaterial[material]]; }
    // The index into `keys` of `material` drawn by `draw`. Precondition: `keys` is of the draw's scene.
    uint32_t keyOf(uint32_t material, const scene::Draw& draw) const;
};

// The range a draw of a material with `key` goes in; `transmission`: transmissive draws get their
// own range (DrawListPlan::transmissionRange), else they are drawn with the others of their alpha mode.
DrawRange rangeOf(const MaterialKey& key, bool transmission);

// One draw the frame submits.
struct DrawListItem {
    uint32_t draw = 0;       // index into the frame's draws (the scene's, or its pose's: same order)
    uint32_t material = 0;
    uint32_t key = 0;        // index into MaterialKeys::keys
    uint32_t firstIndex = 0, indexCount = 0;  // the chosen level of detail's indices
    uint32_t drawData = 0;   // its (first instance's) entry in the draw buffer
    uint32_t instances = 1;  // instanced draws: how many (else 1)
    float depth = 0.0f;      // view distance of its bounds' centre
    bool flipWinding = false, doubleSided = false;
    DrawRange range = DrawRange::Opaque;
};

struct DrawList {
    std::vector<DrawListItem> items;  // sorted: by range, then as the range says
    std::array<uint32_t, kDrawRangeCount + 1> rangeStart{};  // items of range r: [rangeStart[r], rangeStart[r + 1])
    DrawStats stats;                  // the selection's counts (the state changes are the recorder's)
    uint32_t draws = 0;               // visible draws of the scene (not scaled to nothing)
    uint32_t hiddenDraws = 0;         // draws hidden (KHR_node_visibility) or scaled to nothing this frame, not drawn
    uint32_t instances = 0;           // instances in the scene's instanced draws

    std::span<const DrawListItem> range(DrawRange range) const;
    // Ranges first..last together (contiguous in the list).
    std::span<const DrawListItem> ranges(DrawRange first, DrawRange last) const;
    // The items of ranges `a` and `b` merged back to front (stable: on equal depth, `a`'s first).
    std::vector<DrawListItem> backToFront(DrawRange a, DrawRange b) const;
    bool empty(DrawRange r) const { return range(r).empty(); }
};

// What a frame's draw list is built from.
struct DrawListInputs {
    const scene::Scene& scene;
    const MaterialKeys& keys;              // MaterialKeys::of(scene)
    std::span<const scene::Draw> draws;    // the scene's draws, or its pose's (same order)
    const scene::ViewSetup& view;
    uint32_t targetHeight = 1;             // pixels: the level of detail's error is measured in them
    options::DrawSelection selection;
    // Transmissive draws get their own range (read what lies behind them); false puts them in
    // their alpha mode's range (debug views show data, not what lies behind).
    bool transmission = true;
};

// Selects, picks levels of detail and sorts.
DrawList buildDrawList(const DrawListInputs& in);

// What the list selected, for `--explain`: "draws: 40 of 49 submitted (9 outside the view frustum),
// ... triangles; N draws at a coarser level of detail (error ≤ 0.5 px)".
std::string describeSelection(const DrawList& list, const options::DrawSelection& selection);

}  // namespace candela::passes
