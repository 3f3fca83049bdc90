// The procedural HDR test pattern of the first render graph, shared by pattern.comp.glsl and the
// CPU reference in the tests.
#ifndef CANDELA_SHARED_PATTERN_H
#define CANDELA_SHARED_PATTERN_H

#include "shared/compat.h"

CANDELA_NAMESPACE_BEGIN

#define CANDELA_PATTERN_GROUP_SIZE 8

// Push constants of pattern.comp (std430 layout).
struct PatternParams {
    uvec2 extent;  // image size in pixels
    float exposure;  // multiplies the radiance
    float pad0;
};

// Linear radiance at uv in [0,1]²: a hue wheel from top to bottom whose intensity ramps
// exponentially from 1/16 to 16 left to right (so values above 1 exercise HDR), with a bright ring.
CANDELA_FN vec3 patternRadiance(vec2 uv) {
    float h = uv.y * 6.0f;
    vec3 hue = clamp(vec3(abs(h - 3.0f) - 1.0f, 2.0f - abs(h - 2.0f), 2.0f - abs(h - 4.0f)), vec3(0.0f), vec3(1.0f));
    float intensity = exp2(mix(-4.0f, 4.0f, uv.x));
    float r = length(uv - vec2(0.5f));
    float ring = clamp(1.0f - abs(r - 0.3f) * 50.0f, 0.0f, 1.0f);
    return hue * intensity + vec3(ring * 8.0f);
}

CANDELA_NAMESPACE_END

#endif
