#pragma once
// Preparing a loaded scene's geometry for drawing (meshoptimizer): triangles reordered for the
// post-transform vertex cache and against overdraw, vertices reordered for fetch locality, and a
// chain of levels of detail per mesh (geometry/mesh_lod.h). See docs/geometry.md.

#include "geometry/lod_cost.h"
#include "geometry/mesh_lod.h"
#include "scene/scene.h"

#include <span>
#include <vector>

namespace candela::geometry {

// When prepareGeometry builds the levels of detail: at once, or later (buildLevelsOfDetail) if a
// cost model says they pay (geometry/lod_cost.h: a capture of one frame never does).
enum class LevelsOfDetail { Build, Defer };

// Prepares every distinct triangle mesh of `scene` (an index range the draws use; points and lines
// are left as they are) and records what it did in scene.report.geometry:
//  - its triangles reordered for the vertex cache, then against overdraw — except a mesh drawn
//    with an alpha-blended material (the order of its triangles is the order they blend in);
//  - its vertices reordered for fetch locality when no other mesh shares them and it is not
//    deformed (the deformation data follows the scene's vertex order);
//  - with LevelsOfDetail::Build, its chain (buildLevelsOfDetail); with Defer, none yet
//    (report.geometry.lodDeferred).
// The image is unchanged at level 0 but for ties in depth. Call once, after the draws are final.
// Precondition: the draws' ranges and materials are valid.
void prepareGeometry(scene::Scene& scene, LevelsOfDetail lod = LevelsOfDetail::Build, const LodChainSettings& settings = {});

// A mesh buildLevelsOfDetail gives a chain: every distinct triangle mesh of a scene but a deformed
// one (morph targets or a skin: its error would change with the pose) and one whose draws have a
// chain (the built-in spheres' tessellations; one built before).
struct LodCandidate {
    uint32_t firstIndex = 0, indexCount = 0;    // its range of scene.indices
    uint32_t firstVertex = 0, vertexCount = 0;  // the range of scene.vertices its indices name
    uint64_t drawnTriangles = 0;  // what the draws using it submit a frame at full detail (each instance counted)
};

// The candidates of `scene`, in the order of the draws that first use them (the same for the same
// scene loaded twice).
std::vector<LodCandidate> lodCandidates(const scene::Scene& scene);

// The work of giving `candidates` their chains: their triangles, and those their draws submit in a
// frame at full detail. Without `candidates`: those of lodCandidates(scene).
LodWork lodCandidateWork(std::span<const LodCandidate> candidates);
LodWork lodCandidateWork(const scene::Scene& scene);

// The chain of each of `candidates` (simplifyChain over its vertices; indices relative to its
// firstVertex), the largest meshes first on `threads` threads (the caller's included; 0: every
// hardware thread). Precondition: `candidates` are lodCandidates(scene).
std::vector<std::vector<SimplifiedLevel>> simplifyCandidates(const scene::Scene& scene, std::span<const LodCandidate> candidates,
                                                             const LodChainSettings& settings = {}, uint32_t threads = 0);

// Gives each of `candidates` its chain chains[i] (none when empty): the levels appended to
// scene.indices, listed in scene.lodChains, each draw of the mesh pointing at it (Draw::lod);
// records the index memory and `milliseconds` in scene.report.geometry and clears lodDeferred.
// Preconditions: `candidates` are lodCandidates(scene), chains.size() == candidates.size(), and
// every index of chains[i] < candidates[i].vertexCount (simplifyCandidates' result, or the
// cache's: geometry/lod_cache_file.h checks).
void attachLevelsOfDetail(scene::Scene& scene, std::span<const LodCandidate> candidates,
                          const std::vector<std::vector<SimplifiedLevel>>& chains, double milliseconds);

// simplifyCandidates then attachLevelsOfDetail: the chain of every candidate, built now.
// Precondition: prepareGeometry ran.
void buildLevelsOfDetail(scene::Scene& scene, const LodChainSettings& settings = {}, uint32_t threads = 0);

}  // namespace candela::geometry
