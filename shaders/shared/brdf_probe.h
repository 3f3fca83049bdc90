// The BRDF probe's parameter grid, shared by brdf_probe.comp.glsl and tests/gpu/brdf_probe_test.cpp
// so that both enumerate the same combinations from the same float literals (no transcendental
// functions: the GPU and the CPU build bit-identical N, V, L).
//
// The probe image is CANDELA_BRDF_PROBE_WIDTH × CANDELA_BRDF_PROBE_HEIGHT texels, one combination each:
//   x = (iCosV · 10 + iCosL) · 3 + iAzimuth                          (300 columns)
//   y = ((iRoughness · 3 + iMetallic) · 3 + iBaseColor) · 3 + iModel  (216 rows)
// N = +Z; V = (sin θV, 0, cos θV); L = (sin θL cos φ, sin θL sin φ, cos θL).
// The grid contains, among others: N·V and N·L at −0.5, −1e-6, 0, 1e-6 (grazing and back-facing),
// N·H = 1 (V = L at φ = 0, and the mirror direction at φ = π), V = −L (cos θV = −cos θL at φ = π),
// roughness 0 and 1, metallic 0 and 1, a black base colour.
#ifndef CANDELA_SHARED_BRDF_PROBE_H
#define CANDELA_SHARED_BRDF_PROBE_H

#include "shared/compat.h"

CANDELA_NAMESPACE_BEGIN

#define CANDELA_BRDF_PROBE_GROUP_SIZE 8
#define CANDELA_BRDF_PROBE_COSINES 10u
#define CANDELA_BRDF_PROBE_AZIMUTHS 3u
#define CANDELA_BRDF_PROBE_ROUGHNESSES 8u
#define CANDELA_BRDF_PROBE_METALLICS 3u
#define CANDELA_BRDF_PROBE_BASE_COLORS 3u
#define CANDELA_BRDF_PROBE_MODELS 3u
#define CANDELA_BRDF_PROBE_WIDTH (CANDELA_BRDF_PROBE_COSINES * CANDELA_BRDF_PROBE_COSINES * CANDELA_BRDF_PROBE_AZIMUTHS)
#define CANDELA_BRDF_PROBE_HEIGHT \
    (CANDELA_BRDF_PROBE_ROUGHNESSES * CANDELA_BRDF_PROBE_METALLICS * CANDELA_BRDF_PROBE_BASE_COLORS * CANDELA_BRDF_PROBE_MODELS)

// Push constants of brdf_probe.comp (std430 layout).
struct BrdfProbeParams {
    float intensity;  // light intensity the BRDF·cosine is multiplied by (1 to compare, up to 1e6)
    // With kLayers only: the layers evaluated (CANDELA_LAYER_* bits) and their parameters: the
    // specular layer's (KHR_materials_ior, _specular), the coat's (KHR_materials_clearcoat) and the
    // sheen's (KHR_materials_sheen; its albedo E(N·V) given, as the forward pass reads it from a LUT)
    // and the anisotropy's (KHR_materials_anisotropy).
    float ior;
    float specular;
    uint layers;
    vec4 specularColor;  // rgb
    float clearcoat;
    float clearcoatRoughness;
    float sheenRoughness;
    float sheenAlbedo;
    vec4 clearcoatNormal;  // xyz: unit (the base normal is +Z)
    vec4 sheenColor;       // rgb
    vec4 anisotropy;       // xyz: the unit direction T in the tangent plane (z = 0), w: strength
    // x: the transmission weight (KHR_materials_transmission), y: 1 to mirror L through the surface
    // (L.z → −L.z), so that the grid's light directions probe the back side the BTDFs light from,
    // z: the diffuse transmission weight (KHR_materials_diffuse_transmission), w: its colour,
    // brdfProbeDiffuseTransmissionColor(uint(w)).
    vec4 transmission;
    // x: the thin film's weight (KHR_materials_iridescence), y: its IOR, z: its thickness (nm), w: the
    // IOR above it.
    vec4 iridescence;
};

// One combination of the grid: the inputs of brdfTimesCosine.
struct BrdfProbeSample {
    vec3 N;
    vec3 V;
    vec3 L;
    vec3 baseColor;
    float metallic;
    float perceptualRoughness;
    uint model;  // CANDELA_SHADING_*
};

