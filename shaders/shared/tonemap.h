// Tone mapping operators and the sRGB transfer function, shared by tonemap.frag.glsl and the CPU
// reference in the tests. Input: linear scene-referred RGB (after exposure). Output: linear
// display-referred RGB in [0,1], to be sRGB-encoded.
#ifndef CANDELA_SHARED_TONEMAP_H
#define CANDELA_SHARED_TONEMAP_H

#include "shared/compat.h"
#include "shared/sky_rays.h"

CANDELA_NAMESPACE_BEGIN

#define CANDELA_TONEMAP_PBR_NEUTRAL 0u
#define CANDELA_TONEMAP_ACES 1u
#define CANDELA_TONEMAP_AGX 2u
#define CANDELA_TONEMAP_REINHARD 3u
#define CANDELA_TONEMAP_LINEAR 4u

// Push constants of tonemap.frag (std430). The operator, sRGB encoding, dithering and whether a
// background is composited are specialization constants of the pipeline.
struct TonemapParams {
    /*Color*/ vec4 background;      // rgb: linear display colour of a solid background (when composited)
    /*Range(-10, 10)*/ float exposureEv;  // exposure in stops: radiance × 2^EV
    /*Ignore*/ float exposureScale;       // 2^exposureEv, set by the pass (an exp2 per pixel less)
    /*Ignore*/ float pad1, pad2;
};

// The sky tonemap_sky.frag composites under the image (shared/sky.glsl), after TonemapParams in its
// push constants (96 bytes together).
struct TonemapSky {
    SkyRays rays;                   // the environment rotation included
    /*Ignore*/ vec4 intensityLod;   // x: the environment's intensity; y: the mip shown; zw unused
};

// Khronos PBR Neutral (https://github.com/KhronosGroup/ToneMapping, reference implementation).
CANDELA_FN vec3 tonemapPbrNeutral(vec3 color) {
    float startCompression = 0.8f - 0.04f;
    float desaturation = 0.15f;
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    color -= vec3(offset);
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression) return color;
    float d = 1.0f - startCompression;
    float newPeak = 1.0f - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    return mix(color, vec3(newPeak), g);
}

// ACES: Stephen Hill's fit of the RRT + sRGB ODT (BakingLab ACES.hlsl), with its sRGB → AP1-ish
// input and output matrices. Rows as written; applied as v * M (= M_rows · v).
CANDELA_FN vec3 tonemapAces(vec3 color) {
    mat3 inputRows = mat3(vec3(0.59719f, 0.35458f, 0.04823f), vec3(0.07600f, 0.90834f, 0.01566f),
                          vec3(0.02840f, 0.13383f, 0.83777f));
    mat3 outputRows = mat3(vec3(1.60475f, -0.53108f, -0.07367f), vec3(-0.10208f, 1.10813f, -0.00605f),
                           vec3(-0.00327f, -0.07276f, 1.07602f));
    vec3 v = color * inputRows;
    vec3 a = v * (v + vec3(0.0245786f)) - vec3(0.000090537f);
    vec3 b = v * (0.983729f * v + vec3(0.4329510f)) + vec3(0.238081f);
    return clamp((a / b) * outputRows, vec3(0.0f), vec3(1.0f));
}

// AgX with the default look: Benjamin Wrensch's minimal fit of Troy Sobotka's AgX (6th-order
// polynomial contrast curve), returning linear display RGB.
CANDELA_FN vec3 agxContrast(vec3 x) {
    vec3 x2 = x * x;
    vec3 x4 = x2 * x2;
    return 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x -
           vec3(0.00232f);
}

CANDELA_FN vec3 tonemapAgx(vec3 color) {
    mat3 agxMat = mat3(vec3(0.842479062253094f, 0.0423282422610123f, 0.0423756549057051f),
                       vec3(0.0784335999999992f, 0.878468636469772f, 0.0784336f),
                       vec3(0.0792237451477643f, 0.0791661274605434f, 0.879142973793104f));
    mat3 agxMatInv = mat3(vec3(1.19687900512017f, -0.0528968517574562f, -0.0529716355144438f),
                          vec3(-0.0980208811401368f, 1.15190312990417f, -0.0980434501171241f),
                          vec3(-0.0990297440797205f, -0.0989611768448433f, 1.15107367264116f));
    float minEv = -12.47393f;
    float maxEv = 4.026069f;
    vec3 v = agxMat * max(color, vec3(1e-10f));
    v = clamp(log2(v), vec3(minEv), vec3(maxEv));
    v = (v - vec3(minEv)) / (maxEv - minEv);
    v = agxContrast(v);
    v = agxMatInv * v;
    return pow(clamp(v, vec3(0.0f), vec3(1.0f)), vec3(2.2f));
}

// Per-channel Reinhard x / (1 + x).
CANDELA_FN vec3 tonemapReinhard(vec3 color) { return color / (vec3(1.0f) + color); }

CANDELA_FN vec3 applyTonemap(vec3 color, uint op) {
    color = max(color, vec3(0.0f));
    if (op == CANDELA_TONEMAP_PBR_NEUTRAL) return clamp(tonemapPbrNeutral(color), vec3(0.0f), vec3(1.0f));
    if (op == CANDELA_TONEMAP_ACES) return tonemapAces(color);
    if (op == CANDELA_TONEMAP_AGX) return tonemapAgx(color);
    if (op == CANDELA_TONEMAP_REINHARD) return tonemapReinhard(color);
    return clamp(color, vec3(0.0f), vec3(1.0f));
}

// The sRGB OETF (IEC 61966-2-1), per channel, for values in [0,1]. Its curved part,
// 1.055 x^(1/2.4) − 0.055 on [0.0031308, 1], is a degree-6 polynomial in q = x^(1/4) (two square
// roots), fitted (minimax) to within 1.7e-6 in float arithmetic, 4e-4 of an 8-bit level
// (SrgbEncode.WithinAFewMillionthsOfTheTransferFunction): on llvmpipe a pow is a log2 and an exp2
// polynomial per channel, a quarter of the sky's draw in the tonemap pass (shading.md).
CANDELA_FN vec3 srgbEncode(vec3 linear) {
    vec3 lo = linear * 12.92f;
    vec3 q = sqrt(sqrt(max(linear, vec3(0.0f))));
    vec3 hi = vec3(0.0682079345f);
    hi = hi * q + vec3(-0.31841585f);
    hi = hi * q + vec3(0.657188058f);
    hi = hi * q + vec3(-0.852957308f);
    hi = hi * q + vec3(1.36592102f);
    hi = hi * q + vec3(0.139604151f);
    hi = hi * q + vec3(-0.0595466085f);
    return mix(hi, lo, vec3(lessThanEqual(linear, vec3(0.0031308f))));
}

CANDELA_FN vec3 srgbDecode(vec3 encoded) {
    vec3 lo = encoded / 12.92f;
    vec3 hi = pow((encoded + vec3(0.055f)) / 1.055f, vec3(2.4f));
    return mix(hi, lo, vec3(lessThanEqual(encoded, vec3(0.04045f))));
}

CANDELA_NAMESPACE_END

#ifdef __cplusplus
static_assert(sizeof(candela::shading::TonemapParams) == 32);
static_assert(sizeof(candela::shading::TonemapParams) + sizeof(candela::shading::TonemapSky) == 96);
#endif

#endif
