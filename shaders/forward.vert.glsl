#version 460
#extension GL_GOOGLE_include_directive : require
// The forward pass's vertex stage (forward_vertex.glsl), and its variants (builtin_shaders.txt).
#include "forward_vertex.glsl"
