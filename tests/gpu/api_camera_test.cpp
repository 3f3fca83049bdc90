// The public API's cameras (include/candela/render.h, image.h) on lavapipe under validation: a
// placed camera (lookAt) and pinhole intrinsics reproduce the orbit camera they describe, the
// principal point moves the image by whole pixels, CameraInfo reports the camera drawn with, and
// sequenceFrame's frames rendered one at a time are renderSequence's.

#include "api_test_util.h"
#include "candela/candela.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

namespace candela::test::api_camera_test {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;

RenderOptions small() {
    RenderOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.camera.orbit = std::array<float, 3>{30.0f, 70.0f, 3.0f};
    options.camera.target = std::array<float, 3>{0.0f, 0.0f, 0.0f};
    options.camera.fovYDegrees = 40.0f;
    return options;
}

// The largest difference of one 8-bit channel between `a` and `b`, over pixels x ∈ [x0, x1) of
// `a` against x + shift of `b`.
int largestDifference(const Image& a, const Image& b, uint32_t x0 = 0, uint32_t x1 = kWidth, int shift = 0) {
    int largest = 0;
    for (uint32_t y = 0; y < a.height; ++y)
        for (uint32_t x = x0; x < x1; ++x)
            for (uint32_t c = 0; c < 4; ++c) {
                const int va = int(a.pixels[(y * a.width + x) * 4 + c]);
                const int vb = int(b.pixels[(y * b.width + uint32_t(int(x) + shift)) * 4 + c]);
                largest = std::max(largest, std::abs(va - vb));
            }
    return largest;
}

TEST(ApiCamera, PlacedAndPinholeCamerasReproduceTheOrbitCamera) {
    Device device(validated());
    const Scene grid = Scene::sphereGrid(3);
    const RenderOptions orbit = small();
    const Image byOrbit = device.render(grid, orbit);

    // What CameraInfo says of the orbit camera: its eye at r·(sin φ sin θ, cos φ, sin φ cos θ), a
    // centred principal point and the focal length of a 40° vertical field of view.
    const CameraInfo& info = byOrbit.camera;
    const double theta = 30.0 * std::numbers::pi / 180.0, phi = 70.0 * std::numbers::pi / 180.0;
    EXPECT_NEAR(info.cameraToWorld[12], 3.0 * std::sin(phi) * std::sin(theta), 1e-5);
    EXPECT_NEAR(info.cameraToWorld[13], 3.0 * std::cos(phi), 1e-5);
    EXPECT_NEAR(info.cameraToWorld[14], 3.0 * std::sin(phi) * std::cos(theta), 1e-5);
    const double focal = kHeight / (2.0 * std::tan(20.0 * std::numbers::pi / 180.0));
    EXPECT_NEAR(info.intrinsics[0], focal, 1e-3);
    EXPECT_NEAR(info.intrinsics[1], focal, 1e-3);
    EXPECT_NEAR(info.intrinsics[2], kWidth / 2.0, 1e-4);
    EXPECT_NEAR(info.intrinsics[3], kHeight / 2.0, 1e-4);
    EXPECT_NEAR(info.fovYDegrees, 40.0, 1e-4);
    EXPECT_NEAR(info.znear, 3e-3, 1e-7);  // 1/1000 of the distance
    EXPECT_TRUE(std::isinf(info.zfar));
    EXPECT_FALSE(info.orthographic);
    EXPECT_EQ(info.width, kWidth);

    // The same camera placed by lookAt from that eye, and given by its intrinsics.
    RenderOptions placed = small();
    placed.camera = lookAt({info.cameraToWorld[12], info.cameraToWorld[13], info.cameraToWorld[14]}, {0.0f, 0.0f, 0.0f});
    placed.camera.fovYDegrees = 40.0f;
    const Image byPlacement = device.render(grid, placed);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(byPlacement.camera.cameraToWorld[i], info.cameraToWorld[i], 1e-5) << i;
    RenderOptions pinhole = small();
    pinhole.camera.intrinsics = info.intrinsics;
    const Image byIntrinsics = device.render(grid, pinhole);
    // Both are the orbit camera's matrices to float rounding: at most one level on an edge pixel.
    EXPECT_LE(largestDifference(byOrbit, byPlacement), 1);
    EXPECT_LE(largestDifference(byOrbit, byIntrinsics), 1);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(byIntrinsics.camera.intrinsics[i], info.intrinsics[i], 1e-3) << i;

    // The principal point 8 pixels right moves the image 8 pixels right.
    RenderOptions shifted = pinhole;
    (*shifted.camera.intrinsics)[2] += 8.0f;
    const Image byShifted = device.render(grid, shifted);
    EXPECT_LE(largestDifference(byOrbit, byShifted, 0, kWidth - 8, 8), 1);
    EXPECT_GT(largestDifference(byOrbit, byShifted), 8);  // it did move
    EXPECT_EQ(messages(device), 0u);
}

TEST(ApiCamera, SequenceFramesOneAtATimeAreTheSequence) {
    Device device(validated());
    const Scene grid = Scene::sphereGrid(3);
    RenderOptions options = small();
    options.camera.orbit.reset();  // framed: one distance for the whole turn
    const SequenceOptions turn{.frames = 3, .fps = 24.0, .turntableDegrees = 120.0f};
    std::vector<Image> sequence;
    device.renderSequence(grid, options, turn, [&](uint32_t, const Image& image) { sequence.push_back(image); });
    ASSERT_EQ(sequence.size(), 3u);
    for (uint32_t i = 0; i < 3; ++i) {
        const RenderOptions frame = sequenceFrame(grid, options, turn, i);
        EXPECT_DOUBLE_EQ(frame.time, i / 24.0);
        ASSERT_TRUE(frame.camera.orbit);
        const Image one = device.render(grid, frame);
        EXPECT_EQ(one.pixels, sequence[i].pixels) << "frame " << i;
        EXPECT_EQ(one.camera.cameraToWorld, sequence[i].camera.cameraToWorld) << "frame " << i;
    }
    EXPECT_NE(sequence[0].camera.cameraToWorld, sequence[1].camera.cameraToWorld);
    EXPECT_THROW(sequenceFrame(grid, options, turn, 3), InputError);
    EXPECT_EQ(messages(device), 0u);
}

TEST(ApiCamera, ImpossibleCamerasAreInputErrors) {
    Device device(validated());
    const Scene grid = Scene::sphereGrid(2);
    EXPECT_THROW(lookAt({1.0f, 2.0f, 3.0f}, {1.0f, 2.0f, 3.0f}), InputError);
    EXPECT_THROW(lookAt({0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 0.0f}), InputError);  // looking along up
    RenderOptions options = small();
    options.camera.intrinsics = std::array<float, 4>{0.0f, 10.0f, 32.0f, 24.0f};
    EXPECT_THROW(device.render(grid, options), InputError);
    options.camera.intrinsics = std::array<float, 4>{50.0f, 50.0f, 32.0f, 24.0f};
    options.camera.gltfCamera = 0;
    EXPECT_THROW(device.render(grid, options), InputError);
    options = small();
    options.camera.cameraToWorld = std::array<float, 16>{};  // singular, last row not 0 0 0 1
    EXPECT_THROW(device.render(grid, options), InputError);
    EXPECT_EQ(messages(device), 0u);
}

}  // namespace
}  // namespace candela::test::api_camera_test
