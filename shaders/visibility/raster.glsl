// The visibility pass (docs/shading-paths.md): opaque and alpha-masked draws rasterized into depth
// and the visibility image, (draw entry + 1, primitive) per pixel. Included by visibility.vert /
// visibility.frag (opaque draws: position only, no material) and visibility_masked.vert /
// visibility_masked.frag (CANDELA_VISIBILITY_MASKED: the base colour's alpha against the cutoff,
// the only part of the material the pass reads).
#include "shared/scene_data.h"
#include "shared/visibility.h"

layout(std430, set = 0, binding = 1) readonly buffer Draws {
    DrawData draws[];
};
#ifdef CANDELA_VISIBILITY_MASKED
layout(std430, set = 0, binding = 2) readonly buffer Materials {
    MaterialData materials[];
};
#endif
layout(push_constant) uniform Push {
    FramePush push;  // viewProjection, counts.y: the draw's (first instance's) entry
};
