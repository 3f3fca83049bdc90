#include "assets/procedural_sky.h"

#include "core/errors.h"
#include "shared/environment.h"

#include <algorithm>
#include <cmath>

namespace candela::assets {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kSunSubsamples = 32;  // per texel side, for the disc's coverage (see procedural_sky.h)

float radians(float degrees) { return degrees * (kPi / 180.0f); }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Sky, halo and ground (no sun disc) seen along unit direction `d`.
glm::vec3 skyRadiance(const SkyParams& params, const glm::vec3& sun, const glm::vec3& d) {
    if (d.y < 0.0f) return params.groundRadiance;
    // sqrt: the pale horizon band thins quickly with elevation (≈ 30% zenith colour at 5°).
    const float t = std::sqrt(d.y);
    const glm::vec3 sky = glm::mix(params.horizonRadiance, params.zenithRadiance, t);
    const float cosGamma = std::max(glm::dot(d, sun), 0.0f);
    return sky + params.haloRadiance * std::pow(cosGamma, params.haloExponent);
}

// The fraction of texel (x, y)'s solid angle inside the sun disc and above the horizon, by
// kSunSubsamples² sub-texel directions weighted by sin θ (the equirectangular solid-angle density).
float sunCoverage(uint32_t x, uint32_t y, uint32_t width, uint32_t height, const glm::vec3& sun, float cosRadius) {
    double inside = 0.0, total = 0.0;
    for (int j = 0; j < kSunSubsamples; ++j) {
        const float v = (float(y) + (float(j) + 0.5f) / kSunSubsamples) / float(height);
        const double weight = std::sin(double(v) * kPi);
        for (int i = 0; i < kSunSubsamples; ++i) {
            const float u = (float(x) + (float(i) + 0.5f) / kSunSubsamples) / float(width);
            const glm::vec3 d = shading::equirectUvToDirection(glm::vec2(u, v), 0.0f);
            total += weight;
            if (d.y >= 0.0f && glm::dot(d, sun) >= cosRadius) inside += weight;
        }
    }
    return total > 0.0 ? float(inside / total) : 0.0f;
}

}  // namespace

glm::vec3 sunDirection(const SkyParams& params) {
    const float elevation = radians(params.sunElevationDegrees);
    const float azimuth = radians(params.sunAzimuthDegrees);
    return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation), std::cos(elevation) * std::sin(azimuth)};
}

Environment makeProceduralSky(const SkyParams& params) {
    const std::string source = "procedural sky";
    checkEnvironmentSize(source, params.width, params.height, EnvironmentLoadOptions{});
    if (!std::isfinite(params.sunElevationDegrees) || !std::isfinite(params.sunAzimuthDegrees) ||
        !std::isfinite(params.sunAngularRadiusDegrees) || !std::isfinite(params.haloExponent) ||
        !finite(params.sunRadiance) || !finite(params.zenithRadiance) || !finite(params.horizonRadiance) ||
        !finite(params.groundRadiance) || !finite(params.haloRadiance))
        throw UserError(source + ": parameters must be finite");
    if (params.haloExponent < 0.0f) throw UserError(source + ": the halo exponent must be ≥ 0");

    Environment env;
    env.source = source;
    env.width = params.width;
    env.height = params.height;
    env.rgb.resize(env.texelCount() * 3);

    const glm::vec3 sun = sunDirection(params);
    const float radius = std::clamp(radians(params.sunAngularRadiusDegrees), 0.0f, kPi);
    const bool hasSun = radius > 0.0f;
    const float cosRadius = std::cos(radius);
    // Texels whose centre lies within this angle of the sun may overlap the disc: the disc's radius
    // plus a texel's half-diagonal at the equator (the widest texels), generously rounded up.
    const float reach = radius + kPi / float(params.height) + 2.0f * kPi / float(params.width);
    const float cosReach = std::cos(std::min(reach, kPi));

    for (uint32_t y = 0; y < params.height; ++y) {
        for (uint32_t x = 0; x < params.width; ++x) {
            const glm::vec2 uv((float(x) + 0.5f) / float(params.width), (float(y) + 0.5f) / float(params.height));
            const glm::vec3 d = shading::equirectUvToDirection(uv, 0.0f);
            glm::vec3 radiance = skyRadiance(params, sun, d);
            if (hasSun && glm::dot(d, sun) >= cosReach) {
                const float f = sunCoverage(x, y, params.width, params.height, sun, cosRadius);
                radiance = radiance * (1.0f - f) + params.sunRadiance * f;
            }
            float* texel = env.texel(x, y);
            texel[0] = radiance.x, texel[1] = radiance.y, texel[2] = radiance.z;
        }
    }
    // Negative colours from the parameters become 0 (with a warning), as for loaded maps.
    sanitizeEnvironment(env);
    return env;
}

}  // namespace candela::assets
