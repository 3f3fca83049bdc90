#pragma once
// What the drawing core recorded for one frame (DrawList::select and recordDraws fill it). Plain data.

#include <cstdint>

namespace candela::passes {

// What the last frame drew: draws and triangles of the scene (visible ones, each instance counted)
// against those submitted, the lines and points submitted, and the state changes recorded to draw
// them.
struct DrawStats {
    uint32_t sceneDraws = 0, submittedDraws = 0, culledDraws = 0;
    uint32_t coarserDraws = 0;  // submitted at a level of detail beyond the full one
    uint64_t sceneTriangles = 0, submittedTriangles = 0;  // of triangle draws
    uint64_t submittedLines = 0, submittedPoints = 0;      // of line and point draws
    uint32_t pipelineBinds = 0, descriptorBinds = 0, dynamicStates = 0, bufferBinds = 0;
    uint32_t stateChanges() const { return pipelineBinds + descriptorBinds + dynamicStates + bufferBinds; }
};

}  // namespace candela::passes
