// KHR_materials_clearcoat: the coat's GGX lobe over the material, for punctual and image-based
// light. One of the material layers (shared/brdf_layers.h), shared by GLSL and C++
// (float); a double-precision reference of the same formulas lives in tests/unit/brdf_reference.h.
//
// Clearcoat layer (KHR_materials_clearcoat): a GGX lobe on its own normal N_c and roughness, over
// the material, per the extension's specification:
//   coated = mix(material, D(α_c) · Vis(α_c), clearcoat · F_c),  F_c = 0.04 + 0.96 (1 − N_c·V)⁵,
// the Fresnel being the mix weight (taken at N_c·V, not V·H, so that the layering conserves
// energy); the emission lies under the coat and is darkened by the same 1 − clearcoat · F_c.
#ifndef CANDELA_SHARED_BRDF_CLEARCOAT_H
#define CANDELA_SHARED_BRDF_CLEARCOAT_H

#include "shared/brdf.h"

CANDELA_NAMESPACE_BEGIN

// ---- Clearcoat ----

// The coat of one shading point: its weight (clearcoat factor × texture), perceptual roughness,
// unit normal N_c, N_c·V (clamped like the core's N·V), its Fresnel F_c and what it lets through to
// the material beneath, 1 − clearcoat · F_c (computed without cancellation: near-grazing views
// leave 1 − F_c ≈ 0.96 · 5 N_c·V).
struct Clearcoat {
    float weight;
    float roughness;
    vec3 normal;
    float NoV;
    float fresnel;
    float baseWeight;
};

// A coat of weight `clearcoat` and perceptual roughness `perceptualRoughness` on unit normal `Nc`,
// seen from V.
CANDELA_FN Clearcoat clearcoatLayer(float clearcoat, float perceptualRoughness, vec3 Nc, vec3 V) {
    Clearcoat c;
    c.weight = clearcoat;
    c.roughness = perceptualRoughness;
    c.normal = Nc;
    c.NoV = clamp(dot(Nc, V), CANDELA_MIN_NOV, 1.0f);
    float x = 1.0f - c.NoV;
    float x2 = x * x;
    c.fresnel = 0.04f + 0.96f * (x2 * x2 * x);
    // 1 − x⁵ = (1 − x)(1 + x + x² + x³ + x⁴).
    float oneMinusX5 = c.NoV * (1.0f + x + x2 + x2 * x + x2 * x2);
    c.baseWeight = (1.0f - clearcoat) + clearcoat * 0.96f * oneMinusX5;
    return c;
}

// The coat's reflection toward light direction L, times N_c·L (colourless):
// clearcoat · F_c · D · Vis · N_c·L. `model` as in brdfLobesTimesCosine (Cook-Torrance only).
CANDELA_FN float clearcoatTimesCosine(Clearcoat c, vec3 V, vec3 L, uint model) {
    BrdfAngles g = brdfAngles(c.normal, V, L);
    if (g.NoL <= 0.0f) return 0.0f;
    float roughness = clampRoughness(c.roughness);
    float a = roughness * roughness;
    float D = distributionGgx(g.NoH, g.oneMinusNoH2, a);
    float Vis = model == CANDELA_SHADING_PBR_SCHLICK_GGX ? visibilitySchlickGgx(g.NoV, g.NoL, roughness)
                                                          : visibilitySmithGgxCorrelated(g.NoV, g.NoL, a);
    return c.weight * c.fresnel * D * Vis * g.specularWeight * g.NoL;
}

// The coat under image-based light: clearcoat · F_c · (prefiltered · (A + B) + irradiance · (1 − A − B)).
// `lut` is the split sum's (A, B) at (N_c·V, coat roughness), `prefiltered` the specular cube in the
// mirror direction about N_c at the coat's roughness. The second term is the multiscatter
// compensation (Fdez-Agüera, with the Fresnel outside the lobe: F_avg = 1), returned only with
// `multiscatter`: with it the coat's directional albedo is exactly clearcoat · F_c, which the
// material beneath loses, so a coat over a white furnace-neutral material reflects exactly 1.
// Occlusion as for the core's specular (`specularOcclusionFactor`) and multiscatter (`diffuseOcclusion`).
CANDELA_FN vec3 iblClearcoat(Clearcoat c, vec3 prefiltered, vec3 irradiance, vec2 lut, bool multiscatter,
                             float diffuseOcclusion, float specularOcclusionFactor) {
    vec3 single = prefiltered * ((lut.x + lut.y) * specularOcclusionFactor);
    vec3 multi = multiscatter ? irradiance * ((1.0f - (lut.x + lut.y)) * diffuseOcclusion) : vec3(0.0f);
    return (single + multi) * (c.weight * c.fresnel);
}

CANDELA_NAMESPACE_END

#endif