// (cos θ, sin θ) of the i-th view/light elevation, i < CANDELA_BRDF_PROBE_COSINES; sin θ is
// √(1 − cos²θ) rounded to float. Grazing, back-facing and tiny cosines first, then small to 1.
CANDELA_FN vec2 brdfProbeCosine(uint i) {
    switch (i) {
        case 0u: return vec2(-0.5f, 0.8660254037844386f);
        case 1u: return vec2(-1e-6f, 1.0f);
        case 2u: return vec2(0.0f, 1.0f);
        case 3u: return vec2(1e-6f, 1.0f);
        case 4u: return vec2(1e-3f, 0.999999499999875f);
        case 5u: return vec2(0.05f, 0.998749217771909f);
        case 6u: return vec2(0.25f, 0.9682458365518543f);
        case 7u: return vec2(0.5f, 0.8660254037844386f);
        case 8u: return vec2(0.9f, 0.4358898943540673f);
        default: return vec2(1.0f, 0.0f);
    }
}

// (cos φ, sin φ) of the azimuth between V and L: 0, π/2, π.
CANDELA_FN vec2 brdfProbeAzimuth(uint i) {
    switch (i) {
        case 0u: return vec2(1.0f, 0.0f);
        case 1u: return vec2(0.0f, 1.0f);
        default: return vec2(-1.0f, 0.0f);
    }
}

// Perceptual roughness: 0 and 0.01 exercise the clamp to 0.045.
CANDELA_FN float brdfProbeRoughness(uint i) {
    switch (i) {
        case 0u: return 0.0f;
        case 1u: return 0.01f;
        case 2u: return 0.045f;
        case 3u: return 0.1f;
        case 4u: return 0.25f;
        case 5u: return 0.5f;
        case 6u: return 0.75f;
        default: return 1.0f;
    }
}

CANDELA_FN float brdfProbeMetallic(uint i) { return 0.5f * float(i); }

// White, black (zero diffuse; F0 = 0 when metallic), and copper.
CANDELA_FN vec3 brdfProbeBaseColor(uint i) {
    switch (i) {
        case 0u: return vec3(1.0f);
        case 1u: return vec3(0.0f);
        default: return vec3(0.955f, 0.638f, 0.538f);
    }
}

// The diffuse transmission colours the probe chooses from (BrdfProbeParams::transmission.w): white,
// a red-orange one unlike any base colour of the grid, and black.
CANDELA_FN vec3 brdfProbeDiffuseTransmissionColor(uint i) {
    switch (i) {
        case 0u: return vec3(1.0f);
        case 1u: return vec3(1.0f, 0.35f, 0.05f);
        default: return vec3(0.0f);
    }
}

// The combination of texel (x, y). Precondition: x < CANDELA_BRDF_PROBE_WIDTH, y < CANDELA_BRDF_PROBE_HEIGHT.
CANDELA_FN BrdfProbeSample brdfProbeSample(uvec2 texel) {
    uint x = texel.x;
    uint y = texel.y;
    vec2 azimuth = brdfProbeAzimuth(x % CANDELA_BRDF_PROBE_AZIMUTHS);
    x /= CANDELA_BRDF_PROBE_AZIMUTHS;
    vec2 light = brdfProbeCosine(x % CANDELA_BRDF_PROBE_COSINES);
    vec2 view = brdfProbeCosine(x / CANDELA_BRDF_PROBE_COSINES);
    BrdfProbeSample s;
    s.model = y % CANDELA_BRDF_PROBE_MODELS;
    y /= CANDELA_BRDF_PROBE_MODELS;
    s.baseColor = brdfProbeBaseColor(y % CANDELA_BRDF_PROBE_BASE_COLORS);
    y /= CANDELA_BRDF_PROBE_BASE_COLORS;
    s.metallic = brdfProbeMetallic(y % CANDELA_BRDF_PROBE_METALLICS);
    s.perceptualRoughness = brdfProbeRoughness(y / CANDELA_BRDF_PROBE_METALLICS);
    s.N = vec3(0.0f, 0.0f, 1.0f);
    s.V = vec3(view.y, 0.0f, view.x);
    s.L = vec3(light.y * azimuth.x, light.y * azimuth.y, light.x);
    return s;
}

CANDELA_NAMESPACE_END

#ifdef __cplusplus
static_assert(sizeof(candela::shading::BrdfProbeParams) == 128);
#endif

#endif
