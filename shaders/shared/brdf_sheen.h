// KHR_materials_sheen: the Charlie sheen lobe over the material, for punctual and image-based
// light. One of the material layers (shared/brdf_layers.h), shared by GLSL and C++
// (float); a double-precision reference of the same formulas lives in tests/unit/brdf_reference.h.
//
// Sheen layer (KHR_materials_sheen): the Charlie distribution with the Estevez-Kulla visibility
// (Conty Estevez & Kulla 2017, as the extension's specification gives them), over the material
// scaled by 1 − max(sheenColor) · E(N·V), E the sheen lobe's directional albedo (a LUT):
//   sheened = sheenColor · D_c · Vis_c + material · (1 − max(sheenColor) · E(N·V)),
// and the coat, when there is one, over both.
#ifndef CANDELA_SHARED_BRDF_SHEEN_H
#define CANDELA_SHARED_BRDF_SHEEN_H

#include "shared/brdf.h"

CANDELA_NAMESPACE_BEGIN

// ---- Sheen ----

// The sheen distribution's α_g = roughness², the perceptual roughness clamped like the GGX one:
// below it 1/α_g overflows the Charlie exponent (docs/materials.md).
CANDELA_FN float sheenAlpha(float perceptualRoughness) {
    float r = clamp(perceptualRoughness, CANDELA_MIN_ROUGHNESS, 1.0f);
    return r * r;
}

// Charlie: D = (2 + 1/α) sin(θ_h)^(1/α) / 2π, from sin²θ_h = |N × H|² (no cancellation near N·H = 1).
CANDELA_FN float distributionCharlie(float sin2h, float alpha) {
    float invAlpha = 1.0f / alpha;
    return (2.0f + invAlpha) * pow(sin2h, 0.5f * invAlpha) * (1.0f / (2.0f * CANDELA_PI));
}

// The Estevez-Kulla fit L(x) of the sheen's Λ, interpolated in (1 − α)².
CANDELA_FN float sheenL(float x, float alpha) {
    float t = (1.0f - alpha) * (1.0f - alpha);
    float a = mix(21.5473f, 25.3245f, t);
    float b = mix(3.82987f, 3.32435f, t);
    float c = mix(0.19823f, 0.16801f, t);
    float d = mix(-1.97760f, -1.27393f, t);
    float e = mix(-4.32054f, -4.85967f, t);
    return a / (1.0f + b * pow(x, c)) + d * x + e;
}

CANDELA_FN float sheenLambda(float cosTheta, float alpha) {
    return cosTheta < 0.5f ? exp(sheenL(cosTheta, alpha)) : exp(2.0f * sheenL(0.5f, alpha) - sheenL(1.0f - cosTheta, alpha));
}

// The sheen lobe's f · N·L toward L (colourless): D_c / (4 N·V (1 + Λ(N·V) + Λ(N·L))) — the
// visibility's N·L cancels against the cosine, so grazing light needs no division.
CANDELA_FN float sheenTimesCosine(vec3 N, vec3 V, vec3 L, float perceptualRoughness) {
    BrdfAngles g = brdfAngles(N, V, L);
    if (g.NoL <= 0.0f) return 0.0f;
    float alpha = sheenAlpha(perceptualRoughness);
    float D = distributionCharlie(g.oneMinusNoH2, alpha);
    float NoL = min(g.NoL, 1.0f);
    float NoV = min(g.NoV, 1.0f);
    return D * g.specularWeight / (4.0f * NoV * (1.0f + sheenLambda(NoV, alpha) + sheenLambda(NoL, alpha)));
}

// The sheen of one shading point: colour (sheenColorFactor × texture), perceptual roughness, and
// what it lets through to the material beneath, 1 − max(colour) · min(E(N·V), 1) with E = `albedo`
// (the sheen LUT at N·V and this roughness). E exceeds 1 at grazing views below sheen roughness
// ≈ 0.25 (the Estevez-Kulla Λ fit does not conserve energy there; 4.1 at roughness 0, N·V 1e-4):
// clamped, the material beneath never gets a negative weight.
struct Sheen {
    vec3 color;
    float roughness;
    float albedo;      // min(E(N·V), 1)
    float baseWeight;  // 1 − max(colour) · albedo
};

CANDELA_FN Sheen sheenLayer(vec3 color, float perceptualRoughness, float albedo) {
    Sheen s;
    s.color = color;
    s.roughness = perceptualRoughness;
    s.albedo = min(albedo, 1.0f);
    s.baseWeight = 1.0f - max(color.x, max(color.y, color.z)) * s.albedo;
    return s;
}

// Where the image-based sheen reads the Charlie-prefiltered cube: normalize(mix(N, R, weight)),
// R = reflect(−V, N), weight CANDELA_SHEEN_MIRROR_WEIGHT = 0: about the normal N. The cube holds the lobe for n = v (a ring
// about its direction, exact at normal incidence); away from it the sheen lobe is a back-scattering
// lobe that stays about N and leans toward V, never toward the mirror direction — at grazing views
// R lies on the far side, and a ring about it takes in light from below the surface. Against the
// lobe integrated over the environment in double precision (tests/unit/shared/layer_ibl_error_test.cpp,
// docs/materials.md) the mean relative error is 0.47 about N, 0.82 about R (weight 1: what the
// forward pass did, and what the Khronos sample viewer does).
#define CANDELA_SHEEN_MIRROR_WEIGHT 0.0f
CANDELA_FN vec3 sheenLookupDirection(vec3 N, vec3 V) {
    vec3 d = mix(N, reflect(-V, N), CANDELA_SHEEN_MIRROR_WEIGHT);
    float lengthD = length(d);
    return lengthD > 1e-6f ? d / lengthD : N;
}

// The sheen under image-based light: sheenColor · min(E(N·V), 1) · `prefiltered` (the sheen cube
// about sheenLookupDirection), darkened by the occlusion. With a white sheen in a uniform
// environment it reflects exactly what the material beneath loses (white furnace).
CANDELA_FN vec3 iblSheen(Sheen s, vec3 prefiltered, float occlusion) {
    return s.color * (s.albedo * occlusion) * prefiltered;
}

CANDELA_NAMESPACE_END

#endif
