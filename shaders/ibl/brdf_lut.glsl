#version 460
#extension GL_GOOGLE_include_directive : require
// ibl_brdf_lut.comp and its variants (builtin_shaders.txt: they define CANDELA_LUT_FORMAT, the
// storage format qualifier).
// IBL precompute: the split-sum BRDF LUT. Texel (x, y) holds, for N·V = x/(size−1) and perceptual
// roughness y/(size−1), A = ∫(1 − Fc)·f·cos and B = ∫Fc·f·cos of the forward pass's specular BRDF
// (GGX, height-correlated Smith visibility; Fc = (1 − v·h)^5), by sampling GGX visible normals
// (weight G2/G1(v) ≤ 1, so grazing views converge as fast as the rest). A + B is the directional
// albedo E(μ) that the multiscatter compensation needs.
// Roughness 0 is a perfect mirror here (A + B = 1): no clamp, unlike punctual lights.
#include "shared/brdf.h"
#include "shared/ibl.h"

layout(local_size_x = CANDELA_IBL_GROUP, local_size_y = CANDELA_IBL_GROUP) in;

layout(set = 0, binding = 0, CANDELA_LUT_FORMAT) uniform writeonly image2D lut;

layout(push_constant) uniform Push {
    IblLutPush push;
};

void main() {
    uvec2 id = gl_GlobalInvocationID.xy;
    if (id.x >= push.size || id.y >= push.size) return;
    float NoV = max(float(id.x) / float(push.size - 1u), CANDELA_MIN_NOV);
    float roughness = float(id.y) / float(push.size - 1u);
    float alpha = roughness * roughness;
    vec3 v = vec3(sqrt(1.0f - NoV * NoV), 0.0f, NoV);
    vec2 ab = vec2(0.0f);
    for (uint i = 0u; i < push.samples; ++i) {
        vec3 h = sampleGgxVisibleNormal(v, alpha, hammersley(i, push.samples));
        float VoH = dot(v, h);
        vec3 l = 2.0f * VoH * h - v;
        float NoL = l.z;
        if (NoL <= 0.0f || VoH <= 0.0f) continue;
        // pdf(l) = G1(v)·D·v·h / (4 n·v · v·h), so f·cos/pdf = Vis · 4 · n·l · n·v / G1(v) = G2/G1(v).
        float weight = visibilitySmithGgxCorrelated(NoV, NoL, alpha) * 4.0f * NoL * NoV / smithG1(NoV, alpha);
        float x = 1.0f - VoH;
        float x2 = x * x;
        float fc = x2 * x2 * x;
        ab += vec2(1.0f - fc, fc) * weight;
    }
    imageStore(lut, ivec2(id), vec4(ab / float(push.samples), 0.0f, 0.0f));
}
