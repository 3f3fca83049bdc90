#version 460
#extension GL_GOOGLE_include_directive : require
// The forward pass's fragment stage (forward_fragment.glsl), and its variants (builtin_shaders.txt).
#include "forward_fragment.glsl"
