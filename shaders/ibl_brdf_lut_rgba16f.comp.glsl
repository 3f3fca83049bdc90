#version 460
#extension GL_GOOGLE_include_directive : require
// The BRDF LUT in RGBA16F, for devices without RG16F storage images (an extended storage format; vk/device_choices.h).
#define CANDELA_LUT_FORMAT rgba16f
#include "ibl/brdf_lut.glsl"
