#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility pass's vertex stage for alpha-masked draws: also the base colour's texture
// coordinates (after its transform) and COLOR_0's alpha.
#define CANDELA_VISIBILITY_MASKED
#include "visibility/raster.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
layout(location = 0) flat out uint outEntry;
layout(location = 1) out vec2 outUv;
layout(location = 2) out float outAlpha;

void main() {
    outEntry = push.counts.y + gl_InstanceIndex;
    DrawData draw = draws[outEntry];
    vec4 world = draw.world * vec4(inPosition, 1.0f);
    gl_Position = push.viewProjection * world;
    outUv = transformUv(materials[draw.material.x].uv[CANDELA_TEX_BASE_COLOR], inUv0, inUv1);
    outAlpha = inColor.a;
}
