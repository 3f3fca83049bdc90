#version 460
#extension GL_GOOGLE_include_directive : require
// Forward pass vertex stage for materials with KHR_materials_* layers: also the layer textures'
// transformed coordinates (see forward_vertex.glsl).
#define CANDELA_MATERIAL_LAYERS
#include "forward_vertex.glsl"
