#pragma once
// The built-in procedural sky: the environment used when the scene asks for one and no file is
// given. A clear-sky gradient (horizon → zenith), a soft circumsolar halo, a uniform ground below
// the horizon and a sun disc, as an equirectangular Environment in the convention of
// shaders/shared/environment.h. Deterministic: the same parameters give the same texels.
//
// Units are relative radiance (the renderer's scene-referred units; `--env-intensity` scales them).
// At the defaults (measured by tests/unit/assets/sky_test.cpp, luminance): the sun disc's irradiance at
// normal incidence is 6.8, 3.9 on a horizontal surface (sun at 35°); the sky's (with the halo) on a
// horizontal surface is 2.24; so a white Lambertian floor reflects a radiance of 6.14/π ≈ 1.96 — a
// slightly hazy clear afternoon (sun ≈ 63% of the light on the floor, sky ≈ 37%), with sky radiance
// 0.5–1.3 (up to ≈ 3 in the halo) against ≈ 28,300 for the sun disc.
//
// The sun disc is anti-aliased by area coverage: each texel it touches holds sun·f + sky·(1 − f),
// f being the fraction of the texel's solid angle inside the disc and above the horizon (estimated
// with 32 × 32 sin θ-weighted sub-samples), so its irradiance is right (within 2%) at any resolution,
// even when the disc is smaller than a texel.

#include "assets/environment.h"

#include <glm/glm.hpp>

namespace candela::assets {

struct SkyParams {
    uint32_t width = 512;   // equirectangular size; 1 ≤ width ≤ 16384, 1 ≤ height ≤ 8192
    uint32_t height = 256;
    // Sun direction: elevation above the horizon, azimuth from +X towards +Z (so at environment
    // rotation 0 the sun sits at u = 0.5 + azimuth/360°). Negative elevations hide it below the ground.
    float sunElevationDegrees = 35.0f;
    float sunAzimuthDegrees = 45.0f;
    // Angular radius of the disc: about twice the real sun's 0.27°, so it spans a couple of texels
    // at the default size. 0 removes the sun.
    float sunAngularRadiusDegrees = 0.5f;
    glm::vec3 sunRadiance{30000.0f, 28200.0f, 25500.0f};  // warm white, luminance ≈ 28,300
    glm::vec3 zenithRadiance{0.30f, 0.55f, 1.20f};         // deep blue overhead, luminance ≈ 0.54
    glm::vec3 horizonRadiance{1.10f, 1.25f, 1.45f};        // pale, brighter near the horizon (≈ 1.23)
    glm::vec3 groundRadiance{0.40f, 0.36f, 0.30f};         // ~20% albedo ground lit by sun and sky (≈ 0.36)
    // Circumsolar halo added to the sky: haloRadiance · max(cos γ, 0)^haloExponent, γ the angle
    // to the sun (half strength ≈ 8° from it at exponent 64).
    glm::vec3 haloRadiance{2.0f, 1.8f, 1.5f};
    float haloExponent = 64.0f;
};

// The unit direction towards the sun's centre (world space at environment rotation 0).
glm::vec3 sunDirection(const SkyParams& params);

// Builds the sky (source "procedural sky"). Throws UserError "procedural sky: ..." for a size of 0
// or beyond 16384 × 8192, or non-finite parameters. All texels are finite and ≥ 0.
Environment makeProceduralSky(const SkyParams& params = {});

}  // namespace candela::assets
