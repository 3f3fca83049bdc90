// The sky behind the scene: the environment's radiance seen through a pixel, read from the
// specular cube at the blur level's mip (0 = the environment itself). Drawn by skybox.frag and,
// composited under the image, by tonemap_sky.frag. The includer declares `samplerCube specularCube`.
#ifndef CANDELA_SHARED_SKY_GLSL
#define CANDELA_SHARED_SKY_GLSL

#include "shared/sky_rays.h"

// The radiance of the sky through the pixel at `pixel` (gl_FragCoord.xy) along `rays` (the
// environment rotation included), at specular mip `lod`, scaled by `intensity`. The ray needs no
// normalization: a cube lookup divides by its major axis.
vec3 skyRadiance(SkyRays rays, vec2 pixel, float lod, float intensity) {
    vec3 ray = rays.perX.xyz * pixel.x + rays.perY.xyz * pixel.y + rays.origin.xyz;
    vec3 radiance = textureLod(specularCube, ray, lod).rgb;
    return min(radiance * intensity, vec3(60000.0f));
}

#endif
