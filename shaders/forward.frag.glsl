#version 460
#extension GL_GOOGLE_include_directive : require
// Forward pass fragment stage for core glTF materials (the shading is in forward_fragment.glsl).
#include "forward_fragment.glsl"
