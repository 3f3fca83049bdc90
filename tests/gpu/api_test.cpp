// The public API (include/candela/, docs/embedding.md) on lavapipe under validation: its images
// against the renderer's own with `candela render`'s defaults, the pixel formats and caller memory,
// scenes and environments from memory, sequences, cancellation, two devices on two threads, and
// its errors.

#include "gltf_test_util.h"
#include "api_test_util.h"
#include "gpu_test.h"
#include "temp_dir.h"
#include "api/access.h"
#include "candela/candela.h"
#include "assets/procedural_sky.h"
#include "assets/builtin_scenes.h"
#include "render/renderer.h"
#include "vk/context.h"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <thread>

namespace candela::test::api_test {
namespace {

using assets::test::Bytes;
using assets::test::GltfBuilder;
using assets::test::smallPng;
using assets::test::texturedTriangle;
using assets::test::writeFile;
namespace fs = std::filesystem;


RenderOptions small(uint32_t width = 64, uint32_t height = 48) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    return options;
}

// `scene` lit by `environment`, drawn on a device of its own that reports no validation message.
// GoogleTest's assertions may run on any thread.
Image renderAlone(const Scene& scene, const Environment* environment) {
    Device device(validated());
    Image image = device.render(scene, small(), environment);
    EXPECT_EQ(messages(device), 0u);
    return image;
}

std::vector<std::byte> asBytes(const Bytes& bytes) {
    std::vector<std::byte> out(bytes.size());
    if (!bytes.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

TEST(Api, VersionMatchesTheHeaders) {
    EXPECT_STREQ(version(), CANDELA_VERSION_STRING);
    EXPECT_EQ(std::string(version()), std::to_string(CANDELA_VERSION_MAJOR) + "." + std::to_string(CANDELA_VERSION_MINOR) +
                                          "." + std::to_string(CANDELA_VERSION_PATCH));
}

// The API's defaults are `candela render`'s: the same pixels as the renderer given the settings
// the command builds (app/session.cpp: the sky's skybox behind, no default lights with it).
TEST(Api, RendersWhatTheRendererRendersWithTheCommandsDefaults) {
    const Environment sky = Environment::sky();
    const Image api = renderAlone(Scene::sphereGrid(3), &sky);
    ASSERT_EQ(api.pixels.size(), 64u * 48u * 4u);

    vk::Context context({.validation = true});
    Renderer renderer(context);
    const scene::Scene scene = assets::makeSphereGrid(3);
    const assets::Environment environment = assets::makeProceduralSky();
    RenderSettings settings{.width = 64, .height = 48, .scene = &scene};
    settings.environment = &environment;
    settings.ibl.skybox = true;
    settings.defaultLights = false;
    const CapturedFrame frame = renderer.capture(settings);
    ASSERT_EQ(frame.rgba8.size(), api.pixels.size());
    EXPECT_EQ(std::memcmp(frame.rgba8.data(), api.pixels.data(), api.pixels.size()), 0);
    EXPECT_EQ(messages(context), 0u);
}

TEST(Api, FloatFormatsHoldTheSameValues) {
    Device device(validated());
    const Scene grid = Scene::sphereGrid(2);
    RenderOptions options = small(32, 24);
    options.format = PixelFormat::Rgba32Float;
    const Image full = device.render(grid, options);
    options.format = PixelFormat::Rgba16Float;
    const Image half = device.render(grid, options);
    ASSERT_EQ(full.pixels.size(), 32u * 24u * 16u);
    ASSERT_EQ(half.pixels.size(), 32u * 24u * 8u);
    float covered = 0.0f;
    for (size_t i = 0; i < 32u * 24u * 4u; ++i) {
        float f;
        uint16_t h;
        std::memcpy(&f, full.pixels.data() + i * 4, 4);
        std::memcpy(&h, half.pixels.data() + i * 2, 2);
        ASSERT_EQ(glm::unpackHalf1x16(h), f) << "value " << i;
        if (i % 4 == 3) covered += f;
    }
    EXPECT_GT(covered, 0.0f);  // the spheres are there (alpha = coverage)
    EXPECT_EQ(messages(device), 0u);
}

TEST(Api, RenderIntoLeavesTheRowPaddingAlone) {
    Device device(validated());
    const Scene grid = Scene::sphereGrid(2);
    const RenderOptions options = small(20, 10);
    const Image packed = device.render(grid, options);
    const size_t rowBytes = 20 * 4 + 12;
    std::vector<std::byte> memory(rowBytes * 10, std::byte{0xAB});
    device.renderInto(memory.data(), rowBytes, grid, options);
    for (uint32_t y = 0; y < 10; ++y) {
        EXPECT_EQ(std::memcmp(memory.data() + y * rowBytes, packed.pixels.data() + y * 80, 80), 0) << "row " << y;
        for (size_t x = 80; x < rowBytes; ++x) ASSERT_EQ(memory[y * rowBytes + x], std::byte{0xAB});
    }
    EXPECT_THROW(device.renderInto(memory.data(), 79, grid, options), InputError);
}

TEST(Api, SceneFromMemoryReadsItsUrisThroughTheResolver) {
    TempDir dir;
    const GltfBuilder model = texturedTriangle("texture.png");
    const fs::path file = model.writeGltf(dir.path());
    writeFile(dir.path() / "texture.png", smallPng());
    const std::string json = model.withBuffer("model.bin").dump();
    const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(json.data()), json.size());
    std::vector<std::string> asked;
    const UriResolver resolver = [&](const std::string& uri) -> std::optional<std::vector<std::byte>> {
        asked.push_back(uri);
        if (uri == "model.bin") return asBytes(model.bin);
        if (uri == "texture.png") return asBytes(smallPng());
        return std::nullopt;
    };
    const Scene fromMemory = Scene::fromMemory(bytes, "memory.gltf", resolver);
    EXPECT_EQ(fromMemory.name(), "memory.gltf");
    EXPECT_NE(std::find(asked.begin(), asked.end(), "model.bin"), asked.end());
    EXPECT_NE(std::find(asked.begin(), asked.end(), "texture.png"), asked.end());

    Device device(validated());
    const Image a = device.render(Scene::fromFile(file.string()), small());
    const Image b = device.render(fromMemory, small());
    EXPECT_EQ(a.pixels, b.pixels);

    try {
        (void)Scene::fromMemory(bytes, "memory.gltf");
        ADD_FAILURE() << "no resolver, yet the URIs were read";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "memory.gltf");
        EXPECT_NE(e.reason().find("model.bin"), std::string::npos) << e.what();
    }
}

TEST(Api, EnvironmentFromMemoryIsTheFilesEnvironment) {
    // A 4 × 2 Radiance file, flat (not run-length encoded: narrower than 8).
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
    for (int i = 0; i < 8; ++i) hdr += std::string{char(128), char(64 + i), char(32), char(129)};
    TempDir dir;
    writeFile(dir.path() / "tiny.hdr", hdr);
    const Environment file = Environment::fromFile((dir.path() / "tiny.hdr").string());
    const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(hdr.data()), hdr.size());
    const Environment memory = Environment::fromMemory(bytes, "tiny.hdr");
    EXPECT_EQ(memory.width(), 4u);
    EXPECT_EQ(memory.height(), 2u);
    EXPECT_EQ(memory.width(), file.width());

