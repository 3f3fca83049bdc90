#pragma once
// Preparing a loaded scene's geometry for drawing (meshoptimizer): triangles reordered for the
// post-transform vertex cache and against overdraw, vertices reordered for fetch locality, and a
// chain of levels of detail per mesh (geometry/mesh_lod.h). See docs/geometry.md.

#include "geometry/mesh_lod.h"
#include "scene/scene.h"

namespace candela::geometry {

// Prepares every distinct triangle mesh of `scene` (an index range the draws use; points and lines
// are left as they are) and records what it did
// in scene.report.geometry:
//  - its triangles reordered for the vertex cache, then against overdraw — except a mesh drawn
//    with an alpha-blended material (the order of its triangles is the order they blend in);
//  - its levels of detail appended to scene.indices and listed in scene.lodChains, each draw of it
//    pointing at the chain (Draw::lod) — except a deformed mesh (morph targets or a skin: its
//    error would change with the pose), which keeps its full detail only, and a mesh whose draws
//    come with a chain (the built-in spheres' tessellations), which keeps it;
//  - its vertices reordered for fetch locality when no other mesh shares them and it is not
//    deformed (the deformation data follows the scene's vertex order).
// The image is unchanged at level 0 but for ties in depth. Call once, after the draws are final.
// Precondition: the draws' ranges and materials are valid.
void prepareGeometry(scene::Scene& scene, const LodChainSettings& settings = {});

}  // namespace candela::geometry
