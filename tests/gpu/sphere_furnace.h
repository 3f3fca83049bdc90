#pragma once
// Unit spheres in a uniform environment, as the white-furnace tests render them (the IBL numerical
// tests, the material layers' furnace): the scene, the camera, ray casting the analytic spheres
// to find which pixel sees which sphere at which N·V, the interior of the coverage, and the
// "[ measured ]" lines the tests print.
#include "gpu_test.h"

#include "assets/builtin_scenes.h"
#include "assets/environment.h"
#include "ibl/ibl_settings.h"
#include "render/renderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace candela::test {

// Prints a measured value (quotable from the log) and keeps it in the test's XML properties.
inline void measured(const std::string& key, double value) {
    std::printf("[ measured ] %s = %.6g\n", key.c_str(), value);
    std::fflush(stdout);
    std::ostringstream text;
    text.precision(6);
    text << value;
    ::testing::Test::RecordProperty(key, text.str());
}

// ---- Environments and scenes --------------------------------------------------------------------

inline assets::Environment constantEnvironment(uint32_t width, uint32_t height, glm::vec3 c) {
    assets::Environment env;
    env.source = "constant";
    env.width = width;
    env.height = height;
    env.rgb.resize(env.texelCount() * 3);
    for (size_t i = 0; i < env.texelCount(); ++i) {
        env.rgb[3 * i] = c.r;
        env.rgb[3 * i + 1] = c.g;
        env.rgb[3 * i + 2] = c.b;
    }
    return env;
}

struct Sphere {
    glm::vec3 centre;
    float radius;
    float metallic;
    float roughness;
};

// The spheres as draws of one UV sphere mesh (white base colour, one material each), no lights.
inline scene::Scene sphereScene(const std::vector<Sphere>& spheres, uint32_t sectors, uint32_t stacks) {
    scene::Scene scene;
    scene.source = "built-in: IBL test spheres";
    const auto [firstIndex, indexCount] = assets::appendUvSphere(scene, 1.0f, sectors, stacks);
    for (const Sphere& s : spheres) {
        scene::Material material;
        material.baseColorFactor = glm::vec4(1.0f);
        material.metallicFactor = s.metallic;
        material.roughnessFactor = s.roughness;
        scene.materials.push_back(material);
        scene::Draw draw;
        draw.firstIndex = firstIndex;
        draw.indexCount = indexCount;
        draw.material = uint32_t(scene.materials.size() - 1);
        draw.world = glm::scale(glm::translate(glm::mat4(1.0f), s.centre), glm::vec3(s.radius));
        draw.bounds.extend(s.centre - glm::vec3(s.radius));
        draw.bounds.extend(s.centre + glm::vec3(s.radius));
        scene.bounds.extend(draw.bounds);
        scene.draws.push_back(draw);
    }
    return scene;
}

// 5 roughness values (columns) × metallic 0 (bottom row) and 1 (top row), unit spheres 2.5 m
// apart in the XY plane, facing +Z.
inline constexpr std::array<float, 5> kRoughness = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
inline std::vector<Sphere> furnaceSpheres() {
    std::vector<Sphere> spheres;
    for (int m = 0; m < 2; ++m)
        for (size_t r = 0; r < kRoughness.size(); ++r)
            spheres.push_back({glm::vec3((float(r) - 2.0f) * 2.5f, m == 0 ? -1.25f : 1.25f, 0.0f), 1.0f, float(m),
                               kRoughness[r]});
    return spheres;
}

// On +Z, 10 m from the origin: the 12.5 m × 5 m grid fills most of a 16:9 frame at 45° (unit
// spheres about 23 px in radius at 320×180).
inline CameraSettings furnaceCamera() {
    CameraSettings camera;
    camera.orbit = glm::vec3(0.0f, 90.0f, 10.0f);
    camera.target = glm::vec3(0.0f);
    return camera;
}

// ---- Ray casting the analytic spheres -------------------------------------------------------------

struct Hit {
    int sphere = -1;   // index into the sphere list; −1: the ray misses them all
    double mu = 0.0;   // N·V at the hit
};

