// The fragment stage's inputs from the forward vertex stage (forward.vert.glsl: world position,
// normal, tangent, COLOR_0, each texture slot's transformed coordinates) and SurfaceInputs made of
// them, as the forward programs and the aov pass read a material (forward.frag.glsl,
// aov.frag.glsl). Include after shading/material_eval.glsl (facedNormal).
#ifndef CANDELA_FRAGMENT_INPUTS_GLSL
#define CANDELA_FRAGMENT_INPUTS_GLSL

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec4 inColor;
layout(location = 4) in vec2 inTexUv[CANDELA_TEX_COUNT];  // per texture slot, transformed (see forward.vert.glsl)
#ifdef CANDELA_MATERIAL_LAYERS
layout(location = 4 + CANDELA_TEX_COUNT) in vec4 inLayerUv[(CANDELA_LAYER_TEX_COUNT + 1) / 2];  // two layer slots each
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

#endif
