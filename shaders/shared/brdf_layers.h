// The material layers beyond glTF's core metallic-roughness model (KHR_materials_*), shared by
// GLSL (the forward pass's layered program) and C++ (float). Each builds on shared/brdf.h; a
// double-precision reference of the same formulas lives in tests/ and is compared with the GPU's
// evaluation of this file (docs/materials.md).
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
// Clearcoat layer (KHR_materials_clearcoat): a GGX lobe on its own normal N_c and roughness, over
// the material, per the extension's specification:
//   coated = mix(material, D(α_c) · Vis(α_c), clearcoat · F_c),  F_c = 0.04 + 0.96 (1 − N_c·V)⁵,
// the Fresnel being the mix weight (taken at N_c·V, not V·H, so that the layering conserves
// energy); the emission lies under the coat and is darkened by the same 1 − clearcoat · F_c.
//
// Sheen layer (KHR_materials_sheen): the Charlie distribution with the Estevez-Kulla visibility
// (Conty Estevez & Kulla 2017, as the extension's specification gives them), over the material
// scaled by 1 − max(sheenColor) · E(N·V), E the sheen lobe's directional albedo (a LUT):
//   sheened = sheenColor · D_c · Vis_c + material · (1 − max(sheenColor) · E(N·V)),
// and the coat, when there is one, over both.
//
// Anisotropy (KHR_materials_anisotropy): the material's GGX lobe becomes anisotropic about the
// direction T (in the tangent plane) with α_t = mix(α, 1, anisotropy²) along T and α_b = α across,
// D = 1 / (π α_t α_b ((T·H/α_t)² + (B·H/α_b)² + (N·H)²)²) and the height-correlated anisotropic
// Smith visibility (Heitz 2014), as the extension's specification gives them.
//
// Transmission (KHR_materials_transmission): the dielectric part's diffuse lobe is replaced, for the
// fraction `transmission`, by a microfacet BTDF tinted by the base colour:
//   dielectric base = mix(diffuse_brdf, specular_btdf(α_t) · baseColor, transmission),
// specular_btdf = D_T · V_T at the transmission half vector H_T = normalize(V + L − 2(N·L)N) (the
// light mirrored through the thin surface), with the separable Smith visibility the specification's
// implementation notes give, and α_t the roughness scaled by the IOR as in the Khronos sample viewer
// (roughness · clamp(2·ior − 2, 0, 1): an index-matched surface does not blur). The base layer's
// weight 1 − max(F_d) is taken at V·H_T. Light reaches it from behind the surface only (N·L < 0).
// KHR_materials_volume adds refraction through a thickness and Beer-Lambert absorption along it
// (the forward pass's geometry: volumeTransmittance).
//
// Iridescence (KHR_materials_iridescence): a thin film over the material changes its Fresnel term,
//   F = mix(F_schlick, F_film, iridescence)  for the dielectric part (F_film over f0) and the metal
//   (F_film over baseColor),
// F_film the specification's approximation of Belcour & Barla 2017 (two interfaces with Schlick
// Fresnel, the first-order phase shift, the analytic spectral integration in XYZ). Evaluated once
// per shading point at N·V, as the Khronos sample viewer does (the same value for every light).
#ifndef CANDELA_SHARED_BRDF_LAYERS_H
#define CANDELA_SHARED_BRDF_LAYERS_H

#include "shared/brdf.h"
#include "shared/ibl.h"
#include "shared/scene_data.h"

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

// ---- Iridescence (the thin film) ----

