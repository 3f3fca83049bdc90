// The forward pass's fragment stage, included by forward.frag.glsl (core glTF materials), by
// forward_layers.frag.glsl (materials with KHR_materials_* layers: CANDELA_MATERIAL_LAYERS defined,
// the layer code and its descriptors compiled in) and by forward_reference.frag.glsl (the ground
// truth of `candela ibl-report`: CANDELA_IBL_REFERENCE defined). Its main gathers the fragment's
// inputs, evaluates the material (forward/material_eval.glsl: inputs → Surface), lights it
// (forward/lighting.glsl: Surface → radiance per lobe) and combines the lobes and layers. Variants
// are specialization constants (forward/resources.glsl), so what a draw does not use costs
// nothing: no normal map → no TBN work; no lights → no light loop; unlit → no BRDF; no environment
// → no image-based lighting; in the layered program, only the layers the material uses.
#extension GL_EXT_demote_to_helper_invocation : require
#include "forward/resources.glsl"

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec4 inColor;
layout(location = 4) in vec2 inTexUv[CANDELA_TEX_COUNT];  // per texture slot, transformed (see forward_vertex.glsl)
#ifdef CANDELA_MATERIAL_LAYERS
layout(location = 4 + CANDELA_TEX_COUNT) in vec4 inLayerUv[(CANDELA_LAYER_TEX_COUNT + 1) / 2];  // two layer slots each
#endif

layout(location = 0) out vec4 outColor;

// Material textures are read with the fragment's own derivatives (see forward/material_eval.glsl).
vec4 materialTexture(sampler2D t, vec2 uv) { return texture(t, uv); }

#include "forward/debug_views.glsl"
#include "forward/lighting.glsl"
#include "forward/material_eval.glsl"
#ifdef CANDELA_IBL_REFERENCE
#include "forward/reference_ibl.glsl"
#endif

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
    float alpha = materialOf(inputs).alphaMode == float(CANDELA_ALPHA_BLEND) ? baseColor.a : 1.0f;

    if (kUnlit && kDebugView == CANDELA_DEBUG_NONE) {
        outColor = vec4(baseColor.rgb * alpha, alpha * maskCoverage);
        return;
    }

    Surface s = evaluateMaterial(inputs, baseColor.rgb);
    SurfaceLight lit = noLight();
    if (kLights && !kUnlit) {
        for (uint i = 0u; i < push.counts.x; ++i) lit = plus(lit, lightRadiance(s, lights[i]));
    }
#ifdef CANDELA_IBL_REFERENCE
    vec3 reference = vec3(0.0f);
    if (kIbl && !kUnlit) reference = referenceImageBasedLight(s, gl_FragCoord.xy);
#else
    if (kIbl && !kUnlit) {
#ifdef CANDELA_MATERIAL_LAYERS
        lit = plus(lit, underLayers(imageBasedLight(s), s));
#else
        lit = plus(lit, imageBasedLight(s));
#endif
    }
#endif
    vec3 emissive = s.emissive;
    vec3 throughput = vec3(0.0f);  // the fraction of the light behind that comes through
#ifdef CANDELA_MATERIAL_LAYERS
    float backgroundAlpha = 1.0f;
    // The emission lies beneath the coat too.
    if (hasLayer(CANDELA_LAYER_CLEARCOAT)) emissive *= s.layers.coat.baseWeight;
    if (hasLayer(CANDELA_LAYER_TRANSMISSION)) {
        // The light from behind, beneath the sheen and the coat like the material's own.
        SurfaceLight behind = noLight();
        behind.transmission = transmittedThroughput(s);
        throughput = underLayers(behind, s).transmission;
        vec4 background = transmittedBackground(s, gl_FragCoord.xy);
        backgroundAlpha = background.a;
        lit.transmission += throughput * background.rgb;
    }
#endif

    if (kDebugView != CANDELA_DEBUG_NONE) {
        vec3 value = debugViewValue(s, lit, emissive, throughput);
        outColor = vec4(min(value, vec3(60000.0f)) * alpha, alpha * maskCoverage);
        return;
    }

    vec3 color = lit.diffuse + lit.specular + lit.sheen + lit.coat;
#ifdef CANDELA_IBL_REFERENCE
    color += reference;
#endif
    color += emissive;
#ifdef CANDELA_MATERIAL_LAYERS
    color += lit.transmission;
    // Where the background behind a transmitting surface is uncovered (a transparent background),
    // the part of it that comes through stays uncovered: coverage 1 − mean(throughput) · (1 − its alpha).
    float coverage = alpha * (1.0f - (throughput.r + throughput.g + throughput.b) * (1.0f / 3.0f) * (1.0f - backgroundAlpha));
#else
    float coverage = alpha;
#endif
    // Radiance can exceed half-float range with extreme lights: keep it finite.
    color = min(color, vec3(60000.0f));
    outColor = vec4(color * alpha, coverage * maskCoverage);
}
