#version 460
#extension GL_GOOGLE_include_directive : require
// The tonemap pass (tonemap/composite.glsl), and its variants (builtin_shaders.txt).
#include "tonemap/composite.glsl"
