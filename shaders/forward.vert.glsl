#version 460
#extension GL_GOOGLE_include_directive : require
// The forward pass's vertex stage (forward.vert, and with CANDELA_MATERIAL_LAYERS defined
// forward_layers.vert: builtin_shaders.txt): world-space position, normal and tangent of one drawn
// primitive (triangles, lines or points), and the transformed texture coordinates of each texture slot; with CANDELA_AOV defined
// (aov.vert: the per-pixel outputs' pass, aov.frag.glsl) also the draw entry of the instance.
#include "shading/scene_buffers.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;

CANDELA_DRAWS_BLOCK
CANDELA_MATERIALS_BLOCK
#ifdef CANDELA_MATERIAL_LAYERS
CANDELA_MATERIAL_LAYERS_BLOCK
#endif
layout(push_constant) uniform Push {
    FramePush push;
};

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec4 outTangent;
layout(location = 3) out vec4 outColor;
// Texture coordinates of each material texture slot, after KHR_texture_transform. Transformed here
// rather than per pixel so that their screen-space derivatives (mip selection) come from plain
// interpolants: a fragment-stage transform built from storage-buffer loads gave wrong derivatives
// at triangle edges on lavapipe, whose helper invocations skip those loads.
layout(location = 4) out vec2 outTexUv[CANDELA_TEX_COUNT];
#ifdef CANDELA_MATERIAL_LAYERS
// The layer texture slots' coordinates, two per location (.xy, .zw): the layers bring many texture
// slots, and a device need offer only 16 output locations.
layout(location = 4 + CANDELA_TEX_COUNT) out vec4 outLayerUv[(CANDELA_LAYER_TEX_COUNT + 1) / 2];
#endif
#ifdef CANDELA_AOV
layout(location = 4 + CANDELA_TEX_COUNT) flat out uint outEntry;  // index into Draws of this instance
#endif

void main() {
    // Instanced draws (EXT_mesh_gpu_instancing) have one entry per instance, in a row.
    DrawData draw = draws[push.counts.y + gl_InstanceIndex];
    vec4 world = draw.world * vec4(inPosition, 1.0f);
    outWorldPosition = world.xyz;
    outNormal = mat3(draw.normalMatrix) * inNormal;
    outTangent = vec4(mat3(draw.world) * inTangent.xyz, inTangent.w);
    outColor = inColor;
    MaterialData material = materials[draw.material.x];
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) outTexUv[slot] = transformUv(material.uv[slot], inUv0, inUv1);
#ifdef CANDELA_MATERIAL_LAYERS
    MaterialLayerData layer = layers[draw.material.x];
    for (int i = 0; i < (CANDELA_LAYER_TEX_COUNT + 1) / 2; ++i) {
        // An odd count leaves the last .zw unused (it repeats the last slot).
        vec2 second = transformUv(layer.uv[min(2 * i + 1, CANDELA_LAYER_TEX_COUNT - 1)], inUv0, inUv1);
        outLayerUv[i] = vec4(transformUv(layer.uv[2 * i], inUv0, inUv1), second);
    }
#endif
#ifdef CANDELA_AOV
    outEntry = push.counts.y + gl_InstanceIndex;
#endif
    gl_Position = push.viewProjection * world;
    // POINTS draws (point-list pipelines) are one pixel, as glTF viewers draw them; other
    // topologies ignore it.
    gl_PointSize = 1.0f;
}
