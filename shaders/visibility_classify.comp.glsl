#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's classification, first step: per screen tile (one invocation each), the
// bits of the shading lists its pixels need (shared/visibility.h), frame.lists.y words. visibility_tiles.comp turns them into a tile list per shading list.
#include "shared/visibility.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform usampler2D visibility;
layout(std430, set = 0, binding = 1) readonly buffer VisibilityDraws {
    VisibilityDraw visibilityDraws[];
};
layout(std430, set = 0, binding = 2) writeonly buffer TileMasks {
    uint tileMasks[];  // per tile (row-major), frame.lists.y words
};
layout(std430, set = 0, binding = 3) readonly buffer Frame {
    VisibilityFrame frame;
};

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
                uint entry = texelFetch(visibility, ivec2(x, y), 0).x;
                if (entry == 0u) continue;  // no draw: the background
                uint list = visibilityDraws[entry - 1u].list;
                if (list / 32u == word) mask |= 1u << (list % 32u);
            }
        tileMasks[tile * frame.lists.y + word] = mask;
    }
}
