#pragma once
// Preparing a loaded scene's geometry for drawing (meshoptimizer): triangles reordered for the
// post-transform vertex cache and against overdraw, vertices reordered for fetch locality, and a
// chain of levels of detail per mesh (geometry/mesh_lod.h). See docs/geometry.md.

#include "geometry/mesh_lod.h"
#include "scene/scene.h"

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

// The triangles of the meshes buildLevelsOfDetail would give a chain: every distinct triangle mesh
// of `scene` but a deformed one (morph targets or a skin: its error would change with the pose) and
// one whose draws have a chain (the built-in spheres' tessellations; one built before).
uint64_t lodCandidateTriangles(const scene::Scene& scene);

// Builds the chain of levels of detail of every mesh lodCandidateTriangles counts (on `threads`
// threads, the caller's included; 0: every hardware thread): appended to scene.indices, listed in
// scene.lodChains, each draw of the mesh pointing at it (Draw::lod); records the index memory and
// the time in scene.report.geometry and clears lodDeferred. Precondition: prepareGeometry ran.
void buildLevelsOfDetail(scene::Scene& scene, const LodChainSettings& settings = {}, uint32_t threads = 0);

}  // namespace candela::geometry
