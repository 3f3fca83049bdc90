#version 460
#extension GL_GOOGLE_include_directive : require
// Forward pass vertex stage for core glTF materials (see forward_vertex.glsl).
#include "forward_vertex.glsl"
