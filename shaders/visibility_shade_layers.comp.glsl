#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's compute shading of materials with KHR_materials_* layers
// (visibility/shade.glsl with the layers' code and descriptors).
#define CANDELA_MATERIAL_LAYERS
#include "visibility/shade.glsl"
