#version 460
#extension GL_GOOGLE_include_directive : require
// The sheen LUT in R32F (the body is in ibl/sheen_lut.glsl).
#define CANDELA_LUT_FORMAT r32f
#include "ibl/sheen_lut.glsl"
