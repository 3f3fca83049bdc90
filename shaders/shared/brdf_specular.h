// KHR_materials_ior and KHR_materials_specular: the dielectric Fresnel of a material and the
// Appendix B mix it takes part in, for punctual and image-based light. One of the material layers
// (shared/brdf_layers.h), shared by GLSL and C++ (float); a double-precision reference of the same
// formulas lives in tests/unit/brdf_reference.h.
//
// Specular layer (KHR_materials_ior, KHR_materials_specular): the dielectric Fresnel
//   F_d = f0 + (f90 − f0)(1 − V·H)⁵,  f0 = min(((ior − 1)/(ior + 1))² · specularColor, 1) · specular,
//   f90 = specular,
// and the material, per glTF 2.0 Appendix B, mix(dielectric, metal, metallic) with
//   dielectric = F_d · specular_brdf + (1 − max(F_d)) · diffuse_brdf,  metal = F_m · specular_brdf,
//   F_m = Schlick(baseColor, 1).
// The core path (shared/brdf.h) weights the diffuse by (1 − F)(1 − metallic), F the mixed Fresnel;
// the two agree at metallic 0 and 1 (docs/materials.md gives the difference in between).
//
// The thin film of KHR_materials_iridescence (shared/brdf_iridescence.h) is carried in the same
// DielectricFresnel and mixed in by the Fresnel functions here.
#ifndef CANDELA_SHARED_BRDF_SPECULAR_H
#define CANDELA_SHARED_BRDF_SPECULAR_H

#include "shared/brdf.h"

CANDELA_NAMESPACE_BEGIN

// The Fresnel of the dielectric part of a material: reflectance at normal (f0) and grazing (f90)
// incidence.
// 1 − f0 is kept apart, computed without cancellation: near f0 = 1 (large IORs, IOR 0) the diffuse
// weight 1 − F would otherwise lose all its digits in float.
// With iridescence, the thin film's Fresnel at N·V over the dielectric (filmDielectric, and 1 minus it
// without cancellation) and over the metal (filmMetal), mixed in with weight `film` (0: none).
struct DielectricFresnel {
    vec3 f0;
    float f90;
    vec3 oneMinusF0;
    float film;
    vec3 filmDielectric;
    vec3 filmOneMinusDielectric;
    vec3 filmMetal;
};

// The core material's: IOR 1.5 (f0 = 0.04), f90 = 1.
CANDELA_FN DielectricFresnel coreDielectricFresnel() {
    DielectricFresnel d;
    d.f0 = vec3(0.04f);
    d.f90 = 1.0f;
    d.oneMinusF0 = vec3(0.96f);
    d.film = 0.0f;
    d.filmDielectric = vec3(0.0f);
    d.filmOneMinusDielectric = vec3(1.0f);
    d.filmMetal = vec3(0.0f);
    return d;
}

// KHR_materials_ior and KHR_materials_specular. `ior` 0 gives f0 = specularColor (clamped to 1):
// the specification's conversion of specular-glossiness materials.
CANDELA_FN DielectricFresnel dielectricFresnel(float ior, vec3 specularColor, float specular) {
    float r = (ior - 1.0f) / (ior + 1.0f);
    float r2 = r * r;
    // 1 − r² = 4 ior / (ior + 1)², and 1 − r²c = (1 − r²) + r²(1 − c): no difference of near-equal
    // numbers for c = 1, whatever the IOR.
    float oneMinusR2 = 4.0f * ior / ((ior + 1.0f) * (ior + 1.0f));
    vec3 oneMinusClamped = max(vec3(oneMinusR2) + r2 * (vec3(1.0f) - specularColor), vec3(0.0f));
    DielectricFresnel d;
    d.f0 = min(vec3(r2) * specularColor, vec3(1.0f)) * specular;
    d.f90 = specular;
    d.oneMinusF0 = vec3(1.0f - specular) + specular * oneMinusClamped;
    d.film = 0.0f;
    d.filmDielectric = vec3(0.0f);
    d.filmOneMinusDielectric = vec3(1.0f);
    d.filmMetal = vec3(0.0f);
    return d;
}

CANDELA_FN float minComponent(vec3 c) { return min(c.x, min(c.y, c.z)); }

