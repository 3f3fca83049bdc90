#version 460
#extension GL_GOOGLE_include_directive : require
// ibl_cubemap.comp and its variants (builtin_shaders.txt: they define CANDELA_FLOAT_CUBE_FORMAT,
// the storage format qualifier, and for the half-float cube CANDELA_FLOAT_CUBE_HALF).
// IBL precompute, step 1: the equirectangular environment (half floats, scaled into range; rotation
// 0) resampled into mip 0 of the float cube map — its bright texels clamped to push.clampLuminance
// (engine/ibl_maps/bright_texels.h) — and, as it is, into mip 0 of the specular cube (roughness 0 reflects the environment
// itself; clamped to the half-float maximum). Each cube texel averages k×k bilinear taps spread over its footprint, so a
// source finer than the cube is filtered rather than aliased. Bilinear by texelFetch: no linear
// filtering of 32-bit floats is required from the device.
#include "shared/environment.h"
#include "shared/ibl.h"

layout(local_size_x = CANDELA_IBL_GROUP, local_size_y = CANDELA_IBL_GROUP) in;

layout(set = 0, binding = 0) uniform sampler2D equirect;
layout(set = 0, binding = 1, CANDELA_FLOAT_CUBE_FORMAT) uniform writeonly image2DArray cubeMip0;
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2DArray specularMip0;

layout(push_constant) uniform Push {
    IblCubemapPush push;
};

vec3 fetchWrapped(ivec2 texel, ivec2 size) {
    texel.x = (texel.x % size.x + size.x) % size.x;
    texel.y = clamp(texel.y, 0, size.y - 1);
    return texelFetch(equirect, texel, 0).rgb;
}

// The bilinear filter at `uv` of the texels as they are (.full) and of the texels clamped to
// push.clampLuminance (.clamped).
struct Taps {
    vec3 full;
    vec3 clamped;
};

Taps bilinear(vec2 uv) {
    ivec2 size = textureSize(equirect, 0);
    vec2 p = uv * vec2(size) - 0.5f;
    vec2 base = floor(p);
    vec2 f = p - base;
    ivec2 b = ivec2(base);
    vec3 t00 = fetchWrapped(b, size), t10 = fetchWrapped(b + ivec2(1, 0), size);
    vec3 t01 = fetchWrapped(b + ivec2(0, 1), size), t11 = fetchWrapped(b + ivec2(1, 1), size);
    float c = push.clampLuminance;
    Taps taps;
    taps.full = mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
    taps.clamped = mix(mix(iblClampLuminance(t00, c), iblClampLuminance(t10, c), f.x),
                       mix(iblClampLuminance(t01, c), iblClampLuminance(t11, c), f.x), f.y);
    return taps;
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.faceSize || id.y >= push.faceSize) return;
    uint k = push.supersample;
    vec3 sum = vec3(0.0f), clampedSum = vec3(0.0f);
    for (uint j = 0u; j < k; ++j) {
        for (uint i = 0u; i < k; ++i) {
            vec2 uv = (vec2(id.xy) + (vec2(i, j) + 0.5f) / float(k)) / float(push.faceSize);
            Taps taps = bilinear(directionToEquirectUv(normalize(cubeFaceDirection(id.z, uv)), 0.0f));
            sum += taps.full;
            clampedSum += taps.clamped;
        }
    }
    vec3 radiance = sum / float(k * k) * push.equirectInverseScale;
    vec3 clamped = clampedSum / float(k * k) * push.equirectInverseScale;
#ifdef CANDELA_FLOAT_CUBE_HALF
    imageStore(cubeMip0, ivec3(id), vec4(min(clamped * push.cubeScale, vec3(CANDELA_HALF_MAX)), 1.0f));
#else
    imageStore(cubeMip0, ivec3(id), vec4(clamped * push.cubeScale, 1.0f));
#endif
    imageStore(specularMip0, ivec3(id), vec4(min(radiance, vec3(CANDELA_HALF_MAX)), 1.0f));
}