    Device device(validated());
    const Scene grid = Scene::sphereGrid(2);
    EXPECT_EQ(device.render(grid, small(), &file).pixels, device.render(grid, small(), &memory).pixels);

    const std::string junk = "not an image";
    try {
        (void)Environment::fromMemory(std::span(reinterpret_cast<const std::byte*>(junk.data()), junk.size()), "junk.hdr");
        ADD_FAILURE() << "junk was read";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "junk.hdr");
        EXPECT_FALSE(e.reason().empty());
    }
}

TEST(Api, BadInputIsAnInputErrorNamingItsFile) {
    try {
        (void)Scene::fromFile("no/such/model.glb");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "no/such/model.glb");
        EXPECT_EQ(std::string(e.what()), e.file() + ": " + e.reason());
    }
    EXPECT_THROW(Device({.profile = "no-such-profile"}), InputError);
    EXPECT_THROW(Device({.device = "no-such-device", .pipelineCache = "off"}), InputError);
    EXPECT_THROW(Scene::sphereGrid(0), InputError);

    Device device(validated());
    const Scene grid = Scene::sphereGrid(2);
    EXPECT_THROW(device.render(grid, small(0, 10)), InputError);
    RenderOptions options = small();
    options.variant = "no-such-variant";
    EXPECT_THROW(device.render(grid, options), InputError);
    options = small();
    options.camera.gltfCamera = 3;
    EXPECT_THROW(device.render(grid, options), InputError);
    options = small();
    options.background.kind = Background::Kind::Environment;  // and no environment given
    EXPECT_THROW(device.render(grid, options), InputError);
    // The device is still good.
    EXPECT_EQ(device.render(grid, small()).pixels.size(), 64u * 48u * 4u);
    EXPECT_EQ(messages(device), 0u);
    // Every error is a candela::Error.
    EXPECT_THROW(Scene::fromFile(""), Error);
}

