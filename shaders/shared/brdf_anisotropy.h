// KHR_materials_anisotropy: the material's GGX lobe made anisotropic, and the bent normal of its
// image-based approximation. One of the material layers (shared/brdf_layers.h), shared by GLSL and C++
// (float); a double-precision reference of the same formulas lives in tests/unit/brdf_reference.h.
//
// Anisotropy (KHR_materials_anisotropy): the material's GGX lobe becomes anisotropic about the
// direction T (in the tangent plane) with α_t = mix(α, 1, anisotropy²) along T and α_b = α across,
// D = 1 / (π α_t α_b ((T·H/α_t)² + (B·H/α_b)² + (N·H)²)²) and the height-correlated anisotropic
// Smith visibility (Heitz 2014), as the extension's specification gives them.
#ifndef CANDELA_SHARED_BRDF_ANISOTROPY_H
#define CANDELA_SHARED_BRDF_ANISOTROPY_H

#include "shared/brdf_specular.h"

CANDELA_NAMESPACE_BEGIN

// ---- Anisotropy ----

// The anisotropy of one shading point: strength (0 … 1) and the unit directions T (along the
// brushing) and B = N × T.
struct Anisotropy {
    float strength;
    vec3 t;
    vec3 b;
};

CANDELA_FN Anisotropy anisotropyLayer(float strength, vec3 t, vec3 b) {
    Anisotropy a;
    a.strength = strength;
    a.t = t;
    a.b = b;
    return a;
}

// Anisotropic GGX D in Filament's form: α_t α_b · (α_t α_b / |f|²)² / π with f = (α_b T·H,
// α_t B·H, α_t α_b N·H) — a sum of squares, so no cancellation near the peak.
CANDELA_FN float distributionGgxAnisotropic(float NoH, float ToH, float BoH, float at, float ab) {
    float a2 = at * ab;
    vec3 f = vec3(ab * ToH, at * BoH, a2 * NoH);
    float w2 = a2 / dot(f, f);
    return a2 * w2 * w2 * (1.0f / CANDELA_PI);
}

// The height-correlated anisotropic Smith visibility G / (4 N·L N·V).
CANDELA_FN float visibilityGgxAnisotropic(float NoV, float NoL, float ToV, float BoV, float ToL, float BoL, float at, float ab) {
    float lambdaV = NoL * length(vec3(at * ToV, ab * BoV, NoV));
    float lambdaL = NoV * length(vec3(at * ToL, ab * BoL, NoL));
    return 0.5f / max(lambdaV + lambdaL, 1e-12f);
}

// The material's lobes toward L with its GGX lobe made anisotropic by `an` (the Fresnel and the
// diffuse weighting as in brdfLobesTimesCosine, or with `specularLayer` as in
// brdfLobesTimesCosineDielectric).
CANDELA_FN BrdfLobes brdfLobesTimesCosineAnisotropic(vec3 N, vec3 V, vec3 L, vec3 baseColor, float metallic,
                                                     float perceptualRoughness, bool specularLayer, DielectricFresnel d,
                                                     Anisotropy an) {
    BrdfLobes lobes;
    lobes.diffuse = vec3(0.0f);
    lobes.specular = vec3(0.0f);
    BrdfAngles g = brdfAngles(N, V, L);
    if (g.NoL <= 0.0f) return lobes;
    vec3 H = V + L;
    float lengthH = length(H);
    H = lengthH > 1e-6f ? H / lengthH : N;
    float roughness = clampRoughness(perceptualRoughness);
    float ab = roughness * roughness;
    float at = mix(ab, 1.0f, an.strength * an.strength);
    float D = distributionGgxAnisotropic(g.NoH, dot(an.t, H), dot(an.b, H), at, ab);
    float Vis = visibilityGgxAnisotropic(g.NoV, g.NoL, dot(an.t, V), dot(an.b, V), dot(an.t, L), dot(an.b, L), at, ab);
    if (specularLayer) return dielectricMaterialLobes(g, D * Vis, baseColor, metallic, d);
    // The core's Fresnel and diffuse weight (shared/brdf.h).
    vec3 F = fresnelSchlick(g.VoH, mix(vec3(0.04f), baseColor, metallic));
    lobes.specular = F * (D * Vis * g.specularWeight) * g.NoL;
    lobes.diffuse = (vec3(1.0f) - F) * (1.0f - metallic) * baseColor * (1.0f / CANDELA_PI) * g.NoL;
    return lobes;
}

// The perceptual roughness the image-based approximation reads the split sum's albedo at (the BRDF
// LUT and the specular occlusion): √((α_t + α_b)/2), the mean of the stretched lobe's two
// roughnesses (α_b = roughness², α_t = mix(α_b, 1, strength²), unclamped, so strength 0 is the
// material's roughness exactly). The isotropic E overstates the stretched lobe's energy (its
// directional albedo is 0.50-0.62 against E's 0.78-0.99 at strength 1). The prefiltered mip and
// the bend stay at the material's roughness, which keeps the streak as sharp as the narrow axis
// (docs/materials.md: reading those at this roughness too measures closer but blurs the streaks
// away; tests/unit/shared/anisotropy_ibl_error_test.cpp measures both).
CANDELA_FN float anisotropicIblRoughness(float perceptualRoughness, float strength) {
    float ab = perceptualRoughness * perceptualRoughness;
    float at = mix(ab, 1.0f, strength * strength);
    return sqrt(0.5f * (at + ab));
}

// The image-based approximation (the extension's implementation notes, as the Khronos sample
// viewer does): the prefiltered environment is read about a normal bent toward the plane across
// the brushing, the more so the stronger and smoother the anisotropy, at the material's
// `perceptualRoughness`.
CANDELA_FN vec3 anisotropicBentNormal(vec3 N, vec3 V, float perceptualRoughness, Anisotropy an) {
    vec3 tangentAcross = cross(an.b, V);
    vec3 anisotropicNormal = cross(tangentAcross, an.b);
    float bend = 1.0f - an.strength * (1.0f - perceptualRoughness);
    float bend2 = bend * bend;
    vec3 bent = mix(anisotropicNormal, N, bend2 * bend2);
    float lengthBent = length(bent);
    return lengthBent > 1e-6f ? bent / lengthBent : N;
}

CANDELA_NAMESPACE_END

#endif
