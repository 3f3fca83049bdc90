#pragma once
// The view rays the sky is looked up along (shared/sky_rays.h), computed once a frame: the ray
// through a pixel is a linear function of the pixel's position, so the full-screen passes that draw
// the sky (skybox, tonemap_sky) evaluate that function per pixel instead of an inverse
// view-projection, a division and a normalization.

#include "shared/sky_rays.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace candela::passes {

// The rays through the pixel centres of a `width` × `height` target drawn with `viewProjection`
// (Vulkan clip space, reverse-Z) from `eye`: the direction from the eye to the pixel's point on the
// near plane, rotated into the environment's frame by `rotation` (IblParams::rotation: cos θ, sin θ
// about +Y; shared/ibl.h iblLookupDirection), scaled so that the ray through the target's centre has
// length 1. Computed in double precision: the near plane lies close to the eye, and subtracting the
// two in float loses most of the direction's digits. Precondition: the near plane's homogeneous w
// keeps one sign over the target (true of perspective and orthographic projections).
shading::SkyRays skyRays(const glm::mat4& viewProjection, const glm::vec3& eye, const glm::vec2& rotation, uint32_t width,
                         uint32_t height);

}  // namespace candela::passes
