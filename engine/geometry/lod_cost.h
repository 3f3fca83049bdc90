#pragma once
// When levels of detail pay: building a mesh's chain (geometry/mesh_lod.h) costs CPU time once;
// each frame that draws a coarser level saves device time. A capture renders a known number of
// frames, so the chains are built only when drawing the full detail for those frames would cost
// more than building them (a single still never does); the viewer, which draws frames without
// end, always builds them. See docs/geometry.md#when-levels-of-detail-are-built.

#include <cstdint>
#include <optional>
#include <string>

namespace candela::geometry {

// What one triangle of a mesh's full detail costs.
struct TriangleCosts {
    // To build its chain: simplifying it and measuring each level's error, microseconds on one core.
    double buildMicroseconds = 0.0;
    // To draw it once, microseconds of the device's time: at most what a frame saves by drawing
    // a coarser level instead (that level's own triangles cost something too).
    double drawMicroseconds = 0.0;
};

// The costs measured on the project machine (docs/geometry.md): on a CPU device (lavapipe,
// SwiftShader) drawing a triangle costs as much as a GPU's thousands; `cpuDevice` picks which.
TriangleCosts measuredTriangleCosts(bool cpuDevice);

// The triangles the choice weighs: those the chains are built from (each distinct mesh once) and
// those a frame draws of the same meshes at full detail (each draw and instance of them: one mesh
// drawn by 98 nodes is built once and drawn 98 times).
struct LodWork {
    uint64_t builtTriangles = 0;
    uint64_t drawnTriangles = 0;
};

struct LodDecision {
    bool build = false;
    std::string reason;  // one line for --explain, starting "levels of detail: "
};

// Rent or buy: builds when what drawing `work.drawnTriangles` (of the meshes that would get a
// chain) in full costs over the frames drawn so far and those ahead reaches what building the
// chains of `work.builtTriangles` costs on `cores` cores. `framesAhead` nullopt: frames without end (the viewer): always builds.
// lodErrorPixels ≤ 0 (levels of detail off): never. Deciding at every new frame count keeps the
// total within twice that of the better choice made knowing every frame in advance.
LodDecision decideLevelsOfDetail(const LodWork& work, uint64_t framesDrawn, std::optional<uint64_t> framesAhead,
                                 float lodErrorPixels, const TriangleCosts& costs, uint32_t cores);

}  // namespace candela::geometry
