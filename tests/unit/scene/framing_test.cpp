// Framing of the orbit camera (scene/framing.h): the target at the centre of the points' box, the
// distance R / sin 15°, the field of view that leaves 10% of the image around the projected
// silhouette (touching it on the limiting side), a given field of view at the same distance,
// several directions, degenerate inputs, the default direction and the flags that print the camera.
#include "assets/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/framing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace candela::scene {
namespace {

// The eight corners of a box of `size` about `centre` (framing fits points: here a box's corners).
std::vector<glm::vec3> corners(glm::vec3 size, glm::vec3 centre = glm::vec3(0.0f)) {
    std::vector<glm::vec3> out;
    for (int i = 0; i < 8; ++i)
        out.push_back(centre + 0.5f * size * glm::vec3((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1));
    return out;
}

// The largest |x| and |y| of the points in normalized device coordinates.
glm::vec2 ndcExtent(const OrbitCamera& camera, const std::vector<glm::vec3>& points, float aspect) {
    const ViewSetup view = camera.view(aspect);
    glm::vec2 extent(0.0f);
    for (const glm::vec3& p : points) {
        const glm::vec4 clip = view.viewProjection * glm::vec4(p, 1.0f);
        EXPECT_GT(clip.w, 0.0f) << "a point behind the eye";
        extent = glm::max(extent, glm::abs(glm::vec2(clip) / clip.w));
    }
    return extent;
}

OrbitCamera framed(const std::vector<glm::vec3>& points, float aspect, glm::vec2 direction = {0.0f, kDefaultOrbitPolarDegrees},
                   std::optional<float> fov = std::nullopt) {
    return frame(pointsOf(points), {.aspect = aspect, .directions = {direction}, .fovYDegrees = fov});
}

TEST(Framing, TheSilhouetteSpansEightyPercentOfTheLimitingSide) {
    for (const float aspect : {16.0f / 9.0f, 1.0f, 0.5f}) {
        SCOPED_TRACE("aspect " + std::to_string(aspect));
        const std::vector<glm::vec3> wide = corners({8.0f, 1.0f, 1.0f}, {3.0f, -2.0f, 1.0f});
        const glm::vec2 w = ndcExtent(framed(wide, aspect), wide, aspect);
        EXPECT_NEAR(w.x, kSilhouetteSpan, 1e-4f);  // a wide model fills the width
        EXPECT_LT(w.y, w.x);
        const std::vector<glm::vec3> tall = corners({1.0f, 8.0f, 1.0f});
        const glm::vec2 t = ndcExtent(framed(tall, aspect), tall, aspect);
        EXPECT_NEAR(t.y, kSilhouetteSpan, 1e-4f);  // a tall one the height
        EXPECT_LT(t.x, t.y);
    }
}

TEST(Framing, TargetAndDistanceComeFromTheBoundingSphereAboutTheBoxCentre) {
    // Points whose box centre (1, 0, 0) is not their mean; the farthest is 3 from it.
    const std::vector<glm::vec3> points{{-2, 0, 0}, {4, 0, 0}, {1, 0.5f, 0}, {1, 0, -0.25f}, {1, -0.5f, 0.25f}, {3.9f, 0.1f, 0}};
    const OrbitCamera c = framed(points, 1.0f);
    EXPECT_EQ(c.target, glm::vec3(1, 0, 0));
    EXPECT_NEAR(c.radius, 3.0f / std::sin(glm::radians(15.0f)), 1e-4f);
    EXPECT_NEAR(c.znear, c.radius * 1e-3f, 1e-7f);
}

TEST(Framing, EveryPointKeepsTheMarginFromAnyDirection) {
    const std::vector<glm::vec3> points = corners({2.0f, 3.0f, 5.0f}, {10.0f, 0.0f, -4.0f});
    for (float theta = -180.0f; theta < 180.0f; theta += 37.0f)
        for (float phi = 5.0f; phi < 180.0f; phi += 29.0f) {
            const OrbitCamera c = framed(points, 1.5f, {theta, phi});
            const glm::vec2 e = ndcExtent(c, points, 1.5f);
            EXPECT_NEAR(std::max(e.x, e.y), kSilhouetteSpan, 1e-4f) << theta << ", " << phi;  // inside, and touching
            // Never wider than the cone's 30° needs for the sphere's whole outline.
            EXPECT_LT(c.fovYDegrees, 2.0f * glm::degrees(std::atan(std::tan(glm::radians(15.0f)) / kSilhouetteSpan)) + 1e-3f);
        }
}

TEST(Framing, TheUnitBoxIsSeenFromAboveItsTopFaceWithModestPerspective) {
    // From 15° above the horizon the eye stands above the top face (y = 0.5), which is then seen,
    // 3.9 times the bounding radius away (the eye of the box-corner framing before: 0.012 above it).
    const std::vector<glm::vec3> box = corners(glm::vec3(1.0f));
    const OrbitCamera c = framed(box, 1.0f);
    EXPECT_GT(c.eye().y, 0.85f);
    EXPECT_GT(c.radius, 3.8f * std::sqrt(3.0f) / 2.0f);
}

TEST(Framing, AGivenFieldOfViewKeepsTheDistance) {
    const std::vector<glm::vec3> points = corners({4.0f, 1.0f, 2.0f});
    const OrbitCamera fitted = framed(points, 1.5f);
    const OrbitCamera narrow = framed(points, 1.5f, {0.0f, 75.0f}, 20.0f);
    EXPECT_EQ(narrow.fovYDegrees, 20.0f);
    EXPECT_EQ(narrow.radius, fitted.radius);
    EXPECT_EQ(narrow.target, fitted.target);
    // The image scales by tan(fitted / 2) / tan(10°): the model is that much bigger.
    const glm::vec2 a = ndcExtent(fitted, points, 1.5f), b = ndcExtent(narrow, points, 1.5f);
    EXPECT_NEAR(b.x / a.x, std::tan(glm::radians(fitted.fovYDegrees / 2.0f)) / std::tan(glm::radians(10.0f)), 1e-3f);
}

TEST(Framing, SeveralDirectionsShareTheDistanceAndTheWidestFieldOfView) {
    const std::vector<glm::vec3> points = corners({6.0f, 1.0f, 1.0f});
    const OrbitCamera side = framed(points, 1.0f, {0.0f, 90.0f}), end = framed(points, 1.0f, {90.0f, 90.0f});
    EXPECT_GT(side.fovYDegrees, end.fovYDegrees);  // the long side seen whole needs the wider view
    const OrbitCamera both = frame(pointsOf(points), {.aspect = 1.0f, .directions = {{90.0f, 90.0f}, {0.0f, 90.0f}}});
    EXPECT_EQ(both.thetaDegrees, 90.0f);  // the first direction's
    EXPECT_EQ(both.radius, side.radius);
    EXPECT_NEAR(both.fovYDegrees, side.fovYDegrees, 1e-4f);
}

TEST(Framing, DegenerateInputs) {
    const OrbitCamera none = framed({}, 1.0f);
    EXPECT_EQ(none.target, glm::vec3(0.0f));
    EXPECT_EQ(none.fovYDegrees, kFramingFovYDegrees);
    const OrbitCamera point = framed({{2, 3, 4}, {2, 3, 4}}, 1.0f);
    EXPECT_EQ(point.target, glm::vec3(2, 3, 4));
    EXPECT_EQ(point.fovYDegrees, kFramingConeDegrees);
    EXPECT_GT(point.radius, 0.0f);
    // A segment seen end-on has no extent: the cone's 30°, and not from inside it.
    const OrbitCamera endOn = framed({{0, 0, -1}, {0, 0, 1}}, 1.0f, {0.0f, 90.0f});
    EXPECT_EQ(endOn.fovYDegrees, kFramingConeDegrees);
    EXPECT_GT(endOn.radius, 1.0f);
}

TEST(Framing, DefaultDirection) {
    Scene s;
    const auto box = [](glm::vec3 size) {
        Aabb b;
        b.extend(-0.5f * size);
        b.extend(0.5f * size);
        return b;
    };
    s.bounds = box({2.0f, 1.0f, 2.0f});
    EXPECT_EQ(defaultOrbitAngles(s), glm::vec2(0.0f, 75.0f));  // the front, 15° above the horizon
    s.bounds = box({2.0f, 0.0f, 2.0f});  // a plane in the ground: seen from above, not edge-on
    EXPECT_EQ(defaultOrbitAngles(s), glm::vec2(0.0f, 75.0f));
    s.bounds = box({0.0f, 2.0f, 2.0f});  // a plane facing ±X: from +X
    EXPECT_EQ(defaultOrbitAngles(s), glm::vec2(90.0f, 75.0f));
    s.bounds = {};
    EXPECT_EQ(defaultOrbitAngles(s), glm::vec2(0.0f, 75.0f));
    // The sphere grid, a chart, head-on.
    EXPECT_EQ(defaultOrbitAngles(assets::makeSphereGrid(2)), glm::vec2(0.0f, 90.0f));
}

TEST(Framing, TheFlagsReadBackAsTheSameCamera) {
    const OrbitCamera c = framed(corners({1.3f, 0.7f, 2.9f}, {0.1f, 1.0f / 3.0f, -7.25f}), 1.7f, {30.0f, 75.0f});
    const std::string flags = orbitCameraFlags(c);
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
