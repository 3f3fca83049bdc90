#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's compute shading of a multisampled visibility image, core materials
// (visibility/shade.glsl).
#define CANDELA_VISIBILITY_MSAA
#include "visibility/shade.glsl"