TEST(Api, SequencesTurnTheCameraAndReportProgress) {
    Device device(validated());
    const Scene grid = Scene::sphereGrid(3);
    const RenderOptions options = small();
    std::vector<Image> frames;
    std::vector<RenderProgress> stages;
    device.renderSequence(grid, options, {.frames = 3, .fps = 30.0, .turntableDegrees = 90.0f},
                          [&](uint32_t index, const Image& image) {
                              EXPECT_EQ(index, frames.size());
                              frames.push_back(image);
                          },
                          nullptr, [&](const RenderProgress& p) {
                              stages.push_back(p);
                              return true;
                          });
    ASSERT_EQ(frames.size(), 3u);
    ASSERT_EQ(stages.size(), 4u);  // the upload, then each frame
    EXPECT_EQ(stages[0].stage, RenderProgress::Stage::Upload);
    EXPECT_EQ(stages[3].stage, RenderProgress::Stage::Frame);
    EXPECT_EQ(stages[3].frame, 2u);
    EXPECT_EQ(stages[3].frameCount, 3u);
    EXPECT_NE(frames[0].pixels, frames[1].pixels);  // the camera turned
    EXPECT_EQ(messages(device), 0u);
}

TEST(Api, CancellingStopsTheRenderAndLeavesTheDeviceUsable) {
    Device device(validated());
    const Scene grid = Scene::sphereGrid(2);
    EXPECT_THROW(device.render(grid, small(), nullptr, [](const RenderProgress& p) { return p.stage != RenderProgress::Stage::Frame; }),
                 CancelledError);
    uint32_t written = 0;
    EXPECT_THROW(device.renderSequence(grid, small(), {.frames = 5}, [&](uint32_t, const Image&) {
        ++written;
        device.cancel();  // as another thread would: the next frame does not start
    }), CancelledError);
    EXPECT_EQ(written, 1u);
    EXPECT_EQ(device.render(grid, small()).pixels.size(), 64u * 48u * 4u);
    EXPECT_EQ(messages(device), 0u);
}

TEST(Api, TwoDevicesRenderOnTwoThreadsAtOnce) {
    const Scene grid = Scene::sphereGrid(3);
    const Environment sky = Environment::sky();
    const Image alone = renderAlone(grid, &sky);
    Image images[2];
    std::thread threads[2];
    for (int i = 0; i < 2; ++i) threads[i] = std::thread([&, i] { images[i] = renderAlone(grid, &sky); });
    for (std::thread& thread : threads) thread.join();
    EXPECT_EQ(images[0].pixels, alone.pixels);
    EXPECT_EQ(images[1].pixels, alone.pixels);
}

TEST(Api, WriteImageRefusesAFormatTheFileCannotHold) {
    TempDir dir;
    Image floats{2, 2, PixelFormat::Rgba32Float, std::vector<std::byte>(2 * 2 * 16)};
    EXPECT_THROW(writeImage((dir.path() / "a.png").string(), floats), InputError);
    EXPECT_NO_THROW(writeImage((dir.path() / "a.exr").string(), floats));
    Image bytes{2, 2, PixelFormat::Rgba8Srgb, std::vector<std::byte>(2 * 2 * 4)};
    EXPECT_THROW(writeImage((dir.path() / "a.pfm").string(), bytes), InputError);
    EXPECT_THROW(writeImage((dir.path() / "a.bmp").string(), bytes), InputError);
    bytes.pixels.pop_back();
    EXPECT_THROW(writeImage((dir.path() / "a.png").string(), bytes), InputError);
}

}  // namespace
}  // namespace candela::test::api_test
