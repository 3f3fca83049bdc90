#version 460
#extension GL_GOOGLE_include_directive : require
// The BRDF LUT in RG16F (the body is in ibl/brdf_lut.glsl).
#define CANDELA_LUT_FORMAT rg16f
#include "ibl/brdf_lut.glsl"
