#pragma once
// The visibility path's per-frame tables (docs/shading-paths.md): what the compute shading needs
// of each draw-buffer entry drawn this frame (shading::VisibilityDraw: its level of detail's
// indices, its vertices, its shading list) and the frame's shading lists — a shading variant with
// one material texture set (passes/visibility/visibility_texture_sets.h) — each of which is one
// indirect dispatch. Plain data and pure functions, no Vulkan calls.

#include "passes/drawing/draw_list.h"
#include "passes/drawing/shading_variant.h"
#include "shared/visibility.h"

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace candela::passes {

// The compute shading's variant of a draw's shading variant: the same specialization constants,
// less what only rasterization uses (the alpha test and alpha to coverage happen in the visibility
// pass; blending never reaches it). Draws whose variants differ only there share one dispatch.
ShadingVariant computeShadingVariant(const ShadingVariant& drawn);

// What one compute dispatch shades: pixels of one shading variant and one texture set.
struct ShadingList {
    ShadingVariant variant;
    uint32_t textureSet = 0;
    uint32_t items = 0;  // draw-list items in it
};

struct VisibilityFrameTables {
    // Indexed like the draw buffer; entries the frame does not rasterize stay zero.
    std::vector<shading::VisibilityDraw> draws;
    // In first-use order (VisibilityDraw::list indexes it).
    std::vector<ShadingList> lists;
};

// The tables of `items` (the opaque and masked ranges of the frame's draw list) drawn with `frame`'s
// bits; `textureSetOf`, per scene material, its texture set; `vertexOffset`, per scene draw, maps a
// deformed draw's indices into the deformed vertices (kRestVertices or empty: the
// scene's own). nullopt when the frame needs more than CANDELA_VISIBILITY_MAX_LISTS lists (a
// quarter of that at 4 samples: each list has a tile list per distinct triangle in a pixel).
std::optional<VisibilityFrameTables> visibilityFrameTables(std::span<const DrawListItem> items, const MaterialKeys& keys,
                                                           std::span<const uint32_t> textureSetOf, const FrameVariant& frame,
                                                           std::span<const int32_t> vertexOffset);

// The size of the screen tiles the classification lists: 8 × 1 pixels on a CPU device (its SIMD
// rows: masked-off lanes cost as much as the others, so a tile holds no pixel the list does not
// need but at its ends), 8 × 8 on a GPU (its workgroups' pixels close together on screen).
glm::uvec2 visibilityTileSize(VkPhysicalDeviceType deviceType);

// The classification's tiling of a `width` × `height` image in tiles of `tile` pixels with `lists`
// shading lists at `samples` samples per pixel (with MSAA each list has a tile list for the k-th
// distinct triangle of its pixels, k < samples: visibility_shade.comp.glsl).
shading::VisibilityFrame visibilityExtent(uint32_t width, uint32_t height, glm::uvec2 tile, uint32_t lists, uint32_t samples = 1);

}  // namespace candela::passes
