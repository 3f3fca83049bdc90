// The body of shaders/ibl_cubemap.comp.glsl and its variants: they define CANDELA_FLOAT_CUBE_FORMAT (the storage
// format qualifier) and include this file.
#ifndef CANDELA_IBL_CUBEMAP_GLSL
#define CANDELA_IBL_CUBEMAP_GLSL
// IBL precompute, step 1: the equirectangular environment (half floats, scaled into range; rotation
// 0) resampled into mip 0
// of the float cube map, and into mip 0 of the specular cube (roughness 0 reflects the environment
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

vec3 bilinear(vec2 uv) {
    ivec2 size = textureSize(equirect, 0);
    vec2 p = uv * vec2(size) - 0.5f;
    vec2 base = floor(p);
    vec2 f = p - base;
    ivec2 b = ivec2(base);
    vec3 top = mix(fetchWrapped(b, size), fetchWrapped(b + ivec2(1, 0), size), f.x);
    vec3 bottom = mix(fetchWrapped(b + ivec2(0, 1), size), fetchWrapped(b + ivec2(1, 1), size), f.x);
    return mix(top, bottom, f.y);
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.faceSize || id.y >= push.faceSize) return;
    uint k = push.supersample;
    vec3 sum = vec3(0.0f);
    for (uint j = 0u; j < k; ++j) {
        for (uint i = 0u; i < k; ++i) {
            vec2 uv = (vec2(id.xy) + (vec2(i, j) + 0.5f) / float(k)) / float(push.faceSize);
            sum += bilinear(directionToEquirectUv(normalize(cubeFaceDirection(id.z, uv)), 0.0f));
        }
    }
    vec3 radiance = sum / float(k * k) * push.equirectInverseScale;
#ifdef CANDELA_FLOAT_CUBE_HALF
    imageStore(cubeMip0, ivec3(id), vec4(min(radiance * push.cubeScale, vec3(CANDELA_HALF_MAX)), 1.0f));
#else
    imageStore(cubeMip0, ivec3(id), vec4(radiance * push.cubeScale, 1.0f));
#endif
    imageStore(specularMip0, ivec3(id), vec4(min(radiance, vec3(CANDELA_HALF_MAX)), 1.0f));
}

#endif
