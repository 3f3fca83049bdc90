#pragma once
// Scenes that need no files.

#include "scene/scene.h"

namespace candela::assets {

// The original project's showcase: a 7×7 grid of UV spheres (radius 1, 2.5 m apart) in the XY
// plane facing +Z (framed head-on: Scene::framingAngles), metallic rising left → right (0 → 1)
// and roughness bottom → top (0.05 → 1), base colour a dark red, lit by 4 white point lights of
// 300 cd in front of the grid's corners.
// The spheres (64 × 32) have levels of detail: 32 × 16, 24 × 12, 16 × 8, 12 × 6 and 8 × 4.
// With `side` other than 7: side × side spheres over the same 7 × 7 materials (each sphere wearing
// its part of the grid's), the lights as far out, relative to the grid, and as bright where the
// spheres are (`bench --grid N`). With `materialPerSphere` every sphere wears a material of its
// own (side² materials, a stress scene: --distinct-materials): its grid cell's metallic and
// roughness, and a base colour cycling red, green, blue by material index. Throws
// std::invalid_argument for side 0.
scene::Scene makeSphereGrid(uint32_t side = 7, bool materialPerSphere = false);

// Appends a UV sphere (sectors around Y, stacks from +Y to −Y) with normals, tangents along +φ
// and UVs, to `scene`'s vertex and index arrays; returns the first index and index count.
std::pair<uint32_t, uint32_t> appendUvSphere(scene::Scene& scene, float radius, uint32_t sectors, uint32_t stacks);

}  // namespace candela::assets
