// The sky behind the scene: the environment's radiance seen through a pixel, read from the
// specular cube at the blur level's mip (0 = the environment itself). Drawn by skybox.frag and,
// composited under the image, by tonemap_sky.frag. The includer declares `samplerCube specularCube`.
#ifndef CANDELA_SHARED_SKY_GLSL
#define CANDELA_SHARED_SKY_GLSL

#include "shared/ibl.h"

// The radiance of the sky through normalized device coordinates `ndc` of a view whose inverse
// view-projection is `inverseViewProjection` with the eye at `eye`: the environment rotated by
// `rotation` (cos θ, sin θ), at specular mip `lod`, scaled by `intensity`.
vec3 skyRadiance(mat4 inverseViewProjection, vec3 eye, vec2 rotation, float lod, float intensity, vec2 ndc) {
    // A point on the near plane (reverse-Z: depth 1) through this pixel; the view ray is from the eye.
    vec4 nearPoint = inverseViewProjection * vec4(ndc, 1.0f, 1.0f);
    vec3 direction = normalize(nearPoint.xyz / nearPoint.w - eye);
    vec3 radiance = textureLod(specularCube, iblLookupDirection(direction, vec4(rotation, 0.0f, 0.0f)), lod).rgb;
    return min(radiance * intensity, vec3(60000.0f));
}

#endif
