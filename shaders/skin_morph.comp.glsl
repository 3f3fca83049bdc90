#version 460
#extension GL_GOOGLE_include_directive : require
// skin_morph: one invocation per vertex of one deformed draw. Morphs the rest vertex by the draw's
// non-zero morph weights, then, when skinned, places it by the weighted sum of its joint matrices
// (normals by the cofactor of that matrix, so non-uniform scale stays correct) — the glTF 2.0
// order. Writes the result into the frame's deformed-vertex buffer, which the forward pass draws
// from. The CPU reference is pose/skinning.h deformVertices.
#include "shared/skin_morph.h"

layout(local_size_x = CANDELA_SKIN_MORPH_GROUP_SIZE) in;

struct MorphDeltaData {
    vec4 position;
    vec4 normal;
    vec4 tangent;
    vec4 uv;
    vec4 color;
};
struct Influence {
    uint joint;
    float weight;
};

layout(std430, set = 0, binding = 0) readonly buffer BaseVertices { float base[]; };
layout(std430, set = 0, binding = 1) readonly buffer Deltas { MorphDeltaData deltas[]; };
layout(std430, set = 0, binding = 2) readonly buffer Influences { Influence influences[]; };
layout(std430, set = 0, binding = 3) readonly buffer Joints { mat4 joints[]; };
layout(std430, set = 0, binding = 4) readonly buffer ActiveTargets { ActiveMorphTarget activeTargets[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Deformed { float deformed[]; };

layout(push_constant) uniform Push {
    SkinMorphPush job;
};

vec3 unitOrZero(vec3 v) {
    float length2 = dot(v, v);
    return length2 > 0.0f ? v * inversesqrt(length2) : v;
}

void main() {
    uint v = gl_GlobalInvocationID.x;
    if (v >= job.vertexCount) return;
    uint src = (job.sourceFirstVertex + v) * CANDELA_VERTEX_FLOATS;
    vec3 p = vec3(base[src + 0], base[src + 1], base[src + 2]);
    vec3 n = vec3(base[src + 3], base[src + 4], base[src + 5]);
    vec4 t = vec4(base[src + 6], base[src + 7], base[src + 8], base[src + 9]);
    vec4 uv = vec4(base[src + 10], base[src + 11], base[src + 12], base[src + 13]);
    vec4 color = vec4(base[src + 14], base[src + 15], base[src + 16], base[src + 17]);

    // Only the targets with a non-zero weight this frame are touched.
    for (uint a = 0; a < job.activeCount; ++a) {
        ActiveMorphTarget target = activeTargets[job.activeBase + a];
        MorphDeltaData d = deltas[job.deltaBase + target.target * job.vertexCount + v];
        p += target.weight * d.position.xyz;
        n += target.weight * d.normal.xyz;
        t.xyz += target.weight * d.tangent.xyz;
        uv += target.weight * d.uv;
        color += target.weight * d.color;
    }

    if (job.influencesPerVertex > 0) {
        mat4 m = mat4(0.0f);
        for (uint i = 0; i < job.influencesPerVertex; ++i) {
            Influence influence = influences[job.influenceBase + v * job.influencesPerVertex + i];
            if (influence.weight > 0.0f) m += influence.weight * joints[job.jointBase + influence.joint];
        }
        mat3 linear = mat3(m);
        mat3 cofactor = mat3(cross(linear[1], linear[2]), cross(linear[2], linear[0]), cross(linear[0], linear[1]));
        p = (m * vec4(p, 1.0f)).xyz;
        n = cofactor * n;
        t.xyz = linear * t.xyz;
    }
    n = unitOrZero(n);
    t.xyz = unitOrZero(t.xyz);

    uint dst = (job.targetFirstVertex + v) * CANDELA_VERTEX_FLOATS;
    float values[CANDELA_VERTEX_FLOATS] = float[](p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y, t.z, t.w, uv.x, uv.y, uv.z, uv.w,
                                                  color.r, color.g, color.b, color.a);
    for (uint k = 0; k < CANDELA_VERTEX_FLOATS; ++k) deformed[dst + k] = values[k];
}
