#version 460
#extension GL_GOOGLE_include_directive : require
// ibl_sheen_lut.comp and its variants (builtin_shaders.txt: they define CANDELA_LUT_FORMAT, the
// storage format qualifier).
// The sheen LUT (KHR_materials_sheen): texel (x, y) holds the sheen lobe's directional albedo
// E(N·V, r) = ∫ f_sheen · N·L dω_L for N·V = x/(size−1) and perceptual sheen roughness
// r = y/(size−1) (clamped as shared/brdf_sheen.h clamps it), which scales the material beneath
// the sheen and the sheen's image-based light. A deterministic midpoint quadrature over the half
// vector — cos θ_h in kCosineSteps, φ_h over [0, π] (the lobe is symmetric about the view plane) in
// kAzimuthSteps — with dω_L = 4 V·H dω_h; the Charlie peak (width ≈ √α in cos θ_h) spans at least
// 6 steps at the smallest roughness.
#include "shared/brdf_sheen.h"
#include "shared/ibl.h"

layout(local_size_x = CANDELA_IBL_GROUP, local_size_y = CANDELA_IBL_GROUP) in;

layout(set = 0, binding = 0, CANDELA_LUT_FORMAT) uniform writeonly image2D lut;

layout(push_constant) uniform Push {
    IblLutPush push;  // samples: unused
};

const uint kCosineSteps = 128u;
const uint kAzimuthSteps = 32u;

void main() {
    uvec2 id = gl_GlobalInvocationID.xy;
    if (id.x >= push.size || id.y >= push.size) return;
    float NoV = max(float(id.x) / float(push.size - 1u), CANDELA_MIN_NOV);
    float roughness = float(id.y) / float(push.size - 1u);
    vec3 n = vec3(0.0f, 0.0f, 1.0f);
    vec3 v = vec3(sqrt(1.0f - NoV * NoV), 0.0f, NoV);
    float du = 1.0f / float(kCosineSteps);
    float dphi = CANDELA_PI / float(kAzimuthSteps);
    float sum = 0.0f;
    for (uint i = 0u; i < kCosineSteps; ++i) {
        float cosH = (float(i) + 0.5f) * du;
        float sinH = sqrt(1.0f - cosH * cosH);
        for (uint j = 0u; j < kAzimuthSteps; ++j) {
            float phi = (float(j) + 0.5f) * dphi;
            vec3 h = vec3(sinH * cos(phi), sinH * sin(phi), cosH);
            float VoH = dot(v, h);
            if (VoH <= 0.0f) continue;
            vec3 l = 2.0f * VoH * h - v;
            if (l.z <= 0.0f) continue;
            sum += sheenTimesCosine(n, v, normalize(l), roughness) * 4.0f * VoH;
        }
    }
    // Both halves of the azimuth range.
    imageStore(lut, ivec2(id), vec4(2.0f * sum * du * dphi, 0.0f, 0.0f, 0.0f));
}
