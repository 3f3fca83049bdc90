#version 460
#extension GL_GOOGLE_include_directive : require
// Forward pass fragment stage for materials with KHR_materials_* layers: the shading of
// forward_fragment.glsl with the layers' code and descriptors (set 1, bindings 5 and up) compiled
// in. Core materials never use this program, so their pipelines are those without layers.
#define CANDELA_MATERIAL_LAYERS
#include "forward_fragment.glsl"
