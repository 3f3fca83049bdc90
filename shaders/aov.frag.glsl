#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_demote_to_helper_invocation : require
// The aov pass's fragment stage (docs/outputs.md): what the surface nearest the viewer is at each
// pixel centre — its view depth, shading normal, base colour and alpha, metallic and roughness,
// emission, and the IDs of what drew it — written to the targets of shared/aov_targets.h that
// the frame asks for (kTargets, fixed at load: the outputs of the others and the work only they
// need are compiled out, and their locations have no attachment). The material is read as the shading
// reads it (shading/material_eval.glsl): factor × COLOR_0 × texture, the normal map in the frame of
// the interpolated tangent.
#include "shading/resources.glsl"
#include "shared/aov_targets.h"

layout(constant_id = CANDELA_SPEC_AOV_TARGETS) const uint kTargets = 0u;

layout(location = 4 + CANDELA_TEX_COUNT) flat in uint inEntry;  // this instance's index into Draws (aov.vert)

layout(location = CANDELA_AOV_VIEW_DEPTH) out float outViewDepth;
layout(location = CANDELA_AOV_NORMAL) out vec4 outNormal;
layout(location = CANDELA_AOV_BASE_COLOR) out vec4 outBaseColor;
layout(location = CANDELA_AOV_METALLIC_ROUGHNESS) out vec2 outMetallicRoughness;
layout(location = CANDELA_AOV_EMISSIVE) out vec4 outEmissive;
layout(location = CANDELA_AOV_IDS) out uvec4 outIds;
layout(location = CANDELA_AOV_INSTANCE) out uint outInstance;

#define CANDELA_CORE_TEXTURE(inputs, field, slot) texture(field##Texture, (inputs).uv[slot])
#include "shading/material_eval.glsl"
#include "shading/fragment_inputs.glsl"

bool writes(uint target) { return (kTargets & (1u << target)) != 0u; }

// The distance from the eye along the view axis to `p` (world units). A perspective projection's
// clip w is exactly that (its last row is −(the view's third row)); an orthographic one has w 1,
// and its depth row is the view axis scaled: the eye is the camera's position in both.
float viewDepth(vec3 p) {
    mat4 vp = push.viewProjection;
    vec4 w = vec4(vp[0][3], vp[1][3], vp[2][3], vp[3][3]);
    if (dot(w.xyz, w.xyz) > 0.0f) return dot(w, vec4(p, 1.0f));
    vec3 back = normalize(vec3(vp[0][2], vp[1][2], vp[2][2]));  // reverse Z: depth grows toward the eye
    return dot(push.eye.xyz - p, back);
}

void main() {
    SurfaceInputs inputs = fragmentInputs();  // kSpecularAa is off: no normal change computed
    MaterialData m = materialOf(inputs);
    vec4 baseColor = materialBaseColor(inputs);
    // The surfaces the outputs describe: opaque ones; masked ones where alpha reaches the cutoff
    // (as the image shows them); blended ones where alpha reaches ½.
    uint alphaMode = uint(m.alphaMode);
    if (kAlphaMask && baseColor.a < (alphaMode == CANDELA_ALPHA_BLEND ? 0.5f : m.alphaCutoff)) demote;

    if (writes(CANDELA_AOV_VIEW_DEPTH)) outViewDepth = viewDepth(inWorldPosition);
    if (writes(CANDELA_AOV_NORMAL)) {
        vec3 n = facedNormal(inputs);
        if (kNormalMap) {
            vec4 texel = CANDELA_CORE_TEXTURE(inputs, normal, CANDELA_TEX_NORMAL);
            n = mapNormal(n, inputs.tangent, texel.xyz * 2.0f - 1.0f, m.normalScale);
        }
        outNormal = vec4(n, 0.0f);
    }
    // Alpha: how much of what lies behind the surface it covers — 1 for opaque and masked
    // surfaces (a mask keeps or drops), the material's alpha for blended ones.
    if (writes(CANDELA_AOV_BASE_COLOR)) outBaseColor = vec4(baseColor.rgb, alphaMode == CANDELA_ALPHA_BLEND ? baseColor.a : 1.0f);
    if (writes(CANDELA_AOV_METALLIC_ROUGHNESS)) {
        vec4 mr = CANDELA_CORE_TEXTURE(inputs, metallicRoughness, CANDELA_TEX_METALLIC_ROUGHNESS);
        outMetallicRoughness = vec2(clamp(m.metallic * mr.b, 0.0f, 1.0f), clamp(m.roughness * mr.g, 0.0f, 1.0f));
    }
    if (writes(CANDELA_AOV_EMISSIVE))
        outEmissive = vec4(m.emissive.rgb * CANDELA_CORE_TEXTURE(inputs, emissive, CANDELA_TEX_EMISSIVE).rgb, 0.0f);
    DrawData draw = draws[inEntry];
    if (writes(CANDELA_AOV_IDS)) outIds = uvec4(draw.ids.xyz, draw.material.x);
    if (writes(CANDELA_AOV_INSTANCE)) outInstance = draw.ids.w;
}
