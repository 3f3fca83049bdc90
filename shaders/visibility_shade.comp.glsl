#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's compute shading of core materials (visibility/shade.glsl).
#include "visibility/shade.glsl"
