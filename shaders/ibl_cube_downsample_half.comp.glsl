#version 460
#extension GL_GOOGLE_include_directive : require
// The float cube in RGBA16F, for devices that cannot filter RGBA32F linearly (vk/device_choices.h).
#define CANDELA_FLOAT_CUBE_FORMAT rgba16f
#include "ibl/cube_downsample.glsl"
