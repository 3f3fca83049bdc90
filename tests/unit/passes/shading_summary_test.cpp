// What a frame's draws ask of the shading programs (passes/drawing/shading_summary.h): the summary's
// fields from a hand-made scene's draw list, and the --explain words made of them (no GPU).
#include "passes/drawing/shading_summary.h"
#include "passes/draw_list_test_util.h"

#include <gtest/gtest.h>

namespace candela::passes {
namespace {

TEST(ShadingSummary, CountsDrawsPerVariantAndWhatTheSceneUses) {
    scene::Scene scene;
    scene.materials.resize(3);
    scene.materials[0].name = "plain";
    scene.materials[1].name = "coated";
    scene.materials[1].clearcoatFactor = 1.0f;
    scene.materials[2].name = "flat";
    scene.materials[2].unlit = true;
    const glm::vec3 ahead(0.0f, 0.0f, -2.0f);
    scene.draws = {drawAt(0, ahead), drawAt(0, ahead), drawAt(1, ahead), drawAt(2, ahead)};
    const MaterialKeys keys = MaterialKeys::of(scene);
    const DrawList list = buildDrawList({.scene = scene, .keys = keys, .draws = scene.draws, .view = lookingDownMinusZ(),
                                         .targetHeight = 100, .selection = {}, .transmission = true});
    const ShadingSummary s = summarizeShading(list, keys, scene, /*lightCount=*/0, FrameVariant{}, /*posed=*/false);
    EXPECT_EQ(s.draws, 4u);
    EXPECT_EQ(s.instances, 0u);
    uint32_t variantDraws = 0;
    for (const auto& [name, count] : s.variants) variantDraws += count;
    EXPECT_EQ(variantDraws, 4u);
    EXPECT_EQ(s.variants.size(), 3u) << "plain, coated and unlit draw with three variants";
    EXPECT_FALSE(s.lights);
    EXPECT_FALSE(s.normalMaps);
    EXPECT_TRUE(s.unlit);
    EXPECT_EQ(s.layered, (std::vector<ShadingSummary::LayeredMaterial>{{"coated", scene::kLayerClearcoat}}));
}

TEST(ShadingSummary, ExplainsTheSummaryInWords) {
    ShadingSummary s{.draws = 49, .instances = 0, .variants = {{"pbr", 48}, {"pbr+specular", 1}}, .hiddenDraws = 2,
                     .lights = true, .normalMaps = false, .unlit = true};
    s.layered = {{"glass", scene::kLayerTransmission | scene::kLayerVolume}};
    const std::vector<std::string> lines = explainShading(s, DrawList{}, options::DrawSelection{});
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(lines[0], "forward: 49 draws; variants: pbr ×48 pbr+specular ×1");
    EXPECT_EQ(lines[1].rfind("draws: 0 of 0 submitted", 0), 0u) << lines[1];  // describeSelection's line
    EXPECT_EQ(lines[2], "left out: 2 draws of hidden nodes (KHR_node_visibility)");
    EXPECT_EQ(lines[3], "left out: normal mapping / TBN work (no material has a normal texture)");
    EXPECT_EQ(lines[4], "material 'glass' pays for layers: transmission+volume (the layered forward program)");

    s.posed = true;
    s.lights = false;
    s.unlit = true;
    s.normalMaps = true;
    s.layered.clear();
    s.instances = 7;
    EXPECT_EQ(explainShading(s, DrawList{}, options::DrawSelection{}),
              (std::vector<std::string>{
                  "forward: 49 draws (7 instances in instanced draws); variants: pbr ×48 pbr+specular ×1",
                  explainShading(s, DrawList{}, options::DrawSelection{})[1],
                  "animated: draw matrices of this frame's pose, written by the CPU into a per-frame buffer (2 draws "
                  "hidden or scaled to nothing, not drawn)",
                  "left out: light loop (no punctual lights)",
                  "left out: material layers (no material uses a KHR_materials_* layer; core forward program only)"}));
}

}  // namespace
}  // namespace candela::passes
