#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility pass's vertex stage for opaque draws (visibility/raster.glsl). gl_Position as the
// forward pass computes it, so that later forward draws test against the same depth.
#include "visibility/raster.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 0) flat out uint outEntry;

void main() {
    outEntry = push.counts.y + gl_InstanceIndex;
    vec4 world = draws[outEntry].world * vec4(inPosition, 1.0f);
    gl_Position = push.viewProjection * world;
}
