#version 460
#extension GL_GOOGLE_include_directive : require
// The float cube in RGBA16F, for devices that cannot filter RGBA32F linearly (vk/device_choices.h):
// radiance × IblCubemapPush::cubeScale, clamped to the half-float maximum.
#define CANDELA_FLOAT_CUBE_FORMAT rgba16f
#define CANDELA_FLOAT_CUBE_HALF
#include "ibl/cubemap.glsl"
