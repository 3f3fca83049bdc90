// passes::skyRays (passes/backdrop/sky_rays.h): the linear function of the pixel position gives,
// at every pixel, the direction from the eye through the pixel's point on the near plane, rotated
// into the environment's frame, as a double-precision inverse projection does.
#include "passes/backdrop/sky_rays.h"
#include "scene/camera.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace candela::passes {
namespace {

// The reference: pixel (x, y)'s ray, from the inverse view-projection in double precision.
glm::dvec3 referenceSkyRay(const glm::mat4& viewProjection, const glm::vec3& eye, const glm::vec2& rotation, double x,
                           double y, uint32_t width, uint32_t height) {
    const glm::dvec4 ndc(x * 2.0 / width - 1.0, y * 2.0 / height - 1.0, 1.0, 1.0);
    const glm::dvec4 near = glm::inverse(glm::dmat4(viewProjection)) * ndc;
    const glm::dvec3 d = glm::normalize(glm::dvec3(near) / near.w - glm::dvec3(eye));
    return {d.x * rotation.x + d.z * rotation.y, d.y, -d.x * rotation.y + d.z * rotation.x};
}

// The largest angle, in radians, between skyRays' ray and the reference over a grid of pixels
// (corners and edges included).
double largestSkyRayAngle(const glm::mat4& viewProjection, const glm::vec3& eye, float rotationDegrees, uint32_t width,
                          uint32_t height) {
    const float theta = glm::radians(rotationDegrees);
    const glm::vec2 rotation(std::cos(theta), std::sin(theta));
    const shading::SkyRays rays = skyRays(viewProjection, eye, rotation, width, height);
    double largest = 0.0;
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) {
            const double x = 0.5 + (width - 1.0) * i / 8.0, y = 0.5 + (height - 1.0) * j / 8.0;
            // As the shader evaluates it: in float.
            const glm::vec3 ray = glm::vec3(rays.perX) * float(x) + glm::vec3(rays.perY) * float(y) + glm::vec3(rays.origin);
            const glm::dvec3 expected = referenceSkyRay(viewProjection, eye, rotation, x, y, width, height);
            // atan2 of |a × b| and a · b: exact for small angles, where acos of the cosine is not.
            const glm::dvec3 got(ray);
            largest = std::max(largest, std::atan2(glm::length(glm::cross(got, expected)), glm::dot(got, expected)));
        }
    return largest;
}

// 1e-5 rad is a 600th of a texel of a 256² cube face (90° / 256 = 6.1e-3 rad).
constexpr double kAngle = 1e-5;

TEST(SkyRays, FollowTheInverseProjectionOfAnOrbitCameraFarFromTheOrigin) {
    // The near plane 1 mm from an eye 1 km from the origin: the float subtraction the shader did
    // before lost most of the direction's digits here.
    const scene::OrbitCamera camera{.target = glm::vec3(1000.0f, 20.0f, -300.0f), .thetaDegrees = 37.0f, .phiDegrees = 21.0f,
                                    .radius = 3.0f, .fovYDegrees = 45.0f, .znear = 1e-3f};
    const scene::ViewSetup view = camera.view(1280.0f / 720.0f);
    EXPECT_LT(largestSkyRayAngle(view.viewProjection, view.eye, 0.0f, 1280, 720), kAngle);
    EXPECT_LT(largestSkyRayAngle(view.viewProjection, view.eye, 123.0f, 1280, 720), kAngle);
}

TEST(SkyRays, FollowALensShiftAndAnOffCentrePrincipalPoint) {
    const glm::mat4 view = glm::lookAt(glm::vec3(2.0f, 1.0f, 4.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 shifted =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.0f, 0.0f)) * scene::perspectiveReverseZ(glm::radians(60.0f), 1.5f, 0.01f);
    EXPECT_LT(largestSkyRayAngle(shifted * view, glm::vec3(2.0f, 1.0f, 4.0f), 45.0f, 300, 200), kAngle);
    const glm::mat4 intrinsics = scene::perspectiveReverseZ(scene::Intrinsics{.fx = 0.9f, .fy = 1.3f, .cx = 0.37f, .cy = 0.61f}, 0.01f);
    EXPECT_LT(largestSkyRayAngle(intrinsics * view, glm::vec3(2.0f, 1.0f, 4.0f), -70.0f, 640, 480), kAngle);
}

TEST(SkyRays, FollowAnOrthographicCameraAndAFiniteFarPlane) {
    const glm::vec3 eye(0.0f, 5.0f, 5.0f);
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_LT(largestSkyRayAngle(scene::orthographicReverseZ(2.0f, 1.5f, 0.1f, 50.0f) * view, eye, 10.0f, 256, 192), kAngle);
    EXPECT_LT(largestSkyRayAngle(scene::perspectiveReverseZ(glm::radians(30.0f), 1.0f, 0.1f, 100.0f) * view, eye, 0.0f, 96, 96),
              kAngle);
}

TEST(SkyRays, TheRayThroughTheCentreHasLengthOne) {
    const scene::ViewSetup view = scene::OrbitCamera{.radius = 5.0f, .znear = 0.005f}.view(2.0f);
    const shading::SkyRays rays = skyRays(view.viewProjection, view.eye, glm::vec2(1.0f, 0.0f), 200, 100);
    const glm::vec3 centre = glm::vec3(rays.perX) * 100.0f + glm::vec3(rays.perY) * 50.0f + glm::vec3(rays.origin);
    EXPECT_NEAR(glm::length(centre), 1.0f, 1e-5f);
}

}  // namespace
}  // namespace candela::passes
