#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's classification, first step (visibility_classify.comp, and
// visibility_classify_msaa.comp with CANDELA_VISIBILITY_MSAA: builtin_shaders.txt): per screen tile
// (one invocation each), the bits of the shading lists its pixels need (shared/visibility.h),
// frame.lists.y words.
// visibility_tiles.comp turns them into a tile list per list.
#include "shared/visibility.h"

layout(local_size_x = 64) in;

#ifdef CANDELA_VISIBILITY_MSAA
layout(set = 0, binding = 0) uniform usampler2DMS visibility;
#else
layout(set = 0, binding = 0) uniform usampler2D visibility;
#endif
layout(std430, set = 0, binding = 1) readonly buffer VisibilityDraws {
    VisibilityDraw visibilityDraws[];
};
layout(std430, set = 0, binding = 2) writeonly buffer TileMasks {
    uint tileMasks[];  // per tile (row-major), frame.lists.y words
};
layout(std430, set = 0, binding = 3) readonly buffer Frame {
    VisibilityFrame frame;
};

// Sets in `mask` (the tile's word `word`) the bit of `list` if it is in that word.
void addList(inout uint mask, uint word, uint list) {
    if (list / 32u == word) mask |= 1u << (list % 32u);
}

void main() {
    uint tile = gl_GlobalInvocationID.x;
    if (tile >= frame.extent.w) return;
    uvec2 size = frame.lists.zw;
    ivec2 origin = ivec2(tile % frame.extent.z, tile / frame.extent.z) * ivec2(size);
    ivec2 end = min(origin + ivec2(size), ivec2(frame.extent.xy));
    // The tile's pixels' lists, word by word (almost always one word).
    for (uint word = 0u; word < frame.lists.y; ++word) {
        uint mask = 0u;
        for (int y = origin.y; y < end.y; ++y)
            for (int x = origin.x; x < end.x; ++x) {
#ifdef CANDELA_VISIBILITY_MSAA
                // The k-th distinct covered ID of the pixel's samples needs list k · L + its list
                // (visibility_shade.comp.glsl: k = 0 every covered pixel, k > 0 triangle edges).
                uint distinct = 0u;
                for (int s = 0; s < int(frame.samples.x); ++s) {
                    uvec2 id = texelFetch(visibility, ivec2(x, y), s).xy;
                    bool seen = id.x == 0u;
                    for (int t = 0; t < s; ++t) seen = seen || texelFetch(visibility, ivec2(x, y), t).xy == id;
                    if (seen) continue;
                    addList(mask, word, distinct * frame.samples.y + visibilityDraws[id.x - 1u].list);
                    ++distinct;
                }
#else
                uint entry = texelFetch(visibility, ivec2(x, y), 0).x;
                if (entry == 0u) continue;  // no draw: the background
                addList(mask, word, visibilityDraws[entry - 1u].list);
#endif
            }
        tileMasks[tile * frame.lists.y + word] = mask;
    }
}
