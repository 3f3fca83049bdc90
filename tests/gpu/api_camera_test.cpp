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

#include <glm/glm.hpp>

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

// The direction (unit vector) of orbit angles (θ°, φ°), as the orbit camera places its eye.
glm::dvec3 directionOf(const std::array<float, 2>& view) {
    const double theta = glm::radians(double(view[0])), phi = glm::radians(double(view[1]));
    return {std::sin(phi) * std::sin(theta), std::cos(phi), std::sin(phi) * std::cos(theta)};
}

TEST(ApiCamera, SphereViewsSpreadEvenlyAndRingViewsKeepTheirElevation) {
    const std::vector<std::array<float, 2>> sphere = sphereViews(200);
    ASSERT_EQ(sphere.size(), 200u);
    glm::dvec3 sum(0.0);
    double closest = 1e9;
    for (size_t i = 0; i < sphere.size(); ++i) {
        sum += directionOf(sphere[i]);
        for (size_t j = 0; j < i; ++j)
            closest = std::min(closest, std::acos(glm::clamp(glm::dot(directionOf(sphere[i]), directionOf(sphere[j])), -1.0, 1.0)));
    }
    // Even: the directions balance out, and no two are much closer than the spacing of an even
    // spread (the square root of the sphere's area per point; a Fibonacci lattice keeps ~0.8 of it).
    EXPECT_LT(glm::length(sum) / 200.0, 0.01);
    EXPECT_GT(closest, 0.7 * std::sqrt(4.0 * std::numbers::pi / 200.0));
    const std::vector<std::array<float, 2>> ring = ringViews(8, 20.0f);
    ASSERT_EQ(ring.size(), 8u);
    for (size_t i = 0; i < ring.size(); ++i) {
        EXPECT_FLOAT_EQ(ring[i][0], 45.0f * float(i));
        EXPECT_FLOAT_EQ(ring[i][1], 70.0f);
    }
}

TEST(ApiCamera, ViewsLookFromTheirDirectionsAtOneDistanceWithJitteredLighting) {
    Device device(validated());
    const Scene grid = Scene::sphereGrid(3);
    const Environment sky = Environment::sky();
    RenderOptions options = small();
    options.camera.orbit.reset();
    const SequenceOptions views{.views = sphereViews(5), .lightingSeed = 42};
    std::vector<Image> images;
    device.renderSequence(grid, options, views, [&](uint32_t, const Image& image) { images.push_back(image); }, &sky);
    ASSERT_EQ(images.size(), 5u);
    double radius = -1.0;
    std::vector<float> rotations;
    for (uint32_t i = 0; i < 5; ++i) {
        const auto& m = images[i].camera.cameraToWorld;
        const glm::dvec3 eye(m[12], m[13], m[14]);  // the grid is centred on the origin
        if (radius < 0.0) radius = glm::length(eye);
        EXPECT_NEAR(glm::length(eye), radius, 1e-4 * radius) << "view " << i;
        EXPECT_GT(glm::dot(glm::normalize(eye), directionOf(views.views[i])), 0.99999) << "view " << i;
        const RenderOptions frame = sequenceFrame(grid, options, views, i);
        EXPECT_EQ(frame.time, options.time);  // one pose
        rotations.push_back(frame.environmentRotationDegrees);
        EXPECT_EQ(sequenceFrame(grid, options, views, i).environmentRotationDegrees, rotations.back());  // the same seed, the same turn
        EXPECT_EQ(device.render(grid, frame, &sky).pixels, images[i].pixels) << "view " << i;
    }
    for (size_t i = 1; i < rotations.size(); ++i) EXPECT_NE(rotations[i], rotations[0]);
    for (float r : rotations) EXPECT_TRUE(r >= 0.0f && r < 360.0f) << r;
    SequenceOptions otherSeed = views;
    otherSeed.lightingSeed = 43;
    EXPECT_NE(sequenceFrame(grid, options, otherSeed, 0).environmentRotationDegrees, rotations[0]);
    // Views need the orbit camera.
    RenderOptions placed = options;
    placed.camera = lookAt({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f});
    EXPECT_THROW(device.renderSequence(grid, placed, views, [](uint32_t, const Image&) {}), InputError);
    EXPECT_EQ(messages(device), 0u);
}

TEST(ApiCamera, TransformsJsonHoldsEachFramesCamera) {
    CameraInfo camera;
    camera.width = 64;
    camera.height = 48;
    camera.intrinsics = {50.0f, 50.0f, 32.0f, 24.0f};
    camera.znear = 0.01f;
    camera.cameraToWorld = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1};
    const std::string json = transformsJson({{"a.png", camera, 10.0f}, {"b.png", camera, 20.0f}});
    for (const char* field : {"\"fl_x\": 50.0", "\"cx\": 32.0", "\"w\": 64", "\"file_path\": \"b.png\"", "\"far\": null",
                              "\"environment_rotation_degrees\": 20.0"})
        EXPECT_NE(json.find(field), std::string::npos) << field << " in\n" << json;
    camera.orthographic = true;
    EXPECT_THROW(transformsJson({{"a.png", camera, 0.0f}}), InputError);
    EXPECT_THROW(transformsJson({}), InputError);
}

}  // namespace
}  // namespace candela::test::api_camera_test
