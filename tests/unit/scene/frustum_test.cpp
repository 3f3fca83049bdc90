// View-frustum culling of world-space boxes (scene/frustum.h) with the renderer's reverse-Z
// projections.
#include "scene/camera.h"
#include "scene/frustum.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace candela::scene {
namespace {

Aabb box(glm::vec3 centre, float halfSize) { return Aabb{centre - halfSize, centre + halfSize}; }

// The eye at the origin looking down −Z, 90° vertical field of view, square viewport, near 0.1,
// infinite far plane: the frustum is |x| ≤ −z, |y| ≤ −z, z ≤ −0.1.
Frustum infiniteFrustum() {
    return Frustum(perspectiveReverseZ(glm::radians(90.0f), 1.0f, 0.1f) * glm::lookAt(glm::vec3(0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0)));
}

TEST(Frustum, TheInfiniteFarPlaneIsLeftOut) { EXPECT_EQ(infiniteFrustum().planeCount(), 5u); }

TEST(Frustum, BoxesInsideAreKept) {
    const Frustum f = infiniteFrustum();
    EXPECT_TRUE(f.intersects(box({0, 0, -5}, 1)));
    EXPECT_TRUE(f.intersects(box({3, -3, -5}, 0.5f)));  // off-centre, still inside
    EXPECT_TRUE(f.intersects(box({0, 0, -1e7f}, 1)));   // far away: no far plane
}

TEST(Frustum, BoxesOutsideEachSideAreCulled) {
    const Frustum f = infiniteFrustum();
    for (const glm::vec3 centre : {glm::vec3(20, 0, -5), glm::vec3(-20, 0, -5), glm::vec3(0, 20, -5), glm::vec3(0, -20, -5)})
        EXPECT_FALSE(f.intersects(box(centre, 1))) << centre.x << "," << centre.y;
}

TEST(Frustum, BoxesStraddlingAPlaneAreKept) {
    const Frustum f = infiniteFrustum();
    EXPECT_TRUE(f.intersects(box({5, 0, -5}, 0.5f)));    // across x = −z
    EXPECT_TRUE(f.intersects(box({0, -5.2f, -5}, 0.5f)));  // across y = z
    EXPECT_TRUE(f.intersects(box({0, 0, 0}, 1)));         // around the eye, across the near plane
}

TEST(Frustum, BoxesBehindTheEyeAreCulled) {
    const Frustum f = infiniteFrustum();
    EXPECT_FALSE(f.intersects(box({0, 0, 5}, 1)));
    EXPECT_FALSE(f.intersects(box({0, 0, -0.05f}, 0.01f)));  // in front of the eye, before the near plane
    // Wide boxes behind the eye: inside the side planes' mirror image (|x| ≤ z), still culled.
    EXPECT_FALSE(f.intersects(Aabb{{-50, -50, 1}, {50, 50, 100}}));
}

TEST(Frustum, AFiniteFarPlaneCullsBeyondIt) {
    const Frustum f(perspectiveReverseZ(glm::radians(90.0f), 1.0f, 0.1f, 100.0f));
    EXPECT_EQ(f.planeCount(), 6u);
    EXPECT_TRUE(f.intersects(box({0, 0, -99.5f}, 1)));
    EXPECT_FALSE(f.intersects(box({0, 0, -102}, 1)));
}

TEST(Frustum, OrthographicViewsCullAtTheirExtents) {
    const Frustum f(orthographicReverseZ(2.0f, 1.0f, 0.1f, 50.0f));
    EXPECT_TRUE(f.intersects(box({1.5f, 0, -10}, 0.1f)));
    EXPECT_FALSE(f.intersects(box({2.5f, 0, -10}, 0.1f)));
    EXPECT_FALSE(f.intersects(box({0, 1.5f, -10}, 0.1f)));
    EXPECT_FALSE(f.intersects(box({0, 0, -60}, 1)));
}

TEST(Frustum, FollowsTheCamerasTransform) {
    // The orbit camera of the renderer looking at a box from +X: a box at the far side of the
    // target is in view, one behind the camera is not.
    OrbitCamera camera;
    camera.thetaDegrees = 90.0f;
    camera.radius = 10.0f;
    const Frustum f(camera.view(16.0f / 9.0f).viewProjection);
    EXPECT_TRUE(f.intersects(box({-5, 0, 0}, 1)));
    EXPECT_FALSE(f.intersects(box({15, 0, 0}, 1)));
}

TEST(Projection, OnlyTheInfiniteFarPlaneIsAtInfinity) {
    EXPECT_TRUE(farPlaneAtInfinity(perspectiveReverseZ(glm::radians(60.0f), 1.5f, 0.1f)));
    EXPECT_FALSE(farPlaneAtInfinity(perspectiveReverseZ(glm::radians(60.0f), 1.5f, 0.1f, 100.0f)));
    EXPECT_FALSE(farPlaneAtInfinity(orthographicReverseZ(2.0f, 1.0f, 0.1f, 50.0f)));
}

}  // namespace
}  // namespace candela::scene