inline Hit castRay(const scene::ViewSetup& view, uint32_t width, uint32_t height, uint32_t px, uint32_t py,
            const std::vector<Sphere>& spheres) {
    // Pixel centre → NDC (Vulkan: y down, row 0 at NDC y = −1); any depth in (0, 1] lies on the
    // ray (reverse-Z, infinite far plane).
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(view.viewProjection));
    const glm::dvec4 ndc((px + 0.5) / width * 2.0 - 1.0, (py + 0.5) / height * 2.0 - 1.0, 0.5, 1.0);
    const glm::dvec4 p = inverse * ndc;
    const glm::dvec3 eye(view.eye);
    const glm::dvec3 dir = glm::normalize(glm::dvec3(p) / p.w - eye);
    Hit hit;
    double nearest = 1e300;
    for (size_t i = 0; i < spheres.size(); ++i) {
        const glm::dvec3 oc = eye - glm::dvec3(spheres[i].centre);
        const double b = glm::dot(oc, dir);
        const double c = glm::dot(oc, oc) - double(spheres[i].radius) * spheres[i].radius;
        const double disc = b * b - c;
        if (disc < 0.0) continue;
        const double t = -b - std::sqrt(disc);
        if (t <= 0.0 || t >= nearest) continue;
        nearest = t;
        const glm::dvec3 n = glm::normalize(eye + t * dir - glm::dvec3(spheres[i].centre));
        hit = {int(i), std::clamp(glm::dot(n, -dir), 0.0, 1.0)};
    }
    return hit;
}

// ---- Frames ------------------------------------------------------------------------------------

inline glm::vec4 pixel(const CapturedFrame& frame, uint32_t x, uint32_t y) {
    const size_t i = (size_t(y) * frame.width + x) * 4;
    return {frame.rgba32f[i], frame.rgba32f[i + 1], frame.rgba32f[i + 2], frame.rgba32f[i + 3]};
}

// Covered (alpha == 1) and every pixel within `radius` (Chebyshev) covered too: the coverage mask
// eroded, which leaves out the silhouette band.
inline std::vector<bool> interiorMask(const CapturedFrame& frame, int radius) {
    std::vector<bool> mask(size_t(frame.width) * frame.height, false);
    for (int y = radius; y < int(frame.height) - radius; ++y)
        for (int x = radius; x < int(frame.width) - radius; ++x) {
            bool inside = true;
            for (int dy = -radius; dy <= radius && inside; ++dy)
                for (int dx = -radius; dx <= radius && inside; ++dx)
                    inside = pixel(frame, uint32_t(x + dx), uint32_t(y + dy)).a == 1.0f;
            mask[size_t(y) * frame.width + size_t(x)] = inside;
        }
    return mask;
}

// The first non-finite value of a float frame (or alpha outside [0, 1]), or "".
inline std::string frameProblem(const CapturedFrame& frame) {
    for (size_t i = 0; i < frame.rgba32f.size(); ++i) {
        const float v = frame.rgba32f[i];
        if (!std::isfinite(v) || v < 0.0f || (i % 4 == 3 && v > 1.0f)) {
            std::ostringstream out;
            out << "pixel (" << (i / 4) % frame.width << ", " << (i / 4) / frame.width << ") channel " << i % 4
                << " = " << v;
            return out.str();
        }
    }
    return {};
}

// A small quality: cube 64, 6 levels, default irradiance (the cube) and LUT.
inline ibl::IblQuality smallQuality() {
    ibl::IblQuality q;
    q.cubeSize = 64;
    return q;
}

// The same with irradiance as SH9, projected from the cube's 32² mip.
inline ibl::IblQuality smallSh9Quality() {
    ibl::IblQuality q = smallQuality();
    q.irradiance = ibl::IrradianceMode::Sh9;
    return q;
}

