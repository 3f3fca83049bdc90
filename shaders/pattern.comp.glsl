#version 460
#extension GL_GOOGLE_include_directive : require
// Writes the procedural HDR test pattern into a storage image, one invocation per pixel.
#include "shared/pattern.h"

layout(local_size_x = CANDELA_PATTERN_GROUP_SIZE, local_size_y = CANDELA_PATTERN_GROUP_SIZE) in;

layout(set = 0, binding = 0, rgba16f) uniform writeonly image2D outImage;

layout(push_constant) uniform Push {
    PatternParams params;
};

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, params.extent))) return;
    vec2 uv = (vec2(pixel) + 0.5f) / vec2(params.extent);
    imageStore(outImage, ivec2(pixel), vec4(patternRadiance(uv) * params.exposure, 1.0f));
}
