// The visibility pass (docs/shading-paths.md): opaque and alpha-masked draws rasterized into depth
// and the visibility image, (draw entry + 1, primitive) per pixel. Included by visibility.vert /
// visibility.frag (opaque draws: position only, no material) and visibility_masked.vert /
// visibility_masked.frag (CANDELA_VISIBILITY_MASKED: the base colour's alpha against the cutoff,
// the only part of the material the pass reads).
#include "shading/scene_buffers.glsl"
#include "shared/visibility.h"

CANDELA_DRAWS_BLOCK
#ifdef CANDELA_VISIBILITY_MASKED
CANDELA_MATERIALS_BLOCK
#endif
layout(push_constant) uniform Push {
    FramePush push;  // viewProjection, counts.y: the draw's (first instance's) entry
};
