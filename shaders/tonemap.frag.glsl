#version 460
#extension GL_GOOGLE_include_directive : require
// The tonemap pass (tonemap/composite.glsl).
#include "tonemap/composite.glsl"
