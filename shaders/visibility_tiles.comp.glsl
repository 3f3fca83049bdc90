#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's classification, second step: one workgroup per shading list gathers the
// tiles whose mask has its bit into its tile list and writes its indirect dispatch arguments
// (tiles, 1, 1): a list no pixel needs dispatches nothing.
#include "shared/visibility.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer TileMasks {
    uint tileMasks[];
};
layout(std430, set = 0, binding = 1) writeonly buffer TileLists {
    uint tileLists[];  // per list, frame.extent.w entries: tile x | tile y << 16
};
layout(std430, set = 0, binding = 2) writeonly buffer DispatchArguments {
    uint arguments[];  // per list, VkDispatchIndirectCommand (x, y, z)
};
layout(std430, set = 0, binding = 3) readonly buffer Frame {
    VisibilityFrame frame;
};

shared uint count;

void main() {
    uint list = gl_WorkGroupID.x;
    uint word = list / 32u, bit = 1u << (list % 32u);
    if (gl_LocalInvocationIndex == 0u) count = 0u;
    barrier();
    for (uint base = 0u; base < frame.extent.w; base += gl_WorkGroupSize.x) {
        uint tile = base + gl_LocalInvocationIndex;
        if (tile < frame.extent.w && (tileMasks[tile * frame.lists.y + word] & bit) != 0u) {
            uint slot = atomicAdd(count, 1u);
            tileLists[list * frame.extent.w + slot] = (tile % frame.extent.z) | ((tile / frame.extent.z) << 16u);
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        arguments[3u * list] = count;
        arguments[3u * list + 1u] = 1u;
        arguments[3u * list + 2u] = 1u;
    }
}
