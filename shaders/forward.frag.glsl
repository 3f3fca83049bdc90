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

layout(location = 0) out vec4 outColor;

// Material textures are read with the fragment's own derivatives (see shading/material_eval.glsl).
#define CANDELA_CORE_TEXTURE(inputs, field, slot) texture(field##Texture, (inputs).uv[slot])
#define CANDELA_LAYER_TEXTURE(inputs, field, slot) texture(field##Texture, (inputs).layerUv[slot])

#include "shading/shade.glsl"
#include "shading/fragment_inputs.glsl"

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