// Schlick's weight (1 − V·H)⁵.
CANDELA_FN float schlickWeight(float VoH) {
    float x = 1.0f - clamp(VoH, 0.0f, 1.0f);
    float x2 = x * x;
    return x2 * x2 * x;
}

// 1 − (1 − V·H)⁵ as V·H (1 + x + x² + x³ + x⁴), x = 1 − V·H: no cancellation at small V·H (grazing
// transmission, where H_T meets N), where 1 − schlickWeight would keep no correct digit.
CANDELA_FN float schlickComplement(float VoH) {
    float c = clamp(VoH, 0.0f, 1.0f);
    float x = 1.0f - c;
    float x2 = x * x;
    return c * (1.0f + x + x2 + x2 * x + x2 * x2);
}

// The dielectric Fresnel at V·H (with the thin film's, when there is one).
CANDELA_FN vec3 fresnelDielectric(float VoH, DielectricFresnel d) {
    vec3 F = d.f0 + (vec3(d.f90) - d.f0) * schlickWeight(VoH);
    return d.film > 0.0f ? mix(F, d.filmDielectric, d.film) : F;
}

// The metal's Fresnel at V·H: Schlick with F0 = baseColor, F90 = 1 (with the thin film's).
CANDELA_FN vec3 fresnelMetal(float VoH, vec3 baseColor, DielectricFresnel d) {
    vec3 F = baseColor + (vec3(1.0f) - baseColor) * schlickWeight(VoH);
    return d.film > 0.0f ? mix(F, d.filmMetal, d.film) : F;
}

// 1 − F_d at V·H without cancellation (with the thin film's 1 − F_film mixed in).
CANDELA_FN vec3 oneMinusFresnelDielectricAt(float VoH, DielectricFresnel d) {
    // (1 − f0)(1 − w) + (1 − f90) w with 1 − w = schlickComplement: no cancellation at small V·H.
    float complement = schlickComplement(VoH);
    vec3 oneMinus = d.oneMinusF0 * complement + vec3((1.0f - d.f90) * (1.0f - complement));
    return d.film > 0.0f ? mix(oneMinus, d.filmOneMinusDielectric, d.film) : oneMinus;
}

// The Fresnel of the whole material: dielectric and metal (F0 = baseColor, F90 = 1) mixed by metallic.
CANDELA_FN vec3 fresnelDielectricMetal(float VoH, vec3 baseColor, float metallic, DielectricFresnel d) {
    return mix(fresnelDielectric(VoH, d), fresnelMetal(VoH, baseColor, d), metallic);
}

// The Appendix B material toward a light with angles `g` (g.NoL > 0), given its specular lobe
// D · Vis: the dielectric Fresnel `d` and the metal's mixed by metallic on the specular lobe, the
// diffuse weighted by the dielectric part's 1 − max(F_d).
CANDELA_FN BrdfLobes dielectricMaterialLobes(BrdfAngles g, float specularBrdf, vec3 baseColor, float metallic,
                                             DielectricFresnel d) {
    BrdfLobes lobes;
    lobes.specular = fresnelDielectricMetal(g.VoH, baseColor, metallic, d) * (specularBrdf * g.specularWeight) * g.NoL;
    // 1 − max(F_d), the specification's diffuse weight.
    float diffuseWeight = minComponent(oneMinusFresnelDielectricAt(g.VoH, d));
    lobes.diffuse = (1.0f - metallic) * diffuseWeight * baseColor * (1.0f / CANDELA_PI) * g.NoL;
    return lobes;
}

// brdfLobesTimesCosine (shared/brdf.h) with the dielectric Fresnel `d` and the Appendix B mix.
// `model` is CANDELA_SHADING_PBR or CANDELA_SHADING_PBR_SCHLICK_GGX.
CANDELA_FN BrdfLobes brdfLobesTimesCosineDielectric(vec3 N, vec3 V, vec3 L, vec3 baseColor, float metallic,
                                                    float perceptualRoughness, uint model, DielectricFresnel d) {
    BrdfLobes lobes;
    lobes.diffuse = vec3(0.0f);
    lobes.specular = vec3(0.0f);
    BrdfAngles g = brdfAngles(N, V, L);
    if (g.NoL <= 0.0f) return lobes;
    float roughness = clampRoughness(perceptualRoughness);
    float a = roughness * roughness;
    float D = distributionGgx(g.NoH, g.oneMinusNoH2, a);
    float Vis = model == CANDELA_SHADING_PBR_SCHLICK_GGX ? visibilitySchlickGgx(g.NoV, g.NoL, roughness)
                                                          : visibilitySmithGgxCorrelated(g.NoV, g.NoL, a);
    return dielectricMaterialLobes(g, D * Vis, baseColor, metallic, d);
}

