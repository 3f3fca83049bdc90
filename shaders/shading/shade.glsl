// The shading both paths share: a surface point's material evaluated (shading/material_eval.glsl),
// lit (shading/lighting.glsl) and its lobes and layers combined into premultiplied radiance and
// coverage. Called by the forward fragment stage (forward.frag.glsl) and by the visibility
// path's compute shading (visibility_shade.comp.glsl), so both paths run the same code.
#ifndef CANDELA_FORWARD_SHADE_GLSL
#define CANDELA_FORWARD_SHADE_GLSL

#include "shading/debug_views.glsl"
#include "shading/lighting.glsl"
#include "shading/material_eval.glsl"
#ifdef CANDELA_IBL_REFERENCE
#include "shading/reference_ibl.glsl"
#endif

// The premultiplied radiance (rgb) and coverage (a) of the surface at `inputs` with base colour
// `baseColor` (materialBaseColor), seen through window position `pixel` (pixel centre, as
// gl_FragCoord.xy: where transmission and the ground truth read the screen).
vec4 shadeSurface(SurfaceInputs inputs, vec4 baseColor, vec2 pixel) {
    float alpha = materialOf(inputs).alphaMode == float(CANDELA_ALPHA_BLEND) ? baseColor.a : 1.0f;

    if (kUnlit && kDebugView == CANDELA_DEBUG_NONE) {
        return vec4(baseColor.rgb * alpha, alpha);
    }

    Surface s = evaluateMaterial(inputs, baseColor.rgb);
    SurfaceLight lit = noLight();
    if (kLights && !kUnlit) {
        for (uint i = 0u; i < push.counts.x; ++i) lit = plus(lit, lightRadiance(s, lights[i]));
    }
#ifdef CANDELA_IBL_REFERENCE
    vec3 reference = vec3(0.0f);
    if (kIbl && !kUnlit) reference = referenceImageBasedLight(s, pixel);
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
        vec4 background = transmittedBackground(s, pixel);
        backgroundAlpha = background.a;
        lit.transmission += throughput * background.rgb;
    }
#endif

    if (kDebugView != CANDELA_DEBUG_NONE) {
        vec3 value = debugViewValue(s, lit, emissive, throughput);
        return vec4(min(value, vec3(60000.0f)) * alpha, alpha);
    }

    vec3 color = lit.diffuse + lit.specular + lit.sheen + lit.coat;
#ifdef CANDELA_IBL_REFERENCE
    color += reference;
#endif
    color += emissive;
#ifdef CANDELA_MATERIAL_LAYERS
    color += lit.transmission;
    if (hasLayer(CANDELA_LAYER_DIFFUSE_TRANSMISSION)) color += lit.diffuseTransmission;
    // Where the background behind a transmitting surface is uncovered (a transparent background),
    // the part of it that comes through stays uncovered: coverage 1 − mean(throughput) · (1 − its alpha).
    float coverage = alpha * (1.0f - (throughput.r + throughput.g + throughput.b) * (1.0f / 3.0f) * (1.0f - backgroundAlpha));
#else
    float coverage = alpha;
#endif
    // Radiance can exceed half-float range with extreme lights: keep it finite.
    color = min(color, vec3(60000.0f));
    return vec4(color * alpha, coverage);
}

#endif
