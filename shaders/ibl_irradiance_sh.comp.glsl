#version 460
#extension GL_GOOGLE_include_directive : require
// IBL precompute: diffuse irradiance as 9 spherical-harmonic coefficients. One workgroup projects
// every texel of one mip of the float cube (radiance × Y_lm × the texel's exact solid angle), reduces
// in shared memory and stores the coefficients already convolved with the clamped cosine and
// divided by π, so that irradiance(n)/π = Σ sh[i] · Y_i(n). The source is clamped at the bright
// texels (engine/ibl_maps/bright_texels.h); their excess is projected from the BrightTexels list.
#include "shared/ibl.h"

layout(local_size_x = CANDELA_IBL_SH_GROUP) in;

layout(set = 0, binding = 0) uniform samplerCube source;
layout(std430, set = 0, binding = 1) writeonly buffer ShCoefficients {
    vec4 shOut[9];
};

layout(std430, set = 0, binding = 2) readonly buffer BrightTexels {
    vec4 bright[];  // engine/ibl_maps/bright_texels.h: the excess the source's clamp removed
};

layout(push_constant) uniform Push {
    IblShPush push;
};

shared vec3 partial[CANDELA_IBL_SH_GROUP][9];

void main() {
    uint tid = gl_LocalInvocationIndex;
    vec3 sum[9];
    for (uint c = 0u; c < 9u; ++c) sum[c] = vec3(0.0f);
    uint faceTexels = push.faceSize * push.faceSize;
    for (uint t = tid; t < 6u * faceTexels; t += CANDELA_IBL_SH_GROUP) {
        uint face = t / faceTexels;
        uint x = t % push.faceSize;
        uint y = (t % faceTexels) / push.faceSize;
        vec3 d = normalize(cubeFaceDirection(face, (vec2(x, y) + 0.5f) / float(push.faceSize)));
        vec3 radiance = textureLod(source, d, push.lod).rgb * push.inverseScale * cubeTexelSolidAngle(x, y, push.faceSize);
        for (uint c = 0u; c < 9u; ++c) sum[c] += radiance * shBasis(c, d);
    }
    // The bright texels the source was clamped by, as point sources of their excess flux.
    uint brightCount = uint(bright[0].x);
    for (uint i = tid; i < brightCount; i += CANDELA_IBL_SH_GROUP) {
        vec3 d = bright[1u + 2u * i].xyz;
        vec3 flux = bright[2u + 2u * i].rgb;
        for (uint c = 0u; c < 9u; ++c) sum[c] += flux * shBasis(c, d);
    }
    for (uint c = 0u; c < 9u; ++c) partial[tid][c] = sum[c];
    barrier();
    for (uint stride = CANDELA_IBL_SH_GROUP / 2u; stride > 0u; stride /= 2u) {
        if (tid < stride)
            for (uint c = 0u; c < 9u; ++c) partial[tid][c] += partial[tid + stride][c];
        barrier();
    }
    if (tid < 9u) shOut[tid] = vec4(partial[0][tid] * shCosineBand(tid), 0.0f);
}
