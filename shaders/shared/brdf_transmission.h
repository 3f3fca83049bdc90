// KHR_materials_transmission, KHR_materials_volume and KHR_materials_dispersion: the BTDF of a thin
// surface, its image-based counterpart, Beer-Lambert absorption along a volume's ray and the
// per-channel IORs of a dispersive volume. One of the material layers
// (shared/brdf_layers.h), shared by GLSL and C++ (float); a double-precision reference of the same
// formulas lives in tests/unit/brdf_reference.h.
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
// (the forward pass's geometry: volumeTransmittance), and KHR_materials_dispersion a refracted ray
// per colour channel (dispersionIors).
#ifndef CANDELA_SHARED_BRDF_TRANSMISSION_H
#define CANDELA_SHARED_BRDF_TRANSMISSION_H

#include "shared/brdf_specular.h"

CANDELA_NAMESPACE_BEGIN

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

// The directional albedo of the transmission lobe — the specification's BTDF, single scattering:
// ∫ (1 − max(F_d)) D_T V_T |N·L| dL = (1 − f0)·A_t + (1 − f90)·B_t (the minimum over channels; with
// a thin film mixed with (1 − F_film)(A_t + B_t)), (A_t, B_t) the split sum at (N·V, the
// transmission roughness): the BTDF mirrored through the thin surface is the reflection lobe, whose
// albedo the LUT holds (with the height-correlated visibility where V_T is separable, so this is
// above the BTDF's own albedo: by up to 14% at transmission roughness 0.5, 47% at 0.75, 123% at 1,
// the most toward grazing views). A rough BTDF loses much: at transmission roughness 1 its albedo
// is 0.2-0.3.
CANDELA_FN float iblTransmissionAlbedo(vec2 transmissionLut, DielectricFresnel d) {
    vec3 albedo = d.oneMinusF0 * transmissionLut.x + vec3((1.0f - d.f90) * transmissionLut.y);
    if (d.film > 0.0f) albedo = mix(albedo, d.filmOneMinusDielectric * (transmissionLut.x + transmissionLut.y), d.film);
    return max(minComponent(albedo), 0.0f);
}

// The transmission under image-based light: `behind` (the light from behind the surface, already
// blurred by the roughness and attenuated by the volume) through the transmission lobe's albedo
// (iblTransmissionAlbedo at `transmissionLut`, the split sum at the transmission roughness), at most
// the weight the Lambert part has in iblShadeLobesDielectric (`lut`, at the material's roughness):
// so a transmitting material never reflects and transmits more than 1 of a uniform environment,
// and keeps the white furnace where the BTDF is smooth; a rough one loses what its single-scattering
// BTDF loses (docs/materials.md).
CANDELA_FN vec3 iblTransmission(Transmission t, vec3 behind, vec2 lut, vec2 transmissionLut, vec3 baseColor,
                                float metallic, DielectricFresnel d, bool multiscatter) {
    float weight = min(iblTransmissionAlbedo(transmissionLut, d), iblDielectricUnreflected(lut, d, multiscatter));
    return behind * baseColor * (t.weight * (1.0f - metallic) * weight);
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

// The direction of the volume's ray: V refracted into the surface of normal `n` (unit, on V's side)
// with IOR `ior` (below 1 taken as 1: Snell's eta = 1/ior ≤ 1 never reflects totally), normalized.
CANDELA_FN vec3 refractedDirection(vec3 v, vec3 n, float ior) { return normalize(refract(-v, n, 1.0f / max(ior, 1.0f))); }

// ---- Dispersion ----

// KHR_materials_dispersion: the IORs of the red, green and blue rays through a volume,
// (ior − s, ior, ior + s) with the specification's half spread s = (ior − 1) · 0.025 · dispersion
// (dispersion = 20 / the Abbe number V_d, and n_F − n_C = (n_d − 1)/V_d: half of it on either side
// of the green's n_d); an IOR below 1 is taken as 1, as the volume's refraction takes it, and the red
// is clamped to at least 1 (large dispersions). Dispersion 0 gives the IOR three times, exactly.
CANDELA_FN vec3 dispersionIors(float ior, float dispersion) {
    float green = max(ior, 1.0f);
    float halfSpread = (green - 1.0f) * 0.025f * max(dispersion, 0.0f);
    return vec3(max(green - halfSpread, 1.0f), green, green + halfSpread);
}

// The angle in radians between unit directions `a` and `b`, as 2 asin(|a − b| / 2): exact for the
// small angles between the refracted rays of neighbouring wavelengths, where acos(a·b) loses them.
CANDELA_FN float angleBetween(vec3 a, vec3 b) { return 2.0f * asin(min(0.5f * length(a - b), 1.0f)); }

CANDELA_NAMESPACE_END

#endif
