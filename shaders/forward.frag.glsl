#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_demote_to_helper_invocation : require
// The forward pass's fragment stage, which builtin_shaders.txt compiles as forward.frag (core glTF
// materials), forward_layers.frag (materials with KHR_materials_* layers: CANDELA_MATERIAL_LAYERS
// defined, the layer code and its descriptors compiled in) and forward_reference.frag (the ground
// truth of `candela ibl-report`: CANDELA_IBL_REFERENCE defined). Its main gathers the fragment's
// inputs, applies the alpha test or alpha to coverage, and shades (shading/shade.glsl, which the
// visibility path's compute shading calls too: the material evaluated, lit, its lobes combined).
// Variants are specialization constants (shading/resources.glsl), so what a draw does not use costs
// nothing: no normal map → no TBN work; no lights → no light loop; unlit → no BRDF; no environment
// → no image-based lighting; in the layered program, only the layers the material uses.
#include "shading/resources.glsl"

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec4 inColor;
layout(location = 4) in vec2 inTexUv[CANDELA_TEX_COUNT];  // per texture slot, transformed (see forward.vert.glsl)
#ifdef CANDELA_MATERIAL_LAYERS
layout(location = 4 + CANDELA_TEX_COUNT) in vec4 inLayerUv[(CANDELA_LAYER_TEX_COUNT + 1) / 2];  // two layer slots each
#endif

layout(location = 0) out vec4 outColor;

// Material textures are read with the fragment's own derivatives (see shading/material_eval.glsl).
#define CANDELA_CORE_TEXTURE(inputs, field, slot) texture(field##Texture, (inputs).uv[slot])
#define CANDELA_LAYER_TEXTURE(inputs, field, slot) texture(field##Texture, (inputs).layerUv[slot])

#include "shading/shade.glsl"

// What material evaluation reads of this fragment: its interpolants, the face normal from the
// position's derivatives and, with specular AA, the normal's change across the pixel.
SurfaceInputs fragmentInputs() {
    SurfaceInputs inputs;
    inputs.draw = push.counts.y;
    inputs.eye = push.eye.xyz;
    inputs.position = inWorldPosition;
    inputs.normal = inNormal;
    inputs.tangent = inTangent;
    inputs.faceNormal = normalize(cross(dFdx(inWorldPosition), dFdy(inWorldPosition)));
    inputs.frontFacing = gl_FrontFacing;
    inputs.color = inColor;
    inputs.uv = inTexUv;
#ifdef CANDELA_MATERIAL_LAYERS
    for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) {
        vec4 pair = inLayerUv[slot / 2];
        inputs.layerUv[slot] = (slot & 1) == 0 ? pair.xy : pair.zw;
    }
#endif
    // |∂n/∂x|² + |∂n/∂y|² of the faced (interpolated vertex) normal, for geometric specular AA; the
    // normal map's detail is accounted for by its filtered length instead.
    inputs.normalChange = 0.0f;
    if (kSpecularAa) {
        vec3 n = facedNormal(inputs);
        vec3 dx = dFdx(n), dy = dFdy(n);
        inputs.normalChange = dot(dx, dx) + dot(dy, dy);
    }
    return inputs;
}

void main() {
    SurfaceInputs inputs = fragmentInputs();
    vec4 baseColor = materialBaseColor(inputs);
    float alphaCutoff = materialOf(inputs).alphaCutoff;
    // The fraction of the pixel inside the cutoff's edge: alpha sharpened so that it crosses 0 → 1
    // over one pixel around the cutoff (Castaño 2010; Golus 2017), which alpha to coverage turns
    // into that many samples. Without MSAA the alpha test.
    float maskCoverage = 1.0f;
    if (kAlphaMask && kAlphaToCoverage) {
        maskCoverage = clamp((baseColor.a - alphaCutoff) / max(fwidth(baseColor.a), 1e-4f) + 0.5f, 0.0f, 1.0f);
        if (maskCoverage <= 0.0f) demote;
    } else if (kAlphaMask && baseColor.a < alphaCutoff) demote;
    outColor = shadeSurface(inputs, baseColor, gl_FragCoord.xy);
    outColor.a *= maskCoverage;
}
