// The KHR_materials_* layers in the forward pass: scenes without them keep the core program and
// its variants exactly, the layered program at the core's values draws the core image, and the
// layers keep the white furnace.
#include "gpu_test.h"
#include "sphere_furnace.h"

#include "renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace candela::test {
namespace {

bool contains(const std::vector<std::string>& lines, const std::string& part) {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

// The `--explain` line listing the forward pass's variants.
std::string variantLine(const std::vector<std::string>& lines) {
    for (const std::string& l : lines)
        if (l.rfind("forward: ", 0) == 0) return l;
    return {};
}

TEST_F(GpuTest, ScenesWithoutLayersKeepTheCoreProgramAndVariants) {
    // The sphere grid and DamagedHelmet: the variant lines as they were before the layers existed,
    // and the layered program left out.
    const scene::Scene grid = scene::makeSphereGrid();
    const scene::Scene helmet =
        scene::loadGltf(std::filesystem::path(CANDELA_SHARED_ASSETS) / "models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb");
    Renderer renderer(context());
    renderer.capture({.width = 64, .height = 36, .scene = &grid});
    EXPECT_EQ(variantLine(renderer.explain()), "forward: 49 draws; variants: pbr ×49");
    EXPECT_TRUE(contains(renderer.explain(), "left out: material layers"));
    renderer.capture({.width = 64, .height = 36, .scene = &helmet});
    EXPECT_EQ(variantLine(renderer.explain()), "forward: 1 draws; variants: pbr+normal-map ×1");
    EXPECT_TRUE(contains(renderer.explain(), "left out: material layers"));
}

TEST_F(GpuTest, LayeredProgramAtTheCoreValuesDrawsTheCoreImage) {
    // The grid with metallic 0 or 1 (where the core and the specification's diffuse weights agree),
    // once plain and once with an IOR a hair from 1.5, which puts every material in the layered
    // program. Metric: max absolute difference per 8-bit channel ≤ 1 level (the two programs
    // round the same formulas differently).
    scene::Scene core = scene::makeSphereGrid();
    for (scene::Material& m : core.materials) m.metallicFactor = m.metallicFactor < 0.5f ? 0.0f : 1.0f;
    scene::Scene layered = core;
    for (scene::Material& m : layered.materials) m.ior = 1.5000001f;
    ASSERT_EQ(layered.materials[0].layers(), uint32_t(scene::kLayerSpecular));
    Renderer renderer(context());
    const CapturedFrame a = renderer.capture({.width = 240, .height = 135, .scene = &core});
    const CapturedFrame b = renderer.capture({.width = 240, .height = 135, .scene = &layered});
    EXPECT_TRUE(contains(renderer.explain(), "pays for layers: specular"));
    EXPECT_NE(variantLine(renderer.explain()).find("pbr+specular ×49"), std::string::npos) << variantLine(renderer.explain());
    ASSERT_EQ(a.rgba8.size(), b.rgba8.size());
    int worst = 0;
    for (size_t i = 0; i < a.rgba8.size(); ++i) worst = std::max(worst, std::abs(int(a.rgba8[i]) - int(b.rgba8[i])));
    EXPECT_LE(worst, 1);
}


// White furnace of the clearcoat: a uniform environment of radiance 1, no lights, multiscatter on;
// the furnace spheres (IblFurnaceTest) with the roughness of each column moved to a coat of weight
// 1 (coat roughness 0 … 1) over a white material of roughness 0.5, dielectric (bottom row) or metal
// (top row), each of which alone reflects exactly 1. The coat takes clearcoat · F_c and the material
// beneath loses as much (shared/brdf_layers.h), so every interior pixel reflects 1.
// Metric: over interior pixels (no uncovered pixel within 2 px) and RGB, max |x − 1| and max x − 1.
// Tolerances: 0.02 (the bound), and never above 1 by more than one RGBA16F step (1/1024).
TEST_F(GpuTest, ClearcoatKeepsTheWhiteFurnace) {
    const scene::Environment env = constantEnvironment(64, 32, glm::vec3(1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    scene::Scene scene = sphereScene(spheres, 64, 32);
    for (size_t i = 0; i < spheres.size(); ++i) {
        scene.materials[i].clearcoatFactor = 1.0f;
        scene.materials[i].clearcoatRoughnessFactor = spheres[i].roughness;
        scene.materials[i].roughnessFactor = 0.5f;
    }
    Renderer renderer(context());
    RenderSettings settings{.width = 320, .height = 180, .floatOutput = true, .scene = &scene,
                            .camera = furnaceCamera(), .defaultLights = false, .environment = &env,
                            .iblQuality = smallQuality()};
    settings.ibl.skybox = false;
    const CapturedFrame frame = renderer.capture(settings);
    ASSERT_EQ(frameProblem(frame), "");
    EXPECT_TRUE(contains(renderer.explain(), "pays for layers: clearcoat"));
    const scene::ViewSetup view = Renderer::resolveView(scene, settings.camera, 320.0f / 180.0f);
    const std::vector<bool> interior = interiorMask(frame, 2);
    std::vector<size_t> count(spheres.size(), 0);
    double worst = 0.0, highest = -1.0;
    for (uint32_t y = 0; y < frame.height; ++y)
        for (uint32_t x = 0; x < frame.width; ++x) {
            if (!interior[size_t(y) * frame.width + x]) continue;
            const Hit hit = castRay(view, frame.width, frame.height, x, y, spheres);
            ASSERT_GE(hit.sphere, 0) << "interior pixel (" << x << ", " << y << ") misses every sphere";
            ++count[size_t(hit.sphere)];
            const glm::vec4 p = pixel(frame, x, y);
            for (int c = 0; c < 3; ++c) {
                worst = std::max(worst, std::abs(double(p[c]) - 1.0));
                highest = std::max(highest, double(p[c]) - 1.0);
            }
        }
    for (size_t i = 0; i < spheres.size(); ++i) EXPECT_GT(count[i], 1000u) << "sphere " << i;
    measured("clearcoatFurnaceMaxAbsError", worst);
    measured("clearcoatFurnaceMaxAboveOne", highest);
    EXPECT_LE(worst, 0.02);
    EXPECT_LE(highest, 1.0 / 1024.0);
}

}  // namespace
}  // namespace candela::test
