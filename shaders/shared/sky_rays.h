// The view rays of the sky (shared/sky.glsl), shared by skybox.frag's and tonemap_sky.frag's push
// constants and the host code that computes them (passes/backdrop/sky_rays.h).
#ifndef CANDELA_SHARED_SKY_RAYS_H
#define CANDELA_SHARED_SKY_RAYS_H

#include "shared/compat.h"

CANDELA_NAMESPACE_BEGIN

// The view rays through a target's pixels (shared/sky.glsl): ray(p) = perX·p.x + perY·p.y + origin
// for p = gl_FragCoord.xy, from the eye through the pixel's centre, in the environment's frame (its
// rotation applied), not normalized. A linear function of p, computed once a frame on the host
// (passes/backdrop/sky_rays.h), so that a pixel pays three multiply-adds per component for its ray.
struct SkyRays {
    /*Ignore*/ vec4 perX;    // w unused
    /*Ignore*/ vec4 perY;    // w unused
    /*Ignore*/ vec4 origin;  // w unused
};

CANDELA_NAMESPACE_END

#ifdef __cplusplus
static_assert(sizeof(candela::shading::SkyRays) == 48);
#endif

#endif
