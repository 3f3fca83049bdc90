#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_demote_to_helper_invocation : require
// The visibility pass's fragment stage for alpha-masked draws: the alpha test (factor × COLOR_0 ×
// texture, as forward/material_eval.glsl's materialBaseColor), then the draw entry and primitive.
#define CANDELA_VISIBILITY_MASKED
#include "visibility/raster.glsl"

// The material's base colour texture (its binding in the forward programs' set 1,
// shared/forward_tables.h), bound per draw.
layout(set = 1, binding = 0) uniform sampler2D baseColorTexture;

layout(location = 0) flat in uint inEntry;
layout(location = 1) in vec2 inUv;
layout(location = 2) in float inAlpha;
layout(location = 0) out uvec2 outId;

void main() {
    MaterialData m = materials[draws[inEntry].material.x];
    float alpha = m.baseColorFactor.a * inAlpha * texture(baseColorTexture, inUv).a;
    if (alpha < m.alphaCutoff) demote;
    outId = uvec2(inEntry + 1u, uint(gl_PrimitiveID));
}
