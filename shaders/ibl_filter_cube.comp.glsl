#version 460
#extension GL_GOOGLE_include_directive : require
// IBL precompute: one mip of a filtered cube from the float environment cube, by summing a table
// of samples built once on the CPU (engine/passes/ibl/ibl_sample_tables.h): each entry is a
// direction in the texel's tangent frame (z = the texel's direction) and the source mip that
// filtered importance sampling assigns to it; the shader rotates, fetches and sums. Output is
// clamped to the half-float maximum.
//   specular prefilter (kWeightByCosine): GGX half vectors reflected about n (n = v = r), weighted
//     by n·l — the split sum's first term, one roughness per mip (mip 0 is ibl_cubemap.comp's);
//   irradiance cube: cosine-distributed samples, equal weights — E(n)/π.
// The source is the float cube with its bright texels clamped; their excess (BrightTexels) is added
// explicitly, each weighted by this mip's normalised lobe (LobeTable), so a sun is summed, not
// sampled (engine/ibl_maps/bright_texels.h).
#include "shared/ibl.h"
#include "shared/specialization_ids.h"

layout(constant_id = CANDELA_SPEC_FILTER_WEIGHT_BY_COSINE) const bool kWeightByCosine = true;

layout(local_size_x = CANDELA_IBL_GROUP, local_size_y = CANDELA_IBL_GROUP) in;

layout(set = 0, binding = 0) uniform samplerCube source;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2DArray dstMip;
layout(std430, set = 0, binding = 2) readonly buffer SampleTable {
    vec4 samples[];  // xyz: tangent-space direction (z = n·l), w: source lod
};

layout(std430, set = 0, binding = 3) readonly buffer BrightTexels {
    vec4 bright[];  // [0].x: count; then per texel (direction, 0), (flux rgb, 0)
};
layout(std430, set = 0, binding = 4) readonly buffer LobeTable {
    float lobe[];  // per mip CANDELA_IBL_LOBE_TABLE_SIZE entries (shared/ibl.h)
};

layout(push_constant) uniform Push {
    IblFilterPush push;
};

// This mip's lobe weight per steradian for cos θ between the texel's direction and a light's.
float lobeWeight(float cosTheta) {
    float theta = acos(clamp(cosTheta, -1.0f, 1.0f));
    if (theta >= 0.5f * CANDELA_PI) return 0.0f;
    float f = sqrt(theta * (2.0f / CANDELA_PI)) * float(CANDELA_IBL_LOBE_TABLE_SIZE - 1u);
    uint j = min(uint(f), CANDELA_IBL_LOBE_TABLE_SIZE - 2u);
    return mix(lobe[push.firstLobe + j], lobe[push.firstLobe + j + 1u], f - float(j));
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.faceSize || id.y >= push.faceSize) return;
    vec3 n = normalize(cubeFaceDirection(id.z, (vec2(id.xy) + 0.5f) / float(push.faceSize)));
    mat3 frame = basisAround(n);
    vec3 sum = vec3(0.0f);
    for (uint i = 0u; i < push.sampleCount; ++i) {
        vec4 s = samples[push.firstSample + i];
        vec3 radiance = textureLod(source, frame * s.xyz, s.w).rgb;
        sum += kWeightByCosine ? radiance * s.z : radiance;
    }
    vec3 filtered = sum * push.inverseWeight;
    uint brightCount = uint(bright[0].x);
    for (uint i = 0u; i < brightCount; ++i)
        filtered += bright[2u + 2u * i].rgb * lobeWeight(dot(n, bright[1u + 2u * i].xyz));
    imageStore(dstMip, ivec3(id), vec4(min(filtered, vec3(CANDELA_HALF_MAX)), 1.0f));
}
