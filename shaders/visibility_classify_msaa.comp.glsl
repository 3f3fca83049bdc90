#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's classification of a multisampled visibility image (visibility/classify.glsl).
#define CANDELA_VISIBILITY_MSAA
#include "visibility/classify.glsl"
