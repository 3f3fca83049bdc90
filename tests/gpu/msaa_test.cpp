// MSAA on the GPU (docs/anti-aliasing.md): the draw targets multisampled and resolved by the render
// pass into the HDR image, alpha to coverage for alpha-masked materials, and every frame variant
// validation-clean at every sample count --msaa accepts (counts the device lacks are clamped).
#include "gpu_test.h"
#include "test_paths.h"

#include "assets/builtin_scenes.h"
#include "assets/gltf_loader.h"
#include "assets/procedural_sky.h"
#include "render/renderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <list>
#include <optional>
#include <vector>

namespace candela::test {
namespace {

// One unlit white quad, (−1, −1)–(1, 1) in the XY plane, tilted about Z so that its edges cross the
// pixel grid at a slant. `alphaRamp`: alpha-masked (cutoff 0.5) with vertex alpha rising 0 → 1
// from left to right, so the cutoff runs down the middle of the quad, away from its edges.
scene::Scene quad(bool alphaRamp) {
    scene::Scene scene;
    scene.source = "test: quad";
    scene::Material material{.name = "white", .unlit = true};
    if (alphaRamp) material.alphaMode = scene::AlphaMode::Mask;
    scene.materials.push_back(material);
    const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const glm::vec2& corner : corners) {
        scene::Vertex v;
        v.position = glm::vec3(corner, 0.0f);
        v.normal = glm::vec3(0.0f, 0.0f, 1.0f);
        v.color = glm::vec4(1.0f, 1.0f, 1.0f, alphaRamp ? 0.5f + 0.5f * corner.x : 1.0f);
        scene.vertices.push_back(v);
    }
    scene.indices = {0, 1, 2, 0, 2, 3};
    scene::Draw draw{.firstIndex = 0, .indexCount = 6, .material = 0};
    draw.world = glm::rotate(glm::mat4(1.0f), glm::radians(alphaRamp ? 3.0f : 17.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    for (const glm::vec2& corner : corners) draw.bounds.extend(glm::vec3(draw.world * glm::vec4(corner, 0.0f, 1.0f)));
    draw.localBounds = {{-1, -1, 0}, {1, 1, 0}};
    scene.bounds = draw.bounds;
    scene.draws.push_back(draw);
    return scene;
}

// The resolved HDR image (linear, premultiplied RGBA) of `scene` at `samples`, 160 × 120, framed
// from the front at 3 m.
CapturedFrame hdrAt(Renderer& renderer, const scene::Scene& scene, uint32_t samples) {
    RenderSettings settings{.width = 160, .height = 120, .floatOutput = true, .scene = &scene};
    settings.camera.orbit = glm::vec3(0.0f, 90.0f, 3.0f);
    settings.msaa = samples;
    return renderer.capture(settings);
}

float red(const CapturedFrame& f, uint32_t x, uint32_t y) { return f.rgba32f[(size_t(y) * f.width + x) * 4]; }

// Whether the 3 × 3 neighbourhood of (x, y) in `f` has a single red value (no edge near it).
bool flat(const CapturedFrame& f, uint32_t x, uint32_t y) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (red(f, x + dx, y + dy) != red(f, x, y)) return false;
    return true;
}

bool isQuarter(float v) { return v == 0.0f || v == 0.25f || v == 0.5f || v == 0.75f || v == 1.0f; }

TEST_F(GpuTest, MsaaResolvesAnEdgeToIntermediateValuesAndLeavesFlatInteriorsAsWithout) {
    // Metric: exact values of the resolved linear image. The quad is white (1) on black (0): without
    // MSAA every pixel is 0 or 1; with 4 samples an edge pixel is the share of its samples covered
    // (a quarter step), and every pixel away from an edge is exactly what it is without MSAA.
    const scene::Scene scene = quad(false);
    Renderer renderer(context());
    const CapturedFrame one = hdrAt(renderer, scene, 1);
    const CapturedFrame four = hdrAt(renderer, scene, 4);
    uint32_t edges = 0, interiors = 0;
    for (uint32_t y = 1; y + 1 < one.height; ++y)
        for (uint32_t x = 1; x + 1 < one.width; ++x) {
            const float a = red(one, x, y), b = red(four, x, y);
            ASSERT_TRUE(a == 0.0f || a == 1.0f) << x << "," << y << ": " << a;
            ASSERT_TRUE(isQuarter(b)) << x << "," << y << ": " << b;
            if (b > 0.0f && b < 1.0f) ++edges;
            if (flat(one, x, y)) {
                ++interiors;
                ASSERT_EQ(a, b) << "flat pixel " << x << "," << y << " changed with MSAA";
            }
        }
    std::printf("MSAA 4: %u edge pixels resolved to intermediate values, %u flat pixels unchanged\n", edges, interiors);
    // The quad's outline is some 4 × 75 pixels long: most of its pixels are partly covered.
    EXPECT_GT(edges, 150u);
    EXPECT_GT(interiors, 15000u);
}

TEST_F(GpuTest, MsaaOfALitSceneChangesSilhouettesAndLeavesMostOfTheInteriorsAlone) {
    // The default sphere grid at 4 samples against 1. Inside a sphere a pixel changes only where
    // one of its triangles' edges crosses it: with MSAA both triangles shade it (each at the pixel
    // centre, the one not covering the centre extrapolating its normal) and the resolve averages
    // them by coverage; elsewhere it is shaded once, as without MSAA. Metric, over pixels whose
    // 3 × 3 neighbourhood is covered (alpha 1) without MSAA: at least 60% of them bit-identical in
    // the linear red channel, mean relative difference ≤ 0.5%. Silhouettes: some pixels partly
    // covered (0 < alpha < 1).
    const scene::Scene grid = assets::makeSphereGrid();
    Renderer renderer(context());
    RenderSettings settings{.width = 320, .height = 180, .floatOutput = true, .scene = &grid};
    settings.msaa = 1;
    const CapturedFrame one = renderer.capture(settings);
    settings.msaa = 4;
    const CapturedFrame four = renderer.capture(settings);
    const auto alpha = [](const CapturedFrame& f, uint32_t x, uint32_t y) { return f.rgba32f[(size_t(y) * f.width + x) * 4 + 3]; };
    uint32_t partial = 0;
    std::vector<double> relative;  // over interior pixels
    for (uint32_t y = 1; y + 1 < one.height; ++y)
        for (uint32_t x = 1; x + 1 < one.width; ++x) {
            const float a = alpha(four, x, y);
            partial += a > 0.0f && a < 1.0f;
            bool covered = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) covered = covered && alpha(one, x + dx, y + dy) == 1.0f;
            if (!covered) continue;
            const double r1 = red(one, x, y), r4 = red(four, x, y);
            relative.push_back(std::abs(r4 - r1) / std::max(r1, 1e-3));
        }
    ASSERT_GT(relative.size(), 3000u);
    const double identical = double(std::count(relative.begin(), relative.end(), 0.0)) / double(relative.size());
    double mean = 0.0;
    for (double d : relative) mean += d / double(relative.size());
    std::sort(relative.begin(), relative.end());
    std::printf("sphere grid, MSAA 4 vs 1: %u partly covered pixels; interiors (%zu px): %.1f%% identical, mean %.3f%%, "
                "p99 %.2f%%\n", partial, relative.size(), identical * 100.0, mean * 100.0,
                relative[relative.size() * 99 / 100] * 100.0);
    EXPECT_GT(partial, 500u);
    EXPECT_GE(identical, 0.6);
    EXPECT_LE(mean, 0.005);
}

TEST_F(GpuTest, AlphaToCoverageSmoothsTheCutoffOfAnAlphaMaskedMaterial) {
    // The cutoff line of an alpha ramp: without MSAA the alpha test keeps or drops whole pixels; at
    // 4 samples alpha to coverage keeps a share of the samples of the pixels it crosses, stored
    // with alpha 1 (alphaToOne). Metric: exact quarter steps of the resolved linear image.
    if (!context().alphaToOne()) GTEST_SKIP() << "the device has no alphaToOne: alpha-masked draws keep the alpha test";
    const scene::Scene scene = quad(true);
    Renderer renderer(context());
    const CapturedFrame one = hdrAt(renderer, scene, 1);
    const CapturedFrame four = hdrAt(renderer, scene, 4);
    uint32_t steps = 0, stepsWithout = 0;
    for (uint32_t y = 1; y + 1 < one.height; ++y)
        for (uint32_t x = 1; x + 1 < one.width; ++x) {
            const float a = red(one, x, y), b = red(four, x, y);
            ASSERT_TRUE(isQuarter(b)) << x << "," << y << ": " << b;
            stepsWithout += a > 0.0f && a < 1.0f;
            // The cutoff runs near the image's centre column; the quad's edges are 30+ px away.
            if (std::abs(int(x) - int(one.width / 2)) < 12 && b > 0.0f && b < 1.0f) {
                ++steps;
                EXPECT_EQ(four.rgba32f[(size_t(y) * four.width + x) * 4 + 3], b) << "alpha is not the coverage";
            }
        }
    std::printf("alpha to coverage: %u pixels along the cutoff partly covered (%u without MSAA)\n", steps, stepsWithout);
    EXPECT_EQ(stepsWithout, 0u);
    EXPECT_GT(steps, 40u);
}

TEST_F(GpuTest, EveryFrameVariantIsValidationCleanAtEverySampleCount) {
    // The fixture fails the test on any validation message (synchronization validation included).
    // The variants of the draw passes: forward alone (no environment), forward with the sky
    // composited by the tonemap (sky), forward + skybox (a float capture, or transmission) + transmission
    // background + forward_transmission (TransmissionTest), alpha masks (AlphaBlendModeTest), the
    // skybox switched off (bypassed); each at --msaa 1, 2, 4, 8.
    std::list<scene::Scene> scenes;
    scenes.push_back(assets::makeSphereGrid());
    for (const char* model : {"TransmissionTest/glTF-Binary/TransmissionTest.glb",
                              "AlphaBlendModeTest/glTF-Binary/AlphaBlendModeTest.glb"}) {
        const std::filesystem::path path = ::candela::test::sharedAssets() / "models" / model;
        if (std::filesystem::exists(path)) scenes.push_back(assets::loadGltf(path));
    }
    const assets::Environment sky = assets::makeProceduralSky();
    Renderer renderer(context());
    uint32_t frames = 0;
    enum class Sky { Default, SkyboxPass, SkyboxDisabled };
    for (const scene::Scene& scene : scenes)
        for (const assets::Environment* environment : {static_cast<const assets::Environment*>(nullptr), &sky})
            for (uint32_t samples : {1u, 2u, 4u, 8u})
                for (Sky skyCase : {Sky::Default, Sky::SkyboxPass, Sky::SkyboxDisabled}) {
                    if (!environment && skyCase != Sky::Default) continue;
                    RenderSettings settings{.width = 96, .height = 64, .scene = &scene, .environment = environment};
                    settings.msaa = samples;
                    // A float capture reads the HDR image: the skybox pass draws the sky into it.
                    settings.floatOutput = skyCase != Sky::Default;
                    if (skyCase == Sky::SkyboxDisabled) settings.disabledPasses = {"skybox"};
                    const CapturedFrame frame = renderer.capture(settings);
                    if (settings.floatOutput) ASSERT_EQ(frame.rgba32f.size(), 96u * 64u * 4u);
                    else ASSERT_EQ(frame.rgba8.size(), 96u * 64u * 4u);
                    const uint32_t expected = renderer.msaa(samples).samples;
                    const graph::GraphDecl& decl = renderer.lastGraph().declaration();
                    const auto depth = renderer.lastGraph().findResource("depth");
                    ASSERT_TRUE(depth.has_value());
                    EXPECT_EQ(decl.resources[*depth].texture.samples, expected);
                    EXPECT_EQ(renderer.lastGraph().findResource("hdr_msaa").has_value(), expected > 1);
                    ++frames;
                }
    std::printf("%u frames validation-clean (device sample counts: %s)\n", frames,
                vk::sampleCountList(context().attachmentSampleCounts()).c_str());
}

TEST_F(GpuTest, OnlyAttachmentsThatStayInOneRenderPassAreTransientImages) {
    // #27 item 5: TRANSIENT_ATTACHMENT (and lazily allocated memory, where the device has it) only
    // for an attachment used by one render pass that neither loads nor stores it. With a skybox pass
    // the forward pass stores its multisampled colour and depth for the skybox to load; with the sky
    // in the tonemap or without an environment the forward pass is the only one drawing. The
    // fixture checks validation.
    const scene::Scene grid = assets::makeSphereGrid();
    const assets::Environment sky = assets::makeProceduralSky();
    Renderer renderer(context());
    const auto usage = [&](const char* name) {
        const std::optional<uint32_t> resource = renderer.lastGraph().findResource(name);
        EXPECT_TRUE(resource.has_value()) << name;
        return resource ? renderer.lastTransients().imageUsage(*resource) : VkImageUsageFlags(0);
    };
    constexpr VkImageUsageFlags kTransient = VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    RenderSettings settings{.width = 96, .height = 64, .scene = &grid, .environment = &sky};
    settings.msaa = 4;
    ASSERT_EQ(renderer.msaa(4).samples, 4u);
    settings.floatOutput = true;  // the skybox pass draws the sky into the HDR image (not the tonemap)
    renderer.capture(settings);
    ASSERT_TRUE(renderer.lastGraph().findPass("skybox").has_value());
    EXPECT_EQ(usage("hdr_msaa"), VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
    EXPECT_EQ(usage("depth"), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
    EXPECT_EQ(usage("hdr") & kTransient, 0u);
    // With the sky composited by the tonemap the forward pass is the only one drawing.
    settings.floatOutput = false;
    renderer.capture(settings);
    EXPECT_EQ(usage("hdr_msaa"), VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | kTransient);
    EXPECT_EQ(usage("depth"), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | kTransient);
    settings.environment = nullptr;
    renderer.capture(settings);
    EXPECT_EQ(usage("hdr_msaa"), VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | kTransient);
    EXPECT_EQ(usage("depth"), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | kTransient);
    EXPECT_EQ(usage("hdr") & kTransient, 0u);  // resolved into and sampled by the tonemap
    settings.msaa = 1;
    renderer.capture(settings);
    EXPECT_EQ(usage("depth"), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | kTransient);
    EXPECT_EQ(usage("hdr") & kTransient, 0u);
}

TEST_F(GpuTest, MultisampledAttachmentsAreCountedInTheTransientMemory) {
    // Memory report (issue #15): the graph's transient bytes at 4 samples grow by the multisampled
    // colour and the depth's extra samples, as the device sizes them.
    const scene::Scene grid = assets::makeSphereGrid();
    const assets::Environment sky = assets::makeProceduralSky();
    Renderer renderer(context());
    RenderSettings settings{.width = 320, .height = 180, .scene = &grid, .environment = &sky};
    settings.msaa = 1;
    renderer.capture(settings);
    const VkDeviceSize without = renderer.lastGraph().compiled().bytesRequested;
    settings.msaa = 4;
    renderer.capture(settings);
    const VkDeviceSize with = renderer.lastGraph().compiled().bytesRequested;
    const VkDeviceSize pixels = 320 * 180;
    std::printf("transient memory requested at 320x180: %llu bytes at 1 sample, %llu at 4\n", (unsigned long long)without,
                (unsigned long long)with);
    // RGBA16F × 4 samples plus D32 × 3 more samples, at least.
    EXPECT_GE(with - without, pixels * (8 * 4 + 4 * 3));
}

}  // namespace
}  // namespace candela::test
