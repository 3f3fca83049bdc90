#version 460
#extension GL_GOOGLE_include_directive : require
// The tonemap pass with the sky composited under the image (tonemap/composite.glsl).
#define CANDELA_TONEMAP_SKY
#include "tonemap/composite.glsl"
