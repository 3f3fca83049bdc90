// The visibility path's data layouts (docs/shading-paths.md), shared by its shaders
// (visibility*.glsl) and their passes' C++ side (passes/visibility_*.h).
#ifndef CANDELA_SHARED_VISIBILITY_H
#define CANDELA_SHARED_VISIBILITY_H

#include "shared/compat.h"

CANDELA_NAMESPACE_BEGIN

// Screen tiles (VisibilityFrame::lists.zw pixels, the workgroup size of the shading dispatches:
// specialization constants CANDELA_SPEC_TILE_X and _Y) are the unit of classification
// and of shading (one workgroup per listed tile). A CPU device runs a workgroup's invocations as
// SIMD rows in which masked-off lanes still cost, so it takes tiles of one row: a tile's lanes are
// its pixels and a tile list wastes few (passes/visibility/visibility_frame.h).
// A shading list is what one compute dispatch shades: the pixels of one shading variant whose
// materials share one set of textures (bound per dispatch). A tile records the lists its pixels
// need as bits of CANDELA_VISIBILITY_MAX_WORDS words at most.
#define CANDELA_VISIBILITY_MAX_WORDS 32u
#define CANDELA_VISIBILITY_MAX_LISTS (CANDELA_VISIBILITY_MAX_WORDS * 32u)
// VisibilityDraw::vertexOffset of a draw read from the scene's own vertices (not deformed).
#define CANDELA_REST_VERTICES (-2147483647 - 1)

// What shading needs of one draw-buffer entry (DrawData) drawn this frame, indexed like it: the
// visibility image stores (entry + 1, primitive), 0 where no draw covers the pixel.
struct VisibilityDraw {
    uint firstIndex;   // the first index of the level of detail drawn
    int vertexOffset;  // added to its indices to address the deformed vertices; CANDELA_REST_VERTICES: the scene's
    uint list;         // the shading list of its pixels
    uint flipWinding;  // 1: a mirroring transform (clockwise fronts)
};

// The frame's tiling and lists (a storage buffer of the classification and shading passes).
struct VisibilityFrame {
    uvec4 extent;  // width, height, tiles in x, tiles in all
    uvec4 lists;   // x: tile lists (N · L with MSAA), y: mask words per tile, zw: tile size
    // x: samples per pixel, N; y: shading lists, L. With MSAA, tile list k · L + l holds the pixels
    // whose k-th distinct covered ID (in sample order) shows shading list l (k < N; k > 0: pixels on
    // triangle edges).
    uvec4 samples;
};

CANDELA_NAMESPACE_END

#ifdef __cplusplus
static_assert(sizeof(candela::shading::VisibilityDraw) == 16);
static_assert(sizeof(candela::shading::VisibilityFrame) == 48);
#endif

#endif
