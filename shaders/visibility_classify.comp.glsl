#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's classification of a single-sample visibility image (visibility/classify.glsl).
#include "visibility/classify.glsl"
