#version 460
#extension GL_GOOGLE_include_directive : require
// The tonemap pass: exposure, tone mapping, background compositing and sRGB encoding of the HDR
// frame, compiled as tonemap.frag and tonemap_sky.frag (CANDELA_TONEMAP_SKY: the sky composited
// under the image first; builtin_shaders.txt).
// The HDR image's alpha is coverage (geometry writes 1, blended surfaces their alpha, the clear 0);
// its RGB is premultiplied by coverage.
#include "shared/tonemap.h"
#include "shared/specialization_ids.h"

// Specialization constants: llvmpipe executes both sides of uniform branches, so the operator and
// the output options are compiled in rather than selected at run time.
layout(constant_id = CANDELA_SPEC_TONEMAP_OPERATOR) const uint kOperator = CANDELA_TONEMAP_PBR_NEUTRAL;
layout(constant_id = CANDELA_SPEC_TONEMAP_ENCODE_SRGB) const bool kEncodeSrgb = true;
layout(constant_id = CANDELA_SPEC_TONEMAP_DITHER) const bool kDither = false;
layout(constant_id = CANDELA_SPEC_TONEMAP_BACKGROUND) const bool kBackground = true;
// The sky's pixels hold the image's clear value, transparent black: drawn only where nothing was
// drawn, in a frame without blended draws (which leave the depth as it was). The image is then not
// read, which on llvmpipe is a fifth of the pass.
layout(constant_id = CANDELA_SPEC_TONEMAP_IMAGE_CLEAR) const bool kImageClear = false;

layout(set = 0, binding = 0) uniform sampler2D hdrImage;
#ifdef CANDELA_TONEMAP_SKY
// The sky composited under the image (where its coverage is below 1), instead of a skybox pass.
layout(set = 0, binding = 1) uniform samplerCube specularCube;
layout(push_constant) uniform Push {
    TonemapParams params;
    TonemapSky sky;
};
#include "shared/sky.glsl"
#else
layout(push_constant) uniform Push {
    TonemapParams params;
};
#endif

layout(location = 0) out vec4 outColor;

// Triangular dither in [-1, 1) LSB from an integer hash of the pixel.
float ditherNoise(uvec2 p) {
    uint h = p.x * 1973u + p.y * 9277u + 89173u;
    h = (h << 13u) ^ h;
    h = h * (h * h * 15731u + 789221u) + 1376312589u;
    float a = float(h & 0xffffu) / 65536.0f;
    float b = float((h >> 16u) & 0xffffu) / 65536.0f;
    return a + b - 1.0f;
}

void main() {
    vec4 hdr = vec4(0.0f);
    if (!kImageClear) hdr = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0);
#ifdef CANDELA_TONEMAP_SKY
    // Under the image, as the skybox pass blends it: colour += (1 − coverage) · sky, coverage 1.
    vec3 behind = skyRadiance(sky.rays, gl_FragCoord.xy, sky.intensityLod.y, sky.intensityLod.x);
    hdr = vec4(hdr.rgb + (1.0f - clamp(hdr.a, 0.0f, 1.0f)) * behind, 1.0f);
#endif
    float coverage = clamp(hdr.a, 0.0f, 1.0f);
    vec3 radiance = coverage > 0.0f ? hdr.rgb / coverage : vec3(0.0f);
    vec3 display = applyTonemap(radiance * params.exposureScale, kOperator);
    float alpha = coverage;
    if (kBackground) {
        display = mix(params.background.rgb, display, coverage);
        alpha = 1.0f;
    }
    if (kEncodeSrgb) display = srgbEncode(display);
    if (kDither) display += vec3(ditherNoise(uvec2(gl_FragCoord.xy)) / 255.0f);
    outColor = vec4(display, alpha);
}
