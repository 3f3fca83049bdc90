// The equirectangular orientation convention (shaders/shared/environment.h) and the procedural sky.
#include "environment_test_util.h"

#include "assets/procedural_sky.h"
#include "shared/environment.h"

#include <glm/gtc/matrix_transform.hpp>

#include <iostream>

namespace candela::assets::test {
namespace {

using shading::directionToEquirectUv;
using shading::equirectUvToDirection;

constexpr float kPi = 3.14159265358979f;
constexpr float kEps = 1e-6f;

// A deterministic spread of unit directions (a Fibonacci sphere), poles excluded.
std::vector<glm::vec3> directions(int count) {
    std::vector<glm::vec3> out;
    for (int i = 0; i < count; ++i) {
        const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(count);
        const float r = std::sqrt(1.0f - y * y), phi = float(i) * 2.39996323f;
        out.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
    }
    return out;
}

TEST(EnvironmentOrientation, AxesAtRotationZero) {
    EXPECT_NEAR(directionToEquirectUv({1, 0, 0}, 0).x, 0.5f, kEps);  // the image centre faces +X
    EXPECT_NEAR(directionToEquirectUv({1, 0, 0}, 0).y, 0.5f, kEps);
    EXPECT_NEAR(directionToEquirectUv({0, 1, 0}, 0).y, 0.0f, kEps);  // +Y: top row
    EXPECT_NEAR(directionToEquirectUv({0, -1, 0}, 0).y, 1.0f, kEps); // −Y: bottom row
    EXPECT_NEAR(directionToEquirectUv({0, 0, 1}, 0).x, 0.75f, kEps);
    EXPECT_NEAR(directionToEquirectUv({0, 0, -1}, 0).x, 0.25f, kEps);
    const float minusX = directionToEquirectUv({-1, 0, 0}, 0).x;     // the seam: u = 0 ≡ 1
    EXPECT_TRUE(minusX < kEps || minusX > 1.0f - kEps) << minusX;
    // Poles are finite (GLSL's atan(0, 0) is undefined, so it is never evaluated).
    EXPECT_TRUE(std::isfinite(directionToEquirectUv({0, 1, 0}, 1.0f).x));
    EXPECT_TRUE(std::isfinite(directionToEquirectUv({0, -1, 0}, 1.0f).x));
}

TEST(EnvironmentOrientation, PositiveRotationTurnsFromXTowardsZ) {
    // Documented: at +90° the image centre faces +Z and +X sees u = 0.25 (what −Z saw at 0°).
    const float quarter = kPi / 2;
    EXPECT_NEAR(directionToEquirectUv({1, 0, 0}, quarter).x, 0.25f, kEps);
    EXPECT_NEAR(directionToEquirectUv({0, 0, 1}, quarter).x, 0.5f, kEps);
    EXPECT_NEAR(directionToEquirectUv({1, 0, 0}, -quarter).x, 0.75f, kEps);
    glm::vec3 centre = equirectUvToDirection({0.5f, 0.5f}, quarter);
    EXPECT_NEAR(centre.z, 1.0f, kEps);
    // Rotation leaves v alone.
    EXPECT_NEAR(directionToEquirectUv(glm::normalize(glm::vec3(1, 1, 0)), 1.234f).y, 0.25f, kEps);
}

TEST(EnvironmentOrientation, RotationMatchesTheSampleViewersMatrix) {
    // The glTF Sample Viewer samples its rotation-0 map along R·d, R = rotateY(θ) (gl-matrix).
    for (float theta : {0.3f, 1.0f, kPi / 2, 2.5f, -1.7f}) {
        const glm::mat3 r(glm::rotate(glm::mat4(1.0f), theta, glm::vec3(0, 1, 0)));
        for (const glm::vec3& d : directions(64)) {
            const glm::vec2 a = directionToEquirectUv(d, theta), b = directionToEquirectUv(r * d, 0.0f);
            const float du = std::abs(a.x - b.x);
            EXPECT_LT(std::min(du, 1.0f - du), 1e-5f) << theta;
            EXPECT_NEAR(a.y, b.y, 1e-5f);
        }
    }
}

TEST(EnvironmentOrientation, InverseRoundTrips) {
    for (float rotation : {0.0f, 0.7f, -2.0f, 10.0f}) {
        for (const glm::vec3& d : directions(500)) {
            const glm::vec2 uv = directionToEquirectUv(d, rotation);
            ASSERT_TRUE(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f);
            const glm::vec3 back = equirectUvToDirection(uv, rotation);
            EXPECT_LT(glm::length(back - d), 2e-5f) << rotation << " " << d.x << "," << d.y << "," << d.z;
        }
        for (float u = 0.01f; u < 1.0f; u += 0.0737f)
            for (float v = 0.02f; v < 1.0f; v += 0.0913f) {
                const glm::vec2 uv = directionToEquirectUv(equirectUvToDirection({u, v}, rotation), rotation);
                EXPECT_NEAR(uv.x, u, 2e-5f);
                EXPECT_NEAR(uv.y, v, 2e-5f);
            }
    }
}

// ---- Procedural sky --------------------------------------------------------------------------------

float luminance(const float* t) { return 0.2126f * t[0] + 0.7152f * t[1] + 0.0722f * t[2]; }

struct Brightest {
    uint32_t x = 0, y = 0;
    float value = -1.0f;
};
Brightest brightest(const Environment& env) {
    Brightest b;
    for (uint32_t y = 0; y < env.height; ++y)
        for (uint32_t x = 0; x < env.width; ++x)
            if (luminance(env.texel(x, y)) > b.value) b = {x, y, luminance(env.texel(x, y))};
    return b;
}

glm::vec3 texelDirection(const Environment& env, uint32_t x, uint32_t y) {
    return equirectUvToDirection({(x + 0.5f) / env.width, (y + 0.5f) / env.height}, 0.0f);
}

// ∫ L cos⁺ dω over the map for a surface facing `normal` (Riemann sum over texels).
glm::dvec3 irradiance(const Environment& env, const glm::vec3& normal) {
    glm::dvec3 sum(0.0);
    const double texelArea = (2.0 * kPi / env.width) * (kPi / env.height);
    for (uint32_t y = 0; y < env.height; ++y)
        for (uint32_t x = 0; x < env.width; ++x) {
            const glm::vec3 d = texelDirection(env, x, y);
            const double cosine = std::max(0.0f, glm::dot(d, normal));
            const double solidAngle = texelArea * std::sin((y + 0.5) / env.height * kPi);
            const float* t = env.texel(x, y);
            sum += glm::dvec3(t[0], t[1], t[2]) * cosine * solidAngle;
        }
    return sum;
}

double lum(const glm::dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

TEST(SkyProcedural, FiniteDeterministicDefaultSize) {
    const Environment a = makeProceduralSky();
    EXPECT_EQ(a.width, 512u);
    EXPECT_EQ(a.height, 256u);
    EXPECT_EQ(a.source, "procedural sky");
    EXPECT_EQ(a.replacedTexels, 0u);
    EXPECT_TRUE(a.report.warnings.empty());
    for (float v : a.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
    const Environment b = makeProceduralSky();
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(contentHash(a), contentHash(b));
    SkyParams other;
    other.sunAzimuthDegrees = 100.0f;
    EXPECT_NE(contentHash(a), contentHash(makeProceduralSky(other)));
}

TEST(SkyProcedural, SunIsTheBrightestTexelAtTheRequestedDirection) {
    struct Case { float elevation, azimuth; };
    for (const Case& c : {Case{35, 45}, Case{10, 90}, Case{60, -120}, Case{5, 170}, Case{89, 0}}) {
        SCOPED_TRACE(std::to_string(c.elevation) + "/" + std::to_string(c.azimuth));
        SkyParams params;
        params.sunElevationDegrees = c.elevation;
        params.sunAzimuthDegrees = c.azimuth;
        const Environment sky = makeProceduralSky(params);
        const Brightest b = brightest(sky);
        // Within about a texel (0.7°) plus the disc's radius of the requested direction.
        const float angle = std::acos(std::min(1.0f, glm::dot(texelDirection(sky, b.x, b.y), sunDirection(params))));
        EXPECT_LT(angle * 180.0f / kPi, 1.2f);
        // And at the documented place in the image: u = 0.5 + azimuth/360°, v = (90° − elevation)/180°.
        const glm::vec2 uv = directionToEquirectUv(sunDirection(params), 0.0f);
        EXPECT_NEAR(uv.x, std::fmod(0.5f + c.azimuth / 360.0f + 1.0f, 1.0f), 1e-5f);
        EXPECT_NEAR(uv.y, (90.0f - c.elevation) / 180.0f, 1e-5f);
        EXPECT_GT(b.value, 1000.0f * luminance(sky.texel(0, sky.height / 4)));
    }
}

TEST(SkyProcedural, GroundIsDarkerThanTheSky) {
    const Environment sky = makeProceduralSky();
    float darkestSky = 1e30f, brightestGround = 0.0f;
    for (uint32_t y = 0; y < sky.height; ++y)
        for (uint32_t x = 0; x < sky.width; ++x) {
            const float l = luminance(sky.texel(x, y));
            if (y < sky.height / 2) darkestSky = std::min(darkestSky, l);
            else brightestGround = std::max(brightestGround, l);
        }
    EXPECT_LT(brightestGround, darkestSky);
    // Zenith darker (bluer) than the horizon: a clear sky's gradient.
    EXPECT_LT(luminance(sky.texel(10, 0)), luminance(sky.texel(10, sky.height / 2 - 1)));
    EXPECT_GT(sky.texel(10, 0)[2], sky.texel(10, 0)[0]);
}

TEST(SkyProcedural, SunIrradianceIsResolutionIndependent) {
    // The disc is drawn by exact-area coverage, so its irradiance is L_sun · Ω_disc at any size,
    // even when the disc is smaller than a texel. Tolerance 2% (the sub-texel sampling).
    SkyParams params;
    SkyParams noSun = params;
    noSun.sunAngularRadiusDegrees = 0.0f;
    const float r = params.sunAngularRadiusDegrees * kPi / 180.0f;
    const double expected = lum(glm::dvec3(params.sunRadiance)) * 2.0 * kPi * (1.0 - std::cos(r));
    for (uint32_t width : {128u, 512u, 1024u}) {
        params.width = noSun.width = width;
        params.height = noSun.height = width / 2;
        const glm::vec3 sun = sunDirection(params);
        const double sunOnly = lum(irradiance(makeProceduralSky(params), sun) - irradiance(makeProceduralSky(noSun), sun));
        EXPECT_NEAR(sunOnly / expected, 1.0, 0.02) << width;
    }
    // The figures quoted in procedural_sky.h (default parameters).
    const Environment sky = makeProceduralSky();
    const Environment skyOnly = makeProceduralSky(noSun);
    const double sunNormal = lum(irradiance(sky, sunDirection(SkyParams{})) - irradiance(skyOnly, sunDirection(SkyParams{})));
    const double skyHorizontal = lum(irradiance(skyOnly, {0, 1, 0}));
    const double totalHorizontal = lum(irradiance(sky, {0, 1, 0}));
    std::cout << "  sun irradiance (normal) " << sunNormal << ", sky on horizontal " << skyHorizontal
              << ", total on horizontal " << totalHorizontal << ", white floor radiance " << totalHorizontal / kPi << "\n";
    EXPECT_NEAR(sunNormal, 6.8, 0.1);
    EXPECT_NEAR(skyHorizontal, 2.24, 0.05);
    EXPECT_NEAR(totalHorizontal, 6.14, 0.1);
}

TEST(SkyProcedural, SunBelowTheHorizonIsHidden) {
    SkyParams params;
    params.sunElevationDegrees = -5.0f;
    const Environment sky = makeProceduralSky(params);
    EXPECT_LT(brightest(sky).value, 10.0f);
}

TEST(SkyProcedural, TinyAndOddSizes) {
    for (const auto& [w, h] : {std::pair{1u, 1u}, std::pair{2u, 1u}, std::pair{7u, 3u}, std::pair{1000u, 333u}}) {
        SkyParams params;
        params.width = w;
        params.height = h;
        const Environment sky = makeProceduralSky(params);
        ASSERT_EQ(sky.rgb.size(), size_t(w) * h * 3);
        for (float v : sky.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
    }
}

TEST(SkyProcedural, BadParametersAreUserErrors) {
    auto message = [](const SkyParams& p) -> std::string {
        try {
            makeProceduralSky(p);
        } catch (const UserError& e) {
            return e.what();
        }
        return {};
    };
    SkyParams p;
    p.width = 0;
    EXPECT_EQ(message(p), "procedural sky: zero image size 0x256");
    p = {};
    p.width = 20000;
    EXPECT_EQ(message(p), "procedural sky: image size 20000x256 exceeds the limit 16384x8192");
    p = {};
    p.sunRadiance.x = std::numeric_limits<float>::infinity();
    EXPECT_EQ(message(p), "procedural sky: parameters must be finite");
}

}  // namespace
}  // namespace candela::assets::test
