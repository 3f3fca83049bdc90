// The BRDFs of the forward pass, shared by GLSL and C++ (float). A double-precision reference of the
// same formulas lives in tests/ and is compared with the GPU's evaluation of this file.
//
// Cook-Torrance specular  D · V · F  with
//   D  GGX / Trowbridge-Reitz                 a = roughness² (perceptual roughness squared)
//   V  height-correlated Smith-GGX  G/(4 N·L N·V)     (default), or
//      the original project's Schlick-GGX, k = (r+1)²/8, in the same V form (for comparison)
//   F  Schlick with F0 = mix(0.04, baseColor, metallic)
// plus Lambert diffuse baseColor/π weighted by (1 − F)(1 − metallic).
// Blinn-Phong (the original project's first shader) is kept for side-by-side comparison.
//
// Numerical stability: perceptual roughness is clamped to kMinRoughness (a delta highlight from a
// point light is invisible and divides by zero); N·V is clamped away from 0 so grazing and back-
// facing (normal-mapped) views stay finite; lights behind the surface (N·L ≤ 0) contribute 0.
#ifndef CANDELA_SHARED_BRDF_H
#define CANDELA_SHARED_BRDF_H

#include "shared/compat.h"

CANDELA_NAMESPACE_BEGIN

#define CANDELA_PI 3.14159265358979f
#define CANDELA_MIN_ROUGHNESS 0.045f
#define CANDELA_MIN_NOV 1e-4f

#define CANDELA_SHADING_PBR 0u             // height-correlated Smith-GGX visibility
#define CANDELA_SHADING_PBR_SCHLICK_GGX 1u // the original project's Schlick-GGX geometry term
#define CANDELA_SHADING_BLINN_PHONG 2u     // the original project's Blinn-Phong

CANDELA_FN float clampRoughness(float perceptualRoughness) {
    return clamp(perceptualRoughness, CANDELA_MIN_ROUGHNESS, 1.0f);
}

// Specular anti-aliasing (docs/shading.md): the perceptual roughness widened, in α² = roughness⁴,
//  - by the normal's change across the pixel (geometric specular AA, Tokuyoshi & Kaplanyan 2019,
//    "Improved Geometric Specular Antialiasing"): + min(2σ² · (|∂n/∂x|² + |∂n/∂y|²), κ) with the
//    pixel filter's variance σ² = 0.25 and the clamp κ = 0.18; `normalChange` is the sum of squares;
//  - by what a normal-map mip averaged away (Toksvig's idea, as a von Mises-Fisher lobe: Han et al.
//    2007, Neubelt & Pettineo 2013): a mean normal of length r has κ_vMF = (3r − r³)/(1 − r²) and
//    adds 2/κ_vMF; r = 1 (mip 0, or normals that agree) adds nothing, r → 0 gives α² = 1.
CANDELA_FN float specularAntiAliasedRoughness(float perceptualRoughness, float normalChange, float meanNormalLength) {
    float a = perceptualRoughness * perceptualRoughness;
    float a2 = a * a + min(2.0f * 0.25f * max(normalChange, 0.0f), 0.18f);
    float r = clamp(meanNormalLength, 0.0f, 1.0f);
    if (r < 1e-4f) return 1.0f;
    if (r < 0.9999f) a2 += 2.0f * (1.0f - r * r) / (3.0f * r - r * r * r);
    return sqrt(sqrt(min(a2, 1.0f)));
}

// GGX normal distribution. `a` = clamped roughness². Filament's form, with 1 − (N·H)² passed in as
// |N × H|²: from a float N·H near 1 (spacing 6e-8), 1 − N·H·N·H cancels catastrophically where the
// lobe of the smallest roughness lives (1 − (N·H)² ~ a² = 4e-6): up to 10% error in D.
CANDELA_FN float distributionGgx(float NoH, float oneMinusNoH2, float a) {
    float an = NoH * a;
    float k = a / (oneMinusNoH2 + an * an);
    return k * k * (1.0f / CANDELA_PI);
}

// Height-correlated Smith-GGX visibility V = G / (4 N·L N·V). NoV > 0, NoL ≥ 0.
CANDELA_FN float visibilitySmithGgxCorrelated(float NoV, float NoL, float a) {
    float a2 = a * a;
    float ggxV = NoL * sqrt(NoV * NoV * (1.0f - a2) + a2);
    float ggxL = NoV * sqrt(NoL * NoL * (1.0f - a2) + a2);
    return 0.5f / max(ggxV + ggxL, 1e-12f);
}

// The original project's Schlick-GGX geometry term with k = (r+1)²/8 (r = perceptual roughness),
// as a visibility: G1(n)/n = 1/(n(1−k)+k), so V = 1 / (4 (N·V(1−k)+k) (N·L(1−k)+k)) — no division
// by N·V or N·L.
CANDELA_FN float visibilitySchlickGgx(float NoV, float NoL, float roughness) {
    float k = (roughness + 1.0f) * (roughness + 1.0f) / 8.0f;
    return 1.0f / (4.0f * (NoV * (1.0f - k) + k) * (NoL * (1.0f - k) + k));
}

