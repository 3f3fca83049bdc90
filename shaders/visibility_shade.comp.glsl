#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's compute shading (visibility/shade.glsl), and its variants (builtin_shaders.txt).
#include "visibility/shade.glsl"
