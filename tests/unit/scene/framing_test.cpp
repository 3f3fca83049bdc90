// Framing of the orbit camera (scene/camera.h): the bounding box fitted to the image's aspect
// ratio, the field of view at the distance framing chose, the default direction, and the flags
// that print the camera.
#include "assets/builtin_scenes.h"
#include "scene/camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace candela::scene {
namespace {

scene::Aabb box(glm::vec3 size, glm::vec3 centre = glm::vec3(0.0f)) {
    scene::Aabb b;
    b.extend(centre - 0.5f * size);
    b.extend(centre + 0.5f * size);
    return b;
}

// The largest |x| and |y| of the box's corners in normalized device coordinates.
glm::vec2 ndcExtent(const scene::OrbitCamera& camera, const scene::Aabb& bounds, float aspect) {
    const scene::ViewSetup view = camera.view(aspect);
    glm::vec2 extent(0.0f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                               (i & 4) ? bounds.max.z : bounds.min.z);
        const glm::vec4 clip = view.viewProjection * glm::vec4(corner, 1.0f);
        EXPECT_GT(clip.w, 0.0f) << "a corner behind the eye";
        extent = glm::max(extent, glm::abs(glm::vec2(clip) / clip.w));
    }
    return extent;
}

TEST(Framing, AWideBoxFillsTheWidthAndATallOneTheHeight) {
    for (const float aspect : {16.0f / 9.0f, 1.0f, 0.5f}) {
        SCOPED_TRACE("aspect " + std::to_string(aspect));
        const scene::Aabb wide = box({8.0f, 1.0f, 1.0f}, {3.0f, -2.0f, 1.0f});
        const glm::vec2 w = ndcExtent(scene::OrbitCamera::framing(wide, aspect), wide, aspect);
        EXPECT_NEAR(w.x, 1.0f / 1.1f, 1e-4f);  // the margin: 1/1.1 of the half width
        EXPECT_LT(w.y, w.x);
        const scene::Aabb tall = box({1.0f, 8.0f, 1.0f});
        const glm::vec2 t = ndcExtent(scene::OrbitCamera::framing(tall, aspect), tall, aspect);
        EXPECT_NEAR(t.y, 1.0f / 1.1f, 1e-4f);
        EXPECT_LT(t.x, t.y);
    }
    // A wide box in a wide image comes out bigger than the bounding sphere framing made it (that
    // fitted a sphere of the half diagonal into the narrower field of view at 1.05): the camera is
    // 0.59 times as far (measured), the model 1.7 times as big.
    const scene::Aabb wide = box({8.0f, 1.0f, 1.0f});
    const float sphere = 0.5f * glm::length(wide.max - wide.min) / std::sin(glm::radians(22.5f)) * 1.05f;
    EXPECT_LT(scene::OrbitCamera::framing(wide, 16.0f / 9.0f).radius, 0.65f * sphere);
}

TEST(Framing, EveryCornerIsInsideFromAnyDirection) {
    const scene::Aabb bounds = box({2.0f, 3.0f, 5.0f}, {10.0f, 0.0f, -4.0f});
    for (float theta = -180.0f; theta < 180.0f; theta += 37.0f)
        for (float phi = 5.0f; phi < 180.0f; phi += 29.0f) {
            const scene::OrbitCamera c = scene::OrbitCamera::framing(bounds, 1.5f, theta, phi);
            const glm::vec2 e = ndcExtent(c, bounds, 1.5f);
            EXPECT_LE(std::max(e.x, e.y), 1.0f / 1.1f + 1e-4f) << theta << ", " << phi;
            EXPECT_NEAR(std::max(e.x, e.y), 1.0f / 1.1f, 1e-4f) << theta << ", " << phi;  // and touches
        }
}

TEST(Framing, TheFieldOfViewDoesNotMoveTheCamera) {
    const scene::Aabb bounds = box({4.0f, 1.0f, 2.0f});
    const scene::OrbitCamera standard = scene::OrbitCamera::framing(bounds, 1.5f, 0.0f, 75.0f);
    const scene::OrbitCamera narrow = scene::OrbitCamera::framing(bounds, 1.5f, 0.0f, 75.0f, 20.0f);
    EXPECT_EQ(standard.fovYDegrees, scene::kFramingFovYDegrees);
    EXPECT_EQ(narrow.fovYDegrees, 20.0f);
    EXPECT_EQ(narrow.radius, standard.radius);
    EXPECT_EQ(narrow.target, standard.target);
    // The image scales by tan(22.5°) / tan(10°): the model is that much bigger.
    const glm::vec2 a = ndcExtent(standard, bounds, 1.5f), b = ndcExtent(narrow, bounds, 1.5f);
    EXPECT_NEAR(b.x / a.x, std::tan(glm::radians(22.5f)) / std::tan(glm::radians(10.0f)), 1e-3f);
}

TEST(Framing, DefaultDirection) {
    scene::Scene s;
    s.bounds = box({2.0f, 1.0f, 2.0f});
    EXPECT_EQ(scene::defaultOrbitAngles(s), glm::vec2(0.0f, 75.0f));  // the front, 15° above the horizon
    s.bounds = box({2.0f, 0.0f, 2.0f});  // a plane in the ground: seen from above, not edge-on
    EXPECT_EQ(scene::defaultOrbitAngles(s), glm::vec2(0.0f, 75.0f));
    s.bounds = box({0.0f, 2.0f, 2.0f});  // a plane facing ±X: from +X
    EXPECT_EQ(scene::defaultOrbitAngles(s), glm::vec2(90.0f, 75.0f));
    s.bounds = {};
    EXPECT_EQ(scene::defaultOrbitAngles(s), glm::vec2(0.0f, 75.0f));
    // The sphere grid, a chart, head-on.
    EXPECT_EQ(scene::defaultOrbitAngles(assets::makeSphereGrid(2)), glm::vec2(0.0f, 90.0f));
}

TEST(Framing, TheFlagsReadBackAsTheSameCamera) {
    const scene::OrbitCamera c = scene::OrbitCamera::framing(box({1.3f, 0.7f, 2.9f}, {0.1f, 1.0f / 3.0f, -7.25f}), 1.7f, 30.0f,
                                                             75.0f, 33.3f);
    const std::string flags = scene::orbitCameraFlags(c);
    EXPECT_EQ(flags.rfind("--camera-orbit 30,75,", 0), 0u) << flags;
    // Parse it back as the command line does (strtof of each comma-separated number).
    std::istringstream in(flags);
    std::string orbitFlag, orbit, targetFlag, target, fovFlag, fov;
    in >> orbitFlag >> orbit >> targetFlag >> target >> fovFlag >> fov;
    EXPECT_EQ(targetFlag, "--target");
    EXPECT_EQ(fovFlag, "--fov");
    const auto numbers = [](std::string text) {
        std::replace(text.begin(), text.end(), ',', ' ');
        std::istringstream s(text);
        std::vector<float> out;
        for (std::string n; s >> n;) out.push_back(std::strtof(n.c_str(), nullptr));
        return out;
    };
    EXPECT_EQ(numbers(orbit), (std::vector<float>{c.thetaDegrees, c.phiDegrees, c.radius}));
    EXPECT_EQ(numbers(target), (std::vector<float>{c.target.x, c.target.y, c.target.z}));
    EXPECT_EQ(numbers(fov), std::vector<float>{c.fovYDegrees});
}

}  // namespace
}  // namespace candela::scene
