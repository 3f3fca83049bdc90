#version 460
#extension GL_GOOGLE_include_directive : require
// The ground truth of `candela ibl-report` (ForwardPass::Variant::referenceSamples > 0): the
// forward pass's fragment stage for core materials with the environment's light integrated per
// pixel (forward/reference_ibl.glsl) instead of the split sum.
#define CANDELA_IBL_REFERENCE
#include "forward_fragment.glsl"
