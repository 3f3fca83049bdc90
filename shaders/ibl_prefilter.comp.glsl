#version 460
#extension GL_GOOGLE_include_directive : require
// IBL precompute: one mip (≥ 1) of the specular cube — the environment convolved with the GGX lobe
// of that mip's roughness (split-sum first term, n = v = r, weighted by n·l). The samples (GGX
// half vectors reflected about n, with the source mip that filtered importance sampling assigns
// to each) come from a table built once on the CPU (engine/ibl/ibl_sample_tables.h); the shader
// rotates them into the texel's frame, fetches and sums. Mip 0 is written by ibl_cubemap.comp.
// Output is clamped to the half-float maximum.
#include "shared/ibl.h"

layout(local_size_x = CANDELA_IBL_GROUP, local_size_y = CANDELA_IBL_GROUP) in;

layout(set = 0, binding = 0) uniform samplerCube source;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2DArray dstMip;
layout(std430, set = 0, binding = 2) readonly buffer SampleTable {
    vec4 samples[];  // xyz: tangent-space direction (z = n·l), w: source lod
};

layout(push_constant) uniform Push {
    IblFilterPush push;
};

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.faceSize || id.y >= push.faceSize) return;
    vec3 n = normalize(cubeFaceDirection(id.z, (vec2(id.xy) + 0.5f) / float(push.faceSize)));
    mat3 frame = basisAround(n);
    vec3 sum = vec3(0.0f);
    for (uint i = 0u; i < push.sampleCount; ++i) {
        vec4 s = samples[push.firstSample + i];
        sum += textureLod(source, frame * s.xyz, s.w).rgb * s.z;
    }
    imageStore(dstMip, ivec3(id), vec4(min(sum * push.inverseWeight, vec3(CANDELA_HALF_MAX)), 1.0f));
}