// What the dielectric part of a material does not reflect of image-based light:
// 1 − max(E_d + multiscatter_d), E_d = f0·A + f90·B the split sum's directional albedo and, with
// `multiscatter`, multiscatter_d = E_d · F_avg (1 − A − B) / (1 − F_avg (1 − A − B)), F_avg = f0 + (f90 − f0)/21;
// computed from 1 − f0 without cancellation. The weight of the Lambert and transmitted parts.
CANDELA_FN float iblDielectricUnreflected(vec2 lut, DielectricFresnel d, bool multiscatter) {
    float lost = 1.0f - (lut.x + lut.y);
    // 1 − E_d = (1 − f0)A + (1 − f90)B + (1 − A − B); with a thin film, mixed with 1 − F_film (A + B).
    vec3 unreflected = d.oneMinusF0 * lut.x + vec3((1.0f - d.f90) * lut.y + lost);
    vec3 single = d.f0 * lut.x + d.f90 * lut.y;
    if (d.film > 0.0f) {
        unreflected = mix(unreflected, vec3(lost) + d.filmOneMinusDielectric * (lut.x + lut.y), d.film);
        single = mix(single, d.filmDielectric * (lut.x + lut.y), d.film);
    }
    if (multiscatter) {
        vec3 average = d.f0 + (vec3(d.f90) - d.f0) * (1.0f / 21.0f);
        unreflected -= single * average / (vec3(1.0f) - lost * average) * lost;
    }
    return max(minComponent(unreflected), 0.0f);
}

// iblShadeLobes (shared/ibl.h) with the dielectric Fresnel `d`: the split sum's directional albedo
// E = f0·A + f90·B per part (dielectric, metal), mixed by metallic (with a thin film: mixed with
// F_film · (A + B)); multiscatter as there, with
// F_avg = f0 + (f90 − f0)/21; the diffuse weighted by iblDielectricUnreflected and by
// `diffuseFraction` (1 − transmission: the rest is transmitted, iblTransmission).
CANDELA_FN BrdfLobes iblShadeLobesDielectric(vec3 prefiltered, vec3 irradiance, vec2 lut, vec3 baseColor, float metallic,
                                             DielectricFresnel d, bool multiscatter, float diffuseOcclusion,
                                             float specularOcclusionFactor, float diffuseFraction) {
    vec3 f0 = mix(d.f0, baseColor, metallic);
    vec3 f90 = mix(vec3(d.f90), vec3(1.0f), metallic);
    vec3 singleScatter = f0 * lut.x + f90 * lut.y;
    // A thin film's Fresnel (at N·V) taken outside the lobe's albedo A + B.
    if (d.film > 0.0f)
        singleScatter = mix(singleScatter, mix(d.filmDielectric, d.filmMetal, metallic) * (lut.x + lut.y), d.film);
    float lost = 1.0f - (lut.x + lut.y);
    vec3 multiScatter = vec3(0.0f);
    if (multiscatter) {
        vec3 averageFresnel = f0 + (f90 - f0) * (1.0f / 21.0f);
        multiScatter = singleScatter * averageFresnel / (vec3(1.0f) - lost * averageFresnel) * lost;
    }
    float diffuseWeight = iblDielectricUnreflected(lut, d, multiscatter);
    BrdfLobes lobes;
    lobes.specular = prefiltered * singleScatter * specularOcclusionFactor;
    lobes.diffuse = (multiScatter + baseColor * ((1.0f - metallic) * diffuseWeight * diffuseFraction)) * irradiance *
                    diffuseOcclusion;
    return lobes;
}

CANDELA_NAMESPACE_END

#endif
