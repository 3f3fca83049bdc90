// Pinhole intrinsics (scene/camera.h): the projection they give puts a point where K says, v down
// with pixel centres at i + ½, and intrinsicsOf reads them back from any perspective projection.

#include "scene/camera.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace candela::scene {
namespace {

// Where `projection` puts the camera-space point `p` in an image of width × height: (u, v) in
// pixels, v down, the top-left corner at (0, 0).
glm::vec2 pixelOf(const glm::mat4& projection, const glm::vec3& p, float width, float height) {
    const glm::vec4 clip = projection * glm::vec4(p, 1.0f);
    return {(clip.x / clip.w + 1.0f) * 0.5f * width, (clip.y / clip.w + 1.0f) * 0.5f * height};
}

TEST(Pinhole, APointLandsWhereKSays) {
    const float width = 640.0f, height = 480.0f;
    const float fx = 500.0f, fy = 520.0f, cx = 300.0f, cy = 250.0f;
    const glm::mat4 projection = perspectiveReverseZ(Intrinsics{fx / width, fy / height, cx / width, cy / height}, 0.01f);
    for (const glm::vec3 p : {glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(0.3f, 0.2f, -1.5f), glm::vec3(-1.0f, -0.7f, -4.0f)}) {
        const glm::vec2 uv = pixelOf(projection, p, width, height);
        EXPECT_NEAR(uv.x, fx * p.x / -p.z + cx, 1e-3f);
        EXPECT_NEAR(uv.y, fy * -p.y / -p.z + cy, 1e-3f);  // +Y up in the camera, v down in the image
        // Reverse Z, infinite far plane: depth = znear / distance.
        const glm::vec4 clip = projection * glm::vec4(p, 1.0f);
        EXPECT_NEAR(clip.z / clip.w, 0.01f / -p.z, 1e-7f);
    }
}

TEST(Pinhole, IntrinsicsAreReadBackFromAnyPerspective) {
    const Intrinsics k{0.8f, 1.1f, 0.45f, 0.55f};
    const Intrinsics back = intrinsicsOf(perspectiveReverseZ(k, 0.1f));
    EXPECT_FLOAT_EQ(back.fx, k.fx);
    EXPECT_FLOAT_EQ(back.fy, k.fy);
    EXPECT_FLOAT_EQ(back.cx, k.cx);
    EXPECT_FLOAT_EQ(back.cy, k.cy);
    // A symmetric 60° camera at 16:9: fy = ½ / tan 30° image heights, a centred principal point.
    const Intrinsics centred = intrinsicsOf(perspectiveReverseZ(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f));
    EXPECT_NEAR(centred.fy, 0.5f / std::tan(glm::radians(30.0f)), 1e-6f);
    EXPECT_NEAR(centred.fx * 16.0f, centred.fy * 9.0f, 1e-5f);  // square pixels
    EXPECT_FLOAT_EQ(centred.cx, 0.5f);
    EXPECT_FLOAT_EQ(centred.cy, 0.5f);
}

TEST(Pinhole, APlacedCameraLooksDownItsMinusZWithANearPlaneFromTheScene) {
    const glm::mat4 cameraToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 10.0f));
    const ViewSetup view = placedView(cameraToWorld, glm::radians(45.0f), 1.0f, Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)});
    EXPECT_FLOAT_EQ(view.znear, 0.01f);  // 1/1000 of the 10 m to the bounds' centre
    EXPECT_EQ(view.eye, glm::vec3(0.0f, 0.0f, 10.0f));
    const glm::vec4 centre = view.viewProjection * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_NEAR(centre.x / centre.w, 0.0f, 1e-6f);
    EXPECT_NEAR(centre.y / centre.w, 0.0f, 1e-6f);
    EXPECT_NEAR(centre.z / centre.w, 0.001f, 1e-7f);
}

}  // namespace
}  // namespace candela::scene
