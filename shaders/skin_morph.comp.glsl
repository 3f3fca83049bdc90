#version 460
#extension GL_GOOGLE_include_directive : require
// skin_morph: one invocation per vertex of a run of one deformed draw. Morphs the rest vertex by the
// draw's non-zero morph weights, then, when skinned, places it by the weighted sum of its joint
// matrices (normals by the cofactor of that matrix, so non-uniform scale stays correct) — the
// glTF 2.0 order. Writes the result into the frame's deformed-vertex buffer, which the forward pass
// draws from. The CPU reference is pose/skinning.h deformVertices.
//
// Four storage buffers (what every Vulkan device allows per stage): the scene's vertices, the
// scene's deformation records (influences and deltas per vertex, shared/skin_morph.h), this frame's
// joint matrices and non-zero weights in one buffer, and the output. Each dispatch binds only the
// ranges its vertices need (passes/deform/skin_morph_dispatch.h), so no binding passes
// maxStorageBufferRange, and may be a 2-D grid of groups (maxComputeWorkGroupCount).
#include "shared/skin_morph.h"

layout(local_size_x = CANDELA_SKIN_MORPH_GROUP_SIZE) in;

layout(std430, set = 0, binding = 0) readonly buffer BaseVertices { float base[]; };
layout(std430, set = 0, binding = 1) readonly buffer Deformation { uint deformation[]; };
layout(std430, set = 0, binding = 2) readonly buffer FrameData { uint frameData[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Deformed { float deformed[]; };

layout(push_constant) uniform Push {
    SkinMorphPush job;
};

vec3 unitOrZero(vec3 v) {
    float length2 = dot(v, v);
    return length2 > 0.0f ? v * inversesqrt(length2) : v;
}

vec4 deformationVec4(uint word) {
    return uintBitsToFloat(uvec4(deformation[word], deformation[word + 1], deformation[word + 2], deformation[word + 3]));
}

vec4 frameVec4(uint word) {
    return uintBitsToFloat(uvec4(frameData[word], frameData[word + 1], frameData[word + 2], frameData[word + 3]));
}

void main() {
    uint v = (gl_WorkGroupID.y * job.groupsX + gl_WorkGroupID.x) * CANDELA_SKIN_MORPH_GROUP_SIZE + gl_LocalInvocationID.x;
    if (v >= job.vertexCount) return;
    uint src = job.sourceFloat + v * CANDELA_VERTEX_FLOATS;
    vec3 p = vec3(base[src + 0], base[src + 1], base[src + 2]);
    vec3 n = vec3(base[src + 3], base[src + 4], base[src + 5]);
    vec4 t = vec4(base[src + 6], base[src + 7], base[src + 8], base[src + 9]);
    vec4 uv = vec4(base[src + 10], base[src + 11], base[src + 12], base[src + 13]);
    vec4 color = vec4(base[src + 14], base[src + 15], base[src + 16], base[src + 17]);
    uint record = job.recordWord + v * job.recordWords;

    // Only the targets with a non-zero weight this frame are touched.
    for (uint a = 0; a < job.activeCount; ++a) {
        uint weightWord = job.activeWord + a * CANDELA_ACTIVE_TARGET_WORDS;
        uint target = frameData[weightWord];
        float weight = uintBitsToFloat(frameData[weightWord + 1]);
        uint d = record + job.deltaWord + target * CANDELA_MORPH_DELTA_WORDS;
        p += weight * deformationVec4(d).xyz;
        n += weight * deformationVec4(d + 4).xyz;
        t.xyz += weight * deformationVec4(d + 8).xyz;
        uv += weight * deformationVec4(d + 12);
        color += weight * deformationVec4(d + 16);
    }

    if (job.influencesPerVertex > 0) {
        mat4 m = mat4(0.0f);
        for (uint i = 0; i < job.influencesPerVertex; ++i) {
            uint joint = deformation[record + i * CANDELA_INFLUENCE_WORDS];
            float weight = uintBitsToFloat(deformation[record + i * CANDELA_INFLUENCE_WORDS + 1]);
            if (weight > 0.0f) {
                uint j = job.jointWord + joint * CANDELA_JOINT_WORDS;
                m += weight * mat4(frameVec4(j), frameVec4(j + 4), frameVec4(j + 8), frameVec4(j + 12));
            }
        }
        mat3 linear = mat3(m);
        mat3 cofactor = mat3(cross(linear[1], linear[2]), cross(linear[2], linear[0]), cross(linear[0], linear[1]));
        p = (m * vec4(p, 1.0f)).xyz;
        n = cofactor * n;
        t.xyz = linear * t.xyz;
    }
    n = unitOrZero(n);
    t.xyz = unitOrZero(t.xyz);

    uint dst = job.targetFloat + v * CANDELA_VERTEX_FLOATS;
    float values[CANDELA_VERTEX_FLOATS] = float[](p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y, t.z, t.w, uv.x, uv.y, uv.z, uv.w,
                                                  color.r, color.g, color.b, color.a);
    for (uint k = 0; k < CANDELA_VERTEX_FLOATS; ++k) deformed[dst + k] = values[k];
}
