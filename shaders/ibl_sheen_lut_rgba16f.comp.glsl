#version 460
#extension GL_GOOGLE_include_directive : require
// The sheen LUT in RGBA16F, for devices that cannot filter R32F linearly (vk/device_choices.h).
#define CANDELA_LUT_FORMAT rgba16f
#include "ibl/sheen_lut.glsl"