// The XYZ colour matching functions' Fourier transform at optical path difference `opd` (nm) with
// phase shift `shift`, as Rec. 709 RGB (the specification's Gaussian fit).
CANDELA_FN vec3 filmSensitivity(float opd, vec3 shift) {
    float phase = 2.0f * CANDELA_PI * opd * 1.0e-9f;
    vec3 val = vec3(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
    vec3 pos = vec3(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
    vec3 var = vec3(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    vec3 xyz = val * sqrt(2.0f * CANDELA_PI * var) * cos(pos * phase + shift) * exp(-(phase * phase) * var);
    xyz.x += 9.7470e-14f * sqrt(2.0f * CANDELA_PI * 4.5282e+09f) * cos(2.2399e+06f * phase + shift.x) *
             exp(-4.5282e+09f * (phase * phase));
    xyz = xyz * (1.0f / 1.0685e-7f);
    return vec3(3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
                -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
                0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z);
}

// The Fresnel reflectance of a thin film and 1 minus it, each computed without cancellation (at
// grazing views the reflectance nears 1 and 1 − it would keep no digit).
struct ThinFilm {
    vec3 reflectance;
    vec3 oneMinusReflectance;
};

CANDELA_FN ThinFilm thinFilm(vec3 reflectance, vec3 oneMinusReflectance) {
    ThinFilm f;
    f.reflectance = reflectance;
    f.oneMinusReflectance = oneMinusReflectance;
    return f;
}

// The thin film of IOR `filmIor` and `thickness` nm between a medium of IOR `outsideIor` and a base
// of normal reflectance `baseF0`, at cos θ₁ = `cosTheta1` — the specification's implementation notes,
// with the base's IOR from min(baseF0, 0.9999) (their "+ 0.0001" guard would turn an F0 of 1 into a
// negative IOR). Thickness 0 (no film): Schlick's Fresnel of the base.
CANDELA_FN ThinFilm thinFilmFresnel(float outsideIor, float filmIor, float cosTheta1, float thickness, vec3 baseF0) {
    if (thickness <= 0.0f)
        return thinFilm(fresnelSchlick(cosTheta1, baseF0), (vec3(1.0f) - baseF0) * schlickComplement(cosTheta1));
    float ratio = outsideIor / filmIor;
    // Snell: cos²θ₂ = 1 − ratio² sin²θ₁, as (1 − ratio)(1 + ratio) + ratio² cos²θ₁ — at grazing views
    // 1 − cos²θ₁ would round to 1 and lose θ₂.
    float cosTheta2Squared = (1.0f - ratio) * (1.0f + ratio) + ratio * ratio * (cosTheta1 * cosTheta1);
    if (cosTheta2Squared < 0.0f) return thinFilm(vec3(1.0f), vec3(0.0f));  // total internal reflection
    float cosTheta2 = sqrt(cosTheta2Squared);
    // First interface (outside → film).
    float q0 = (filmIor - outsideIor) / (filmIor + outsideIor);
    float r12 = q0 * q0 + (1.0f - q0 * q0) * schlickWeight(cosTheta1);
    // 1 − R12 = (1 − R0)(1 − x⁵): no cancellation at grazing views, where R12 → 1.
    float t121 = (1.0f - q0 * q0) * schlickComplement(cosTheta1);
    float phi12 = filmIor < outsideIor ? CANDELA_PI : 0.0f;
    float phi21 = CANDELA_PI - phi12;
    // Second interface (film → base).
    vec3 s = sqrt(min(baseF0, vec3(0.9999f)));
    vec3 baseIor = (vec3(1.0f) + s) / (vec3(1.0f) - s);
    vec3 q1 = (baseIor - vec3(filmIor)) / (baseIor + vec3(filmIor));
    vec3 r23 = fresnelSchlick(cosTheta2, q1 * q1);
    vec3 t23 = (vec3(1.0f) - q1 * q1) * schlickComplement(cosTheta2);
    vec3 phi23 = vec3(baseIor.x < filmIor ? CANDELA_PI : 0.0f, baseIor.y < filmIor ? CANDELA_PI : 0.0f,
                      baseIor.z < filmIor ? CANDELA_PI : 0.0f);
    float opd = 2.0f * filmIor * thickness * cosTheta2;
    vec3 phi = vec3(phi21) + phi23;
    // Compound terms and the analytic spectral integration (orders 0, 1, 2).
    // R123 = R12 R23 clamped to [1e-5, 0.9999], and 1 − R123 = T121 + R12 T23 clamped to match:
    // 1 − R123 near the upper clamp keeps its digits.
    vec3 r123 = clamp(r12 * r23, vec3(1e-5f), vec3(0.9999f));
    vec3 oneMinusR123 = clamp(vec3(t121) + r12 * t23, vec3(1e-4f), vec3(1.0f - 1e-5f));
    vec3 rootR123 = sqrt(r123);
    vec3 rs = (t121 * t121) * r23 / oneMinusR123;
    // I = R12 + Rs + Σ C_m S_m, and 1 − I = T121 − Rs − Σ C_m S_m from the cancellation-free T121.
    vec3 cm = rs - vec3(t121);
    vec3 oscillation = vec3(0.0f);
    for (int m = 1; m <= 2; ++m) {
        cm *= rootR123;
        oscillation += cm * (2.0f * filmSensitivity(float(m) * opd, float(m) * phi));
    }
    vec3 intensity = vec3(r12) + rs + oscillation;
    vec3 oneMinus = vec3(t121) - rs - oscillation;
    return thinFilm(max(intensity, vec3(0.0f)), min(oneMinus, vec3(1.0f)));
}

// `d` with a thin film of weight `iridescence` (0 … 1), IOR `filmIor`, `thickness` nm, seen at N·V
// = `NoV` from a medium of IOR `outsideIor` (1, or the coat's 1.5 under a clearcoat), over the
// dielectric's f0 and the metal's `baseColor`. Thickness 0 is no film.
CANDELA_FN DielectricFresnel withThinFilm(DielectricFresnel d, float iridescence, float filmIor, float thickness,
                                          float outsideIor, float NoV, vec3 baseColor) {
    DielectricFresnel filmed = d;
    filmed.film = thickness > 0.0f ? iridescence : 0.0f;
    ThinFilm dielectric = thinFilmFresnel(outsideIor, filmIor, NoV, thickness, d.f0);
    filmed.filmDielectric = dielectric.reflectance;
    filmed.filmOneMinusDielectric = dielectric.oneMinusReflectance;
    filmed.filmMetal = thinFilmFresnel(outsideIor, filmIor, NoV, thickness, baseColor).reflectance;
    return filmed;
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

// ---- Transmission ----

// The transmission of one shading point: its weight (transmissionFactor × texture) and the
// perceptual roughness of its BTDF (the material's, scaled by clamp(2·ior − 2, 0, 1)).
struct Transmission {
    float weight;
    float roughness;
};

CANDELA_FN Transmission transmissionLayer(float transmission, float perceptualRoughness, float ior) {
    Transmission t;
    t.weight = transmission;
    t.roughness = perceptualRoughness * clamp(2.0f * ior - 2.0f, 0.0f, 1.0f);
    return t;
}

// The light transmitted from L behind the surface (N·L < 0; 0 otherwise) toward V, times |N·L|:
// transmission · (1 − metallic) · baseColor · (1 − max(F_d(V·H_T))) · D_T · V_T · |N·L|.
CANDELA_FN vec3 transmissionTimesCosine(vec3 N, vec3 V, vec3 L, vec3 baseColor, float metallic, DielectricFresnel d,
                                        Transmission t) {
    float NoL = dot(N, L);
    if (NoL >= 0.0f || t.weight <= 0.0f) return vec3(0.0f);
    vec3 H = V + (L - 2.0f * NoL * N);  // V plus L mirrored through the surface
    float lengthH = length(H);
    if (lengthH <= 1e-6f) return vec3(0.0f);
    H = H / lengthH;
    float NoH = dot(N, H);
    float VoH = dot(V, H);
    // The specification's χ⁺ terms: N·H_T > 0, H_T·L / N·L > 0 and H_T·V / N·V > 0.
    if (NoH <= 0.0f || dot(H, L) >= 0.0f || VoH <= 0.0f) return vec3(0.0f);
    float roughness = clampRoughness(t.roughness);
    float a = roughness * roughness;
    vec3 NxH = cross(N, H);
    float D = distributionGgx(NoH, dot(NxH, NxH), a);
    float NoV = max(dot(N, V), CANDELA_MIN_NOV);
    float absNoL = -NoL;
    float a2 = a * a;
    // V_T · |N·L|: the |N·L| over |N·L| + √(α² + (1 − α²) N·L²) stays finite as N·L → 0.
    float visTimesCosine = absNoL / ((absNoL + sqrt(a2 + (1.0f - a2) * absNoL * absNoL)) *
                                     (NoV + sqrt(a2 + (1.0f - a2) * NoV * NoV)));
    float unreflected = minComponent(oneMinusFresnelDielectricAt(VoH, d));
    return baseColor * (t.weight * (1.0f - metallic) * unreflected * D * visTimesCosine);
}

// The transmission under image-based light: `behind` (the light from behind the surface, already
// blurred by the roughness and attenuated by the volume) through the dielectric part's
// transmitted fraction — the same weight the Lambert part has in iblShadeLobesDielectric, so a
// transmitting material in a uniform environment keeps the white furnace.
CANDELA_FN vec3 iblTransmission(Transmission t, vec3 behind, vec2 lut, vec3 baseColor, float metallic, DielectricFresnel d,
                                bool multiscatter) {
    return behind * baseColor * (t.weight * (1.0f - metallic) * iblDielectricUnreflected(lut, d, multiscatter));
}

// The split sum's (A, B) at (N·V, perceptual roughness) without a LUT: Karis's analytic fit
// ("Physically Based Shading on Mobile", 2014), within a few percent of the LUT. Weighs the
// transmitted light of frames without an environment (and so without the BRDF LUT).
CANDELA_FN vec2 envBrdfApproximation(float NoV, float perceptualRoughness) {
    vec4 r = perceptualRoughness * vec4(-1.0f, -0.0275f, -0.572f, 0.022f) + vec4(1.0f, 0.0425f, 1.04f, -0.04f);
    float a004 = min(r.x * r.x, exp2(-9.28f * NoV)) * r.x + r.y;
    return clamp(vec2(-1.04f, 1.04f) * a004 + vec2(r.z, r.w), vec2(0.0f), vec2(1.0f));
}

// Beer-Lambert transmittance along `distance` through a volume whose light keeps
// `attenuationColor` after `attenuationDistance` (0: infinite, no absorption): colour^(distance /
// attenuationDistance), as exp(−σ · distance) with σ = −ln(max(colour, 1e-30)) / attenuationDistance,
// so a black colour, a distance of 0 or 1e-6 and a thickness of 1e6 all stay finite.
CANDELA_FN vec3 volumeTransmittance(vec3 attenuationColor, float attenuationDistance, float distance) {
    if (attenuationDistance <= 0.0f || distance <= 0.0f) return vec3(1.0f);
    vec3 sigma = -log(max(attenuationColor, vec3(1e-30f))) / attenuationDistance;
    return exp(-sigma * distance);
}

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

// The sheen under image-based light: sheenColor · min(E(N·V), 1) · the Charlie-prefiltered
// environment, darkened by the occlusion. With a white sheen in a uniform environment it reflects
// exactly what the material beneath loses (white furnace).
CANDELA_FN vec3 iblSheen(Sheen s, vec3 prefiltered, float occlusion) {
    return s.color * (s.albedo * occlusion) * prefiltered;
}

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

// The image-based approximation (the extension's implementation notes, as the Khronos sample
// viewer does): the prefiltered environment is read about a normal bent toward the plane across
// the brushing, the more so the stronger and smoother the anisotropy.
CANDELA_FN vec3 anisotropicBentNormal(vec3 N, vec3 V, float perceptualRoughness, Anisotropy an) {
    vec3 tangentAcross = cross(an.b, V);
    vec3 anisotropicNormal = cross(tangentAcross, an.b);
    float bend = 1.0f - an.strength * (1.0f - perceptualRoughness);
    float bend2 = bend * bend;
    vec3 bent = mix(anisotropicNormal, N, bend2 * bend2);
    float lengthBent = length(bent);
    return lengthBent > 1e-6f ? bent / lengthBent : N;
}

// ---- All layers ----

// f(V, L) · (N·L) of a layered material: the material's lobes (the core's, or with the dielectric
// Fresnel `d` when `layers` has CANDELA_LAYER_SPECULAR or CANDELA_LAYER_IRIDESCENCE — the thin film in d; with an anisotropic GGX
// lobe `an` when it has CANDELA_LAYER_ANISOTROPY), beneath the sheen
// `sheen` when `layers` has CANDELA_LAYER_SHEEN, and both beneath the coat `coat` when `layers` has
// CANDELA_LAYER_CLEARCOAT; with CANDELA_LAYER_TRANSMISSION the fraction `tr` of the diffuse lobe
// becomes the transmission lobe toward `Lt` (L, or the direction to the light from where a volume's
// refracted ray leaves it; d is then the dielectric Fresnel of its weight: the core's without the
// specular layer). The forward pass passes its kLayers, a specialization constant, so the
// branches not taken are compiled out.
struct LayeredLobes {
    vec3 diffuse;    // the material's, beneath the sheen and the coat
    vec3 specular;   // the material's, beneath the sheen and the coat
    vec3 transmission;  // the material's transmitted light (from L behind), beneath the sheen and the coat
    vec3 sheen;      // the sheen's, beneath the coat
    float clearcoat; // the coat's (colourless)
};

CANDELA_FN LayeredLobes layeredLobesTimesCosine(vec3 N, vec3 V, vec3 L, vec3 Lt, vec3 baseColor, float metallic,
                                                float perceptualRoughness, uint model, uint layers, DielectricFresnel d,
                                                Anisotropy an, Transmission tr, Sheen sheen, Clearcoat coat) {
    BrdfLobes base;
    // The specular layer and a thin film change the Fresnel: the Appendix B mix with `d`.
    bool dielectric = (layers & (CANDELA_LAYER_SPECULAR | CANDELA_LAYER_IRIDESCENCE)) != 0u;
    if ((layers & CANDELA_LAYER_ANISOTROPY) != 0u)
        base = brdfLobesTimesCosineAnisotropic(N, V, L, baseColor, metallic, perceptualRoughness, dielectric, d, an);
    else if (dielectric)
        base = brdfLobesTimesCosineDielectric(N, V, L, baseColor, metallic, perceptualRoughness, model, d);
    else
        base = brdfLobesTimesCosine(N, V, L, baseColor, metallic, perceptualRoughness, model);
    LayeredLobes layered;
    layered.diffuse = base.diffuse;
    layered.specular = base.specular;
    layered.transmission = vec3(0.0f);
    layered.sheen = vec3(0.0f);
    layered.clearcoat = 0.0f;
    if ((layers & CANDELA_LAYER_TRANSMISSION) != 0u) {
        layered.diffuse *= 1.0f - tr.weight;
        layered.transmission = transmissionTimesCosine(N, V, Lt, baseColor, metallic, d, tr);
    }
    if ((layers & CANDELA_LAYER_SHEEN) != 0u) {
        layered.diffuse *= sheen.baseWeight;
        layered.specular *= sheen.baseWeight;
        layered.transmission *= sheen.baseWeight;
        layered.sheen = sheen.color * sheenTimesCosine(N, V, L, sheen.roughness);
    }
    if ((layers & CANDELA_LAYER_CLEARCOAT) != 0u) {
        layered.diffuse *= coat.baseWeight;
        layered.specular *= coat.baseWeight;
        layered.transmission *= coat.baseWeight;
        layered.sheen *= coat.baseWeight;
        layered.clearcoat = clearcoatTimesCosine(coat, V, L, model);
    }
    return layered;
}

CANDELA_NAMESPACE_END

#endif
