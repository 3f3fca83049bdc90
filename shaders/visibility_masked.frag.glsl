#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_demote_to_helper_invocation : require
// The visibility pass's fragment stage for alpha-masked draws: the alpha test (factor × COLOR_0 ×
// texture, as shading/material_eval.glsl's materialBaseColor), then the draw entry and primitive.
#define CANDELA_VISIBILITY_MASKED
#include "visibility/raster.glsl"
#include "shared/specialization_ids.h"

// The material's base colour texture (its binding in the forward programs' set 1,
// shared/shading_tables.h), bound per draw.
layout(set = 1, binding = 0) uniform sampler2D baseColorTexture;

// Alpha to coverage (MSAA, the device has alphaToOne: as the forward pass decides) over kSamples.
layout(constant_id = CANDELA_SPEC_ALPHA_TO_COVERAGE) const bool kAlphaToCoverage = false;
layout(constant_id = CANDELA_SPEC_SAMPLES) const uint kSamples = 1u;

layout(location = 0) flat in uint inEntry;
layout(location = 1) in vec2 inUv;
layout(location = 2) in float inAlpha;
layout(location = 0) out uvec2 outId;

void main() {
    MaterialData m = materials[draws[inEntry].material.x];
    float alpha = m.baseColorFactor.a * inAlpha * texture(baseColorTexture, inUv).a;
    if (kAlphaToCoverage) {
        // As the forward pass's alpha to coverage: alpha sharpened to cross the cutoff over one
        // pixel, then that share of the samples (the integer visibility image has no alpha for the
        // pipeline to turn into coverage, so the mask is written here).
        float coverage = clamp((alpha - m.alphaCutoff) / max(fwidth(alpha), 1e-4f) + 0.5f, 0.0f, 1.0f);
        uint covered = uint(coverage * float(kSamples) + 0.5f);
        if (covered == 0u) demote;
        gl_SampleMask[0] = int((1u << covered) - 1u);
    } else {
        if (alpha < m.alphaCutoff) demote;
        gl_SampleMask[0] = -1;  // written on every path: an unwritten mask is undefined
    }
    outId = uvec2(inEntry + 1u, uint(gl_PrimitiveID));
}
