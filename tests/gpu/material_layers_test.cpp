// The KHR_materials_* layers in the forward pass: scenes without them keep the core program and
// its variants exactly, and the layered program at the core's values draws the core image.
#include "gpu_test.h"

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

}  // namespace
}  // namespace candela::test
