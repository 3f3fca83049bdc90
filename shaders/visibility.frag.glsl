#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility pass's fragment stage for opaque draws: the draw entry and the primitive.
#include "visibility/raster.glsl"

layout(location = 0) flat in uint inEntry;
layout(location = 0) out uvec2 outId;

void main() { outId = uvec2(inEntry + 1u, uint(gl_PrimitiveID)); }
