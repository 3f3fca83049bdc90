#pragma once
// Levels of detail: simplified index buffers of a triangle mesh (meshoptimizer's edge-collapse
// simplifier, borders locked, attribute seams kept), each with its geometric error, and the choice
// of a level for a draw from the error it would show on screen. See docs/geometry.md.

#include "scene/camera.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace candela::geometry {

// The version of what simplifyChain and surfaceDeviation compute: part of the on-disk cache's key
// (geometry/lod_cache.h), so raise it with any change to their results and cached chains are built anew.
inline constexpr uint32_t kLodChainAlgorithmVersion = 1;

// How a chain is built.
struct LodChainSettings {
    // Each level aims at this fraction of the previous level's triangles.
    float reduction = 1.0f / 3.0f;
    // A level is kept only when it has at most this fraction of the previous level's triangles
    // (the mesh no longer simplifies: locked borders, seams, too few triangles).
    float minimumGain = 0.6f;
    // The levels beyond the first together hold at most this fraction of its indices.
    float maxExtraIndices = 0.5f;
    uint32_t maxLevels = 8;          // including the full detail
    uint32_t minTriangles = 8;       // no level is simplified further once this small
};

struct SimplifiedLevel {
    std::vector<uint32_t> indices;  // into the same vertices as the input
    // Mesh units: the sampled distance between the level's surface and the full detail's
    // (surfaceDeviation), never below the simplifier's own estimate, and never below a finer level's.
    float error = 0.0f;
};

// Simplifies the triangle list `indices` (into `vertices`) into successively coarser levels,
// each simplified from the one before and its error measured against the full detail, with the mesh's
// open borders locked (no cracks where primitives meet) and its attribute seams (vertices sharing
// a position with different normals or UVs) kept. Returns the levels beyond the full detail,
// coarsest last; empty when the mesh does not simplify. Precondition: every index < vertices.size().
std::vector<SimplifiedLevel> simplifyChain(std::span<const scene::Vertex> vertices, std::span<const uint32_t> indices,
                                           const LodChainSettings& settings = {});

// How far the surface of the triangle list `coarse` lies from that of `fine` (both over
// `vertices`): the largest distance from a vertex of `fine` to the surface of `coarse`, and from
// the corners, edge midpoints and centre of a triangle of `coarse` to the surface of `fine` (a
// sampled Hausdorff distance; `fine`'s small triangles are sampled at their corners only). Mesh
// units. Precondition: every index < vertices.size(), both lists non-empty.
float surfaceDeviation(std::span<const scene::Vertex> vertices, std::span<const uint32_t> fine, std::span<const uint32_t> coarse);

// Index of the coarsest level of `chain` whose error, in world units (× `worldScale`, the
// draw's largest mesh-to-world scale), covers at most `maxPixels` at `pixelsPerUnit` (what one
// world unit measures on screen at the draw's nearest point). Level 0 when maxPixels ≤ 0 or
// pixelsPerUnit is infinite (the eye inside the draw's bounds).
uint32_t selectLod(const scene::LodChain& chain, float worldScale, float pixelsPerUnit, float maxPixels);

// What one world unit measures on screen, in pixels, at the point of `bounds` (world space)
// nearest the eye of `view`, for a viewport `heightPixels` tall; infinite when the eye is inside
// the bounds' sphere. Orthographic views: the same everywhere.
float pixelsPerUnit(const scene::ViewSetup& view, uint32_t heightPixels, const scene::Aabb& bounds);

// The largest factor by which `world` (and, for an instanced draw, each of its instances) scales
// a length.
float maxScale(const glm::mat4& world);

}  // namespace candela::geometry
