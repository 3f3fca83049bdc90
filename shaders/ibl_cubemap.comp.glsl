#version 460
#extension GL_GOOGLE_include_directive : require
// The float cube in RGBA32F (the body is in ibl/cubemap.glsl).
#define CANDELA_FLOAT_CUBE_FORMAT rgba32f
#include "ibl/cubemap.glsl"
