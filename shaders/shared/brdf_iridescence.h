// KHR_materials_iridescence: the thin film's Fresnel, carried in the dielectric Fresnel of
// shared/brdf_specular.h. One of the material layers (shared/brdf_layers.h), shared by GLSL and C++
// (float); a double-precision reference of the same formulas lives in tests/unit/brdf_reference.h.
//
// Iridescence (KHR_materials_iridescence): a thin film over the material changes its Fresnel term,
//   F = mix(F_schlick, F_film, iridescence)  for the dielectric part (F_film over f0) and the metal
//   (F_film over baseColor),
// F_film the specification's approximation of Belcour & Barla 2017 (two interfaces with Schlick
// Fresnel, the first-order phase shift, the analytic spectral integration in XYZ). Evaluated once
// per shading point at N·V, as the Khronos sample viewer does (the same value for every light).
#ifndef CANDELA_SHARED_BRDF_IRIDESCENCE_H
#define CANDELA_SHARED_BRDF_IRIDESCENCE_H

#include "shared/brdf_specular.h"

CANDELA_NAMESPACE_BEGIN

// ---- Iridescence (the thin film) ----

// cos of arguments of tens of radians: Vulkan bounds cos's error only on [−π, π] (2⁻¹¹ absolute),
// and beyond it an implementation's own range reduction may lose digits (SwiftShader's was off by
// 6e-3 relative in the film's colour), so the argument is brought into [−π, π] first; the
// reduction's rounding is an ulp of the argument (4e-6 at 32 rad).
CANDELA_FN float cosOfPhase(float x) { return cos(x - (2.0f * CANDELA_PI) * floor(x * (0.5f / CANDELA_PI) + 0.5f)); }
CANDELA_FN vec3 cosOfPhase(vec3 x) { return cos(x - (2.0f * CANDELA_PI) * floor(x * (0.5f / CANDELA_PI) + 0.5f)); }

// The XYZ colour matching functions' Fourier transform at optical path difference `opd` (nm) with
// phase shift `shift`, as Rec. 709 RGB (the specification's Gaussian fit).
CANDELA_FN vec3 filmSensitivity(float opd, vec3 shift) {
    float phase = 2.0f * CANDELA_PI * opd * 1.0e-9f;
    vec3 val = vec3(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
    vec3 pos = vec3(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
    vec3 var = vec3(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    vec3 xyz = val * sqrt(2.0f * CANDELA_PI * var) * cosOfPhase(pos * phase + shift) * exp(-(phase * phase) * var);
    xyz.x += 9.7470e-14f * sqrt(2.0f * CANDELA_PI * 4.5282e+09f) * cosOfPhase(2.2399e+06f * phase + shift.x) *
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

CANDELA_NAMESPACE_END

#endif
