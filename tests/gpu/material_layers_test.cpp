// The KHR_materials_* layers in the forward pass: scenes without them keep the core program and
// its variants exactly, the layered program at the core's values draws the core image, and the
// layers keep the white furnace.
#include "gpu_test.h"
#include "test_paths.h"
#include "shading_summary_util.h"
#include "graph_runner.h"
#include "sphere_furnace.h"

#include "../unit/brdf_reference.h"
#include "ibl_maps/sheen_lut.h"
#include "passes/ibl/ibl_sheen_lut_pass.h"
#include "passes/post/readback_pass.h"

#include "assets/builtin_scenes.h"
#include "assets/gltf_loader.h"
#include "render/renderer.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

namespace candela::test {
namespace {

TEST_F(GpuTest, ScenesWithoutLayersKeepTheCoreProgramAndVariants) {
    // The sphere grid and DamagedHelmet at one sample (the variant names are the single-sample
    // ones on any device): the variant lines as they were before the layers existed,
    // and the layered program left out.
    const scene::Scene grid = assets::makeSphereGrid();
    Renderer renderer(context());
    renderer.capture({.width = 64, .height = 36, .scene = &grid, .msaa = 1});
    EXPECT_EQ(lastShading(renderer).draws, 49u);
    EXPECT_EQ(lastShading(renderer).variants, (std::map<std::string, uint32_t>{{"pbr", 49}}));
    EXPECT_TRUE(lastShading(renderer).layered.empty());
    EXPECT_TRUE(renderer.lastPlan()->leavesOut(PlannedPart::SheenLut));
    const std::filesystem::path helmetPath =
        ::candela::test::sharedAssets() / "models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb";
    if (!std::filesystem::exists(helmetPath)) GTEST_SKIP() << "shared asset missing: the helmet half is not run";
    const scene::Scene helmet = assets::loadGltf(helmetPath);
    renderer.capture({.width = 64, .height = 36, .scene = &helmet, .msaa = 1});
    EXPECT_EQ(lastShading(renderer).draws, 1u);
    EXPECT_EQ(lastShading(renderer).variants, (std::map<std::string, uint32_t>{{"pbr+normal-map", 1}}));
    EXPECT_TRUE(lastShading(renderer).layered.empty());
}

TEST_F(GpuTest, LayeredProgramAtTheCoreValuesDrawsTheCoreImage) {
    // The grid with metallic 0 or 1 (where the core and the specification's diffuse weights agree),
    // once plain and once with an IOR a hair from 1.5, which puts every material in the layered
    // program. Metric: max absolute difference per 8-bit channel ≤ 1 level (the two programs
    // round the same formulas differently).
    scene::Scene core = assets::makeSphereGrid();
    for (scene::Material& m : core.materials) m.metallicFactor = m.metallicFactor < 0.5f ? 0.0f : 1.0f;
    scene::Scene layered = core;
    for (scene::Material& m : layered.materials) m.ior = 1.5000001f;
    ASSERT_EQ(layered.materials[0].layers(), uint32_t(scene::kLayerSpecular));
    Renderer renderer(context());
    const CapturedFrame a = renderer.capture({.width = 240, .height = 135, .scene = &core, .msaa = 1});
    const CapturedFrame b = renderer.capture({.width = 240, .height = 135, .scene = &layered, .msaa = 1});
    EXPECT_TRUE(paysFor(renderer, scene::kLayerSpecular, /*exactly=*/true));
    EXPECT_EQ(variantDraws(renderer, "pbr+specular"), 49u);
    ASSERT_EQ(a.rgba8.size(), b.rgba8.size());
    int worst = 0;
    for (size_t i = 0; i < a.rgba8.size(); ++i) worst = std::max(worst, std::abs(int(a.rgba8[i]) - int(b.rgba8[i])));
    EXPECT_LE(worst, 1);
}


// White furnace of the clearcoat: a uniform environment of radiance 1, no lights, multiscatter on;
// the furnace spheres (IblFurnaceTest) with the roughness of each column moved to a coat of weight
// 1 (coat roughness 0 … 1) over a white material of roughness 0.5, dielectric (bottom row) or metal
// (top row), each of which alone reflects exactly 1. The coat takes clearcoat · F_c and the material
// beneath loses as much (shared/brdf_clearcoat.h), so every interior pixel reflects 1.
// Metric: over interior pixels (no uncovered pixel within 2 px) and RGB, max |x − 1| and max x − 1.
// Tolerances: 0.02 (the bound), and never above 1 by more than one RGBA16F step (1/1024).
TEST_F(GpuTest, ClearcoatKeepsTheWhiteFurnace) {
    const assets::Environment env = constantEnvironment(64, 32, glm::vec3(1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    scene::Scene scene = sphereScene(spheres, 64, 32);
    for (size_t i = 0; i < spheres.size(); ++i) {
        scene.materials[i].clearcoatFactor = 1.0f;
        scene.materials[i].clearcoatRoughnessFactor = spheres[i].roughness;
        scene.materials[i].roughnessFactor = 0.5f;
    }
    Renderer renderer(context());
    const RenderSettings settings = furnaceSettings(scene, env);
    const CapturedFrame frame = renderer.capture(settings);
    ASSERT_EQ(frameProblem(frame), "");
    EXPECT_TRUE(paysFor(renderer, scene::kLayerClearcoat));
    expectWhiteFurnace(furnacePixels(frame, scene, settings, spheres), spheres.size(), "clearcoatFurnace");
}


// White furnace of the transmission: the furnace spheres made transmissive (weight 1, thin-walled,
// and with a volume of thickness 0.5 and a white attenuation colour), roughness 0 … 1 across,
// dielectric (bottom) and metal (top), seen over the skybox of a uniform environment of radiance 1
// — so what lies behind each sphere (the transmission background: the sky) is 1 too, at every mip.
// The transmitted light is the transmission lobe's albedo, at most what the Lambert part of the
// dielectric loses (shared/brdf_transmission.h): the metals (which transmit nothing) and the smooth
// dielectric (whose BTDF loses nothing) keep the furnace; the rough dielectrics lose what their
// single-scattering BTDF loses — never above 1, darker the rougher (measured means 0.9995, 0.994,
// 0.89, 0.64, 0.37 across; asserted: lower than the column before, by 0.05 from roughness 0.5 on),
// and at roughness 1 between 0.25 and 0.5 (the lobe's albedo from the LUT there is 0.3 at N·V 1,
// up to 0.6 toward grazing views, plus the reflection). Interior pixels from a frame of the same
// spheres without skybox. Metric and tolerances of the furnace as the clearcoat's.
TEST_F(GpuTest, TransmissionKeepsTheWhiteFurnaceWhereTheBtdfIsSmooth) {
    const assets::Environment env = constantEnvironment(64, 32, glm::vec3(1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    const scene::Scene opaque = sphereScene(spheres, 64, 32);
    Renderer renderer(context());
    const CapturedFrame coverage = renderer.capture(furnaceSettings(opaque, env));
    for (float thickness : {0.0f, 0.5f}) {
        SCOPED_TRACE(thickness == 0.0f ? "thin-walled" : "volume of thickness 0.5");
        scene::Scene scene = opaque;
        for (scene::Material& m : scene.materials) {
            m.transmissionFactor = 1.0f;
            m.thicknessFactor = thickness;
        }
        RenderSettings settings = furnaceSettings(scene, env);
        settings.ibl.skybox = true;
        // Each pass of the loop makes a new scene at the same address: upload it anew.
        renderer.sceneReplaced();
        const CapturedFrame frame = renderer.capture(settings);
        ASSERT_EQ(frameProblem(frame), "");
        EXPECT_TRUE(thickness > 0.0f ? paysFor(renderer, scene::kLayerTransmission | scene::kLayerVolume)
                                     : paysFor(renderer, scene::kLayerTransmission, /*exactly=*/true));
        EXPECT_EQ(renderer.lastPlan()->transmission, TransmissionPlan::SeesOpaqueImage);
        const std::string key = thickness > 0.0f ? "transmissionVolume" : "transmission";
        const std::vector<FurnacePixel> pixels = furnacePixels(frame, scene, settings, spheres, &coverage);
        // The smooth dielectric (sphere 0) and the metals (spheres 5 … 9).
        std::vector<FurnacePixel> kept;
        std::vector<double> sum(spheres.size(), 0.0);
        std::vector<size_t> count(spheres.size(), 0);
        double highest = -1.0;
        for (const FurnacePixel& fp : pixels) {
            if (fp.sphere == 0 || fp.sphere >= 5) kept.push_back({fp.x, fp.y, fp.sphere == 0 ? 0 : fp.sphere - 4, fp.value});
            if (fp.sphere < 0) continue;
            sum[size_t(fp.sphere)] += (fp.value.r + fp.value.g + fp.value.b) / 3.0;
            ++count[size_t(fp.sphere)];
            for (int c = 0; c < 3; ++c) highest = std::max(highest, double(fp.value[c]) - 1.0);
        }
        expectWhiteFurnace(kept, 6, key + "Furnace");
        measured(key + "RoughMaxAboveOne", highest);
        EXPECT_LE(highest, 1.0 / 1024.0);
        for (size_t i = 0; i < 5; ++i) {
            ASSERT_GT(count[i], 1000u) << "sphere " << i;
            const double mean = sum[i] / double(count[i]);
            measured(key + "MeanRoughness" + std::to_string(kRoughness[i]).substr(0, 4), mean);
            if (i > 0) {
                const double previous = sum[i - 1] / double(count[i - 1]);
                EXPECT_LE(mean, previous - (kRoughness[i] >= 0.5f ? 0.05 : 0.002)) << "roughness " << kRoughness[i];
            }
        }
        const double roughest = sum[4] / double(count[4]);
        EXPECT_GE(roughest, 0.25);
        EXPECT_LE(roughest, 0.5);
    }
}

// The stiff cases of transmission and volume, in one frame lit by the studio-like
// environment, a point light behind the spheres and one in front: transmission roughness 0 and 1,
// thickness 0 and 1e6 (the refracted ray leaves far behind the camera's view), attenuation distance
// 1e-6 (all absorbed) and infinity, a black attenuation colour, IOR 1 and 10. Metric: every value of
// the float frame finite and non-negative, alpha in [0, 1] (frameProblem); in the debug view
// `transmission`, a sphere 1e6 thick of attenuation distance 1e-6 lets through only the channel its
// attenuation colour keeps whole, a thin wall some of each.
TEST_F(GpuTest, TransmissionExtremesStayFinite) {
    const assets::Environment env = constantEnvironment(64, 32, glm::vec3(0.5f, 0.7f, 1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    scene::Scene scene = sphereScene(spheres, 64, 32);
    for (size_t i = 0; i < spheres.size(); ++i) {
        scene::Material& m = scene.materials[i];
        m.metallicFactor = 0.0f;
        m.transmissionFactor = 1.0f;
        m.roughnessFactor = i % 2 == 0 ? 0.0f : 1.0f;
        m.ior = i % 3 == 0 ? 1.0f : (i % 3 == 1 ? 10.0f : 1.5f);
        m.thicknessFactor = i < 3 ? 0.0f : (i < 6 ? 1e6f : 1.0f);
        m.attenuationDistance = i % 4 == 0 ? 1e-6f : 0.0f;  // 0: infinite
        m.attenuationColor = i % 5 == 0 ? glm::vec3(0.0f) : glm::vec3(0.5f, 0.8f, 1.0f);
    }
    scene::Light behind, front;
    behind.position = glm::vec3(0.0f, 0.0f, -6.0f);
    behind.intensity = 1e5f;
    front.position = glm::vec3(2.0f, 3.0f, 8.0f);
    front.intensity = 50.0f;
    scene.lights = {behind, front};
    Renderer renderer(context());
    RenderSettings settings = furnaceSettings(scene, env);
    settings.ibl.skybox = true;
    const CapturedFrame frame = renderer.capture(settings);
    EXPECT_EQ(frameProblem(frame), "");
    EXPECT_TRUE(paysFor(renderer, scene::kLayerTransmission | scene::kLayerVolume));
    // The throughput (debug view `transmission`) over the interior pixels of each sphere (taken from
    // a frame of the same spheres made opaque: over a transparent background a transmissive
    // sphere's coverage is below 1). Sphere 4 — 1e6 thick, attenuation distance 1e-6, colour
    // (0.5, 0.8, 1) — lets no red or green through and keeps blue (a colour of 1 absorbs nothing);
    // sphere 1, a thin wall, lets some of every channel through (rough, of IOR 10: the BTDF's albedo,
    // (1 − f0 = 0.33) · A_t at roughness 1, is 0.01-0.1 over its pixels).
    settings.debugView = options::DebugView::Transmission;
    const CapturedFrame throughput = renderer.capture(settings);
    EXPECT_EQ(frameProblem(throughput), "");
    scene::Scene opaque = scene;
    for (scene::Material& m : opaque.materials) m.transmissionFactor = 0.0f;
    const CapturedFrame coverage = renderer.capture(furnaceSettings(opaque, env));
    const std::vector<ChannelRange> range =
        channelRange(furnacePixels(throughput, scene, settings, spheres, &coverage), spheres.size());
    EXPECT_EQ(range[4].highest.r, 0.0f);
    EXPECT_EQ(range[4].highest.g, 0.0f);
    EXPECT_GT(range[4].lowest.b, 0.0f);
    EXPECT_GT(minComponent(range[1].lowest), 0.005f);
}

// The thin film's stiff cases in one frame (KHR_materials_iridescence): thickness 0 (no film),
// 1 nm and 1200 nm, a film of the outside's IOR (1: no first interface), a film of IOR 1.3 under a
// coat (outside 1.5: total internal reflection at grazing views), over white metal (F0 = 1, the
// base IOR's guard) and black, lit by the environment and a 1e5 light. Metric: every value of the
// float frame finite and non-negative, alpha in [0, 1]; the debug views iridescence-thickness and
// -fresnel too, and the film of thickness 0 shows none (black in iridescence-fresnel).
TEST_F(GpuTest, IridescenceExtremesStayFinite) {
    const assets::Environment env = constantEnvironment(64, 32, glm::vec3(0.5f, 0.7f, 1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    scene::Scene scene = sphereScene(spheres, 64, 32);
    const float thicknesses[] = {0.0f, 1.0f, 1200.0f, 400.0f, 400.0f};
    for (size_t i = 0; i < spheres.size(); ++i) {
        scene::Material& m = scene.materials[i];
        m.iridescenceFactor = 1.0f;
        m.iridescenceThicknessMaximum = thicknesses[i % 5];
        m.iridescenceIor = i % 5 == 3 ? 1.0f : 1.3f;
        m.clearcoatFactor = i % 5 == 4 ? 1.0f : 0.0f;
        m.baseColorFactor = i % 2 == 0 ? glm::vec4(1.0f) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    }
    scene::Light light;
    light.position = glm::vec3(0.0f, 4.0f, 6.0f);
    light.intensity = 1e5f;
    scene.lights = {light};
    Renderer renderer(context());
    RenderSettings settings = furnaceSettings(scene, env);
    EXPECT_EQ(frameProblem(renderer.capture(settings)), "");
    EXPECT_TRUE(paysFor(renderer, scene::kLayerIridescence));
    settings.debugView = options::DebugView::IridescenceThickness;
    EXPECT_EQ(frameProblem(renderer.capture(settings)), "");
    settings.debugView = options::DebugView::IridescenceFresnel;
    const CapturedFrame fresnel = renderer.capture(settings);
    EXPECT_EQ(frameProblem(fresnel), "");
    const std::vector<ChannelRange> range = channelRange(furnacePixels(fresnel, scene, settings, spheres), spheres.size());
    EXPECT_EQ(maxComponent(range[0].highest), 0.0f);  // thickness 0: no film anywhere
    EXPECT_GT(maxComponent(range[2].highest), 0.0f);  // 1200 nm: a film
}

// The sheen albedo LUT (ibl_sheen_lut.comp, a midpoint quadrature over the half vector) against
// E(N·V, r) = ∫ f_sheen · N·L dω of the double-precision sheen reference, integrated over the half
// vector on a 16× finer grid in cos θ_h and 8× in φ, at 20 texels (N·V 0 … 1, roughness 0 … 1).
// Metric: |got − expected|. Tolerance: 2e-3 + 0.5% of the expected value (E reaches 4.1 at grazing
// views of the smoothest sheen, where the lobe is sharpest).
TEST_F(GpuTest, SheenLutMatchesTheDoubleReference) {
    constexpr uint32_t kSize = ibl_maps::SheenLut::kSize;
    const passes::IblSheenLutPass pass(context());
    GraphRunner runner(context());
    graph::RenderGraph graph;
    // R32F, or RGBA16F where R32F is not linearly filterable (the minimum device profile).
    const VkFormat format = passes::IblSheenLutPass::format(context());
    const graph::TextureId lut = graph.createTexture("sheen_lut", {.width = kSize, .height = kSize, .format = format});
    const uint32_t texelBytes = graph::formatTexelSize(format);
    const graph::BufferId target = runner.readbackBuffer(graph, "sheen lut readback", texelBytes * kSize * kSize);
    passes::addReadbackPass(graph, pass.add(graph, lut), target);
    runner.run(graph);
    std::vector<float> texels;
    if (format == VK_FORMAT_R32_SFLOAT) {
        texels = runner.read<float>(target);
    } else {
        const std::vector<uint16_t> halves = runner.read<uint16_t>(target);
        for (size_t i = 0; i < halves.size(); i += 4) texels.push_back(glm::unpackHalf1x16(halves[i]));
    }
    const auto reference = [](double NoV, double roughness) {
        const glm::dvec3 n(0.0, 0.0, 1.0), v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
        constexpr int kU = 2048, kPhi = 256;
        const double du = 1.0 / kU, dphi = std::numbers::pi / kPhi;
        double sum = 0.0;
        for (int i = 0; i < kU; ++i) {
            const double u = (i + 0.5) * du, s = std::sqrt(1.0 - u * u);
            for (int j = 0; j < kPhi; ++j) {
                const double phi = (j + 0.5) * dphi;
                const glm::dvec3 h(s * std::cos(phi), s * std::sin(phi), u);
                const double VoH = glm::dot(v, h);
                if (VoH <= 0.0) continue;
                const glm::dvec3 l = 2.0 * VoH * h - v;
                if (l.z <= 0.0) continue;
                sum += reference::sheenTimesCosine(n, v, glm::normalize(l), roughness) * 4.0 * VoH;
            }
        }
        return 2.0 * sum * du * dphi;
    };
    double worst = 0.0;
    for (uint32_t x : {0u, 3u, 10u, 20u, 31u})
        for (uint32_t y : {0u, 5u, 15u, 31u}) {
            const double NoV = std::max(double(x) / (kSize - 1), 1e-4), roughness = double(y) / (kSize - 1);
            const double expected = reference(NoV, roughness);
            const double got = texels[size_t(y) * kSize + x];
            EXPECT_NEAR(got, expected, 2e-3 + 5e-3 * expected) << "N·V " << NoV << ", roughness " << roughness;
            worst = std::max(worst, std::abs(got - expected) / std::max(expected, 1e-3));
        }
    measured("sheenLutMaxRelativeError", worst);
}

// White furnace of the sheen: the furnace spheres (white, roughness 0.5, dielectric bottom row and
// metal top row, each keeping the furnace alone) under a sheen of roughness 0 … 1 (columns), white
// in one frame and coloured (1, 0.5, 0.2) in another; uniform environment of radiance 1, no lights.
// The sheen reflects E(N·V) of the environment and the material beneath loses max(colour) · E.
// Metric: over interior pixels, max |x − 1| of the brightest channel (red) and max x − 1 of any.
// Tolerances: 0.02 (the bound) and one RGBA16F step above 1 (1/1024).
TEST_F(GpuTest, SheenKeepsTheWhiteFurnace) {
    const assets::Environment env = constantEnvironment(64, 32, glm::vec3(1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    Renderer renderer(context());
    for (const glm::vec3& color : {glm::vec3(1.0f), glm::vec3(1.0f, 0.5f, 0.2f)}) {
        scene::Scene scene = sphereScene(spheres, 64, 32);
        for (size_t i = 0; i < spheres.size(); ++i) {
            scene.materials[i].sheenColorFactor = color;
            scene.materials[i].sheenRoughnessFactor = spheres[i].roughness;
            scene.materials[i].roughnessFactor = 0.5f;
        }
        const RenderSettings settings = furnaceSettings(scene, env);
        renderer.sceneReplaced();  // each colour's scene is a new one at the same address
        const CapturedFrame frame = renderer.capture(settings);
        ASSERT_EQ(frameProblem(frame), "");
        EXPECT_TRUE(paysFor(renderer, scene::kLayerSheen));
        EXPECT_TRUE(renderer.iblMaps().lastFrame().sheen);
        EXPECT_TRUE(renderer.lastPlan()->sheenLut);
        double worst = 0.0, highest = -1.0;
        size_t count = 0;
        for (const FurnacePixel& fp : furnacePixels(frame, scene, settings, spheres)) {
            if (fp.sphere < 0) continue;
            ++count;
            worst = std::max(worst, std::abs(double(fp.value.r) - 1.0));
            for (int c = 0; c < 3; ++c) highest = std::max(highest, double(fp.value[c]) - 1.0);
        }
        const std::string which = color == glm::vec3(1.0f) ? "white" : "coloured";
        EXPECT_GT(count, 10000u);
        measured("sheenFurnaceMaxAbsError." + which, worst);
        measured("sheenFurnaceMaxAboveOne." + which, highest);
        EXPECT_LE(worst, 0.02) << which;
        EXPECT_LE(highest, 1.0 / 1024.0) << which;
    }
}

}  // namespace
}  // namespace candela::test
