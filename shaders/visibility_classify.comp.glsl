#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's classification (visibility/classify.glsl), and its variants (builtin_shaders.txt).
#include "visibility/classify.glsl"