// The settings of a furnace frame of `scene` in `env`: 320×180 float output, the furnace camera,
// no punctual lights, the small IBL quality, no skybox. `scene` and `env` must outlive the settings.
inline RenderSettings furnaceSettings(const scene::Scene& scene, const assets::Environment& env) {
    RenderSettings settings{.width = 320, .height = 180, .floatOutput = true, .scene = &scene,
                            .camera = furnaceCamera(), .defaultLights = false, .environment = &env,
                            .iblQuality = smallQuality()};
    settings.ibl.skybox = false;
    return settings;
}

// One interior pixel of a furnace frame and the sphere it sees (−1: its ray misses them all).
struct FurnacePixel {
    uint32_t x, y;
    int sphere;
    glm::vec4 value;
};

// The interior pixels of `frame` (covered, and no uncovered pixel within 2 px — in `coverage`, when
// given: a frame of the same geometry whose alpha is its coverage, for frames drawn over a skybox),
// rendered of `scene` with `settings`, each with the sphere of `spheres` its ray hits.
inline std::vector<FurnacePixel> furnacePixels(const CapturedFrame& frame, const scene::Scene& scene,
                                               const RenderSettings& settings, const std::vector<Sphere>& spheres,
                                               const CapturedFrame* coverage = nullptr) {
    const scene::ViewSetup view = Renderer::resolveView(scene, settings.camera, float(frame.width) / float(frame.height));
    const std::vector<bool> interior = interiorMask(coverage ? *coverage : frame, 2);
    std::vector<FurnacePixel> out;
    for (uint32_t y = 0; y < frame.height; ++y)
        for (uint32_t x = 0; x < frame.width; ++x)
            if (interior[size_t(y) * frame.width + x])
                out.push_back({x, y, castRay(view, frame.width, frame.height, x, y, spheres).sphere, pixel(frame, x, y)});
    return out;
}

// The white-furnace check of `pixels` (interior pixels of a frame of `sphereCount` spheres that
// should all reflect exactly 1): every pixel sees a sphere, every sphere has over 1000 of them; over
// RGB, max |x − 1| within 0.02 and max x − 1 within one RGBA16F step (1/1024), printed as
// "[ measured ] <key>MaxAbsError" and "<key>MaxAboveOne".
inline void expectWhiteFurnace(const std::vector<FurnacePixel>& pixels, size_t sphereCount, const std::string& key) {
    std::vector<size_t> count(sphereCount, 0);
    double worst = 0.0, highest = -1.0;
    for (const FurnacePixel& fp : pixels) {
        ASSERT_GE(fp.sphere, 0) << "interior pixel (" << fp.x << ", " << fp.y << ") misses every sphere";
        ++count[size_t(fp.sphere)];
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::abs(double(fp.value[c]) - 1.0));
            highest = std::max(highest, double(fp.value[c]) - 1.0);
        }
    }
    for (size_t i = 0; i < sphereCount; ++i) EXPECT_GT(count[i], 1000u) << "sphere " << i;
    measured(key + "MaxAbsError", worst);
    measured(key + "MaxAboveOne", highest);
    EXPECT_LE(worst, 0.02);
    EXPECT_LE(highest, 1.0 / 1024.0);
}

// Per channel, the lowest and the highest value of a sphere's interior pixels (+inf and −inf for
// a sphere without pixels, so a check on it fails).
struct ChannelRange {
    glm::vec3 lowest{INFINITY};
    glm::vec3 highest{-INFINITY};
};

inline std::vector<ChannelRange> channelRange(const std::vector<FurnacePixel>& pixels, size_t sphereCount) {
    std::vector<ChannelRange> range(sphereCount);
    for (const FurnacePixel& fp : pixels) {
        if (fp.sphere < 0) continue;
        ChannelRange& r = range[size_t(fp.sphere)];
        r.lowest = glm::min(r.lowest, glm::vec3(fp.value));
        r.highest = glm::max(r.highest, glm::vec3(fp.value));
    }
    return range;
}

inline float minComponent(glm::vec3 v) { return std::min({v.x, v.y, v.z}); }
inline float maxComponent(glm::vec3 v) { return std::max({v.x, v.y, v.z}); }

}  // namespace candela::test