CANDELA_FN vec3 fresnelSchlick(float VoH, vec3 f0) {
    float x = 1.0f - clamp(VoH, 0.0f, 1.0f);
    float x2 = x * x;
    return f0 + (vec3(1.0f) - f0) * (x2 * x2 * x);
}

// The diffuse and specular parts of a reflection (the debug views show them apart).
struct BrdfLobes {
    vec3 diffuse;
    vec3 specular;
};

// The angles between N, V, L and the half vector H that the BRDFs read, with the clamps above.
// Only meaningful when NoL > 0 (the light is in front of the surface).
struct BrdfAngles {
    float NoL;
    float NoV;           // clamped to ≥ CANDELA_MIN_NOV
    float NoH;           // clamped to [0, 1]
    float VoH;           // clamped to [0, 1]
    float oneMinusNoH2;  // |N × H|² (1 where N·H was clamped to 0), for distributionGgx
    float specularWeight;  // 0 when V = −L: no half vector, no specular term
};

CANDELA_FN BrdfAngles brdfAngles(vec3 N, vec3 V, vec3 L) {
    BrdfAngles g;
    g.NoL = dot(N, L);
    g.NoV = max(dot(N, V), CANDELA_MIN_NOV);
    vec3 H = V + L;
    float lengthH = length(H);
    // V = −L (only possible with V below the surface, e.g. normal-mapped back faces): there is no
    // half vector and no mirror configuration, so there is no specular term.
    g.specularWeight = lengthH > 1e-6f ? 1.0f : 0.0f;
    H = lengthH > 1e-6f ? H / lengthH : N;
    g.NoH = clamp(dot(N, H), 0.0f, 1.0f);
    g.VoH = clamp(dot(V, H), 0.0f, 1.0f);
    vec3 NxH = cross(N, H);
    g.oneMinusNoH2 = g.NoH > 0.0f ? dot(NxH, NxH) : 1.0f;
    return g;
}

// Reflected radiance per unit incident radiance from direction L, f(V, L) · (N·L), as its diffuse
// and specular lobes. N, V, L unit vectors; V points to the viewer, L to the light.
CANDELA_FN BrdfLobes brdfLobesTimesCosine(vec3 N, vec3 V, vec3 L, vec3 baseColor, float metallic,
                                          float perceptualRoughness, uint model) {
    BrdfLobes lobes;
    lobes.diffuse = vec3(0.0f);
    lobes.specular = vec3(0.0f);
    BrdfAngles g = brdfAngles(N, V, L);
    if (g.NoL <= 0.0f) return lobes;
    float NoL = g.NoL;
    float NoV = g.NoV;
    float NoH = g.NoH;
    float specularWeight = g.specularWeight;

    if (model == CANDELA_SHADING_BLINN_PHONG) {
        // The original project's shader: diffuse + specular, no energy conservation.
        float shininess = 2.0f / max(pow(clampRoughness(perceptualRoughness), 4.0f), 1e-4f) - 2.0f;
        // GLSL's pow(0, y ≤ 0) is undefined (lavapipe returns 0, C++ 1): roughness 1 gives shininess 0.
        float specular = shininess > 0.0f ? pow(NoH, shininess) : 1.0f;
        lobes.diffuse = baseColor * NoL;
        lobes.specular = vec3(specular * specularWeight * NoL);
        return lobes;
    }
    float roughness = clampRoughness(perceptualRoughness);
    float a = roughness * roughness;
    vec3 f0 = mix(vec3(0.04f), baseColor, metallic);
    vec3 F = fresnelSchlick(g.VoH, f0);
    float D = distributionGgx(NoH, g.oneMinusNoH2, a);
    float Vis = model == CANDELA_SHADING_PBR_SCHLICK_GGX ? visibilitySchlickGgx(NoV, NoL, roughness)
                                                          : visibilitySmithGgxCorrelated(NoV, NoL, a);
    lobes.specular = F * (D * Vis * specularWeight) * NoL;
    lobes.diffuse = (vec3(1.0f) - F) * (1.0f - metallic) * baseColor * (1.0f / CANDELA_PI) * NoL;
    return lobes;
}

// f(V, L) · (N·L): both lobes.
CANDELA_FN vec3 brdfTimesCosine(vec3 N, vec3 V, vec3 L, vec3 baseColor, float metallic, float perceptualRoughness,
                                uint model) {
    BrdfLobes lobes = brdfLobesTimesCosine(N, V, L, baseColor, metallic, perceptualRoughness, model);
    return lobes.diffuse + lobes.specular;
}

CANDELA_NAMESPACE_END

#endif
