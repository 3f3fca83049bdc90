// The frame's draw list (passes/drawing/draw_list.h): selection, ranges, sort keys and material
// keys, on small hand-made scenes (no GPU).
#include "passes/drawing/draw_list.h"
#include "passes/draw_list_test_util.h"
#include "passes/drawing/shading_variant.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace candela::passes {
namespace {

scene::Material material(scene::AlphaMode mode, float transmission = 0.0f, bool unlit = false) {
    scene::Material m;
    m.alphaMode = mode;
    m.transmissionFactor = transmission;
    m.unlit = unlit;
    return m;
}

struct Fixture {
    scene::Scene scene;
    MaterialKeys keys;
    scene::ViewSetup view = lookingDownMinusZ();
    DrawList build(bool transmission = true, options::DrawSelection selection = {}) {
        keys = MaterialKeys::of(scene);
        return buildDrawList({.scene = scene, .keys = keys, .draws = scene.draws, .view = view, .targetHeight = 100,
                              .selection = selection, .transmission = transmission});
    }
};

// Materials: 0 opaque, 1 masked, 2 blended, 3 transmissive (opaque alpha), 4 opaque again.
Fixture mixedScene() {
    Fixture f;
    f.scene.materials = {material(scene::AlphaMode::Opaque), material(scene::AlphaMode::Mask),
                         material(scene::AlphaMode::Blend), material(scene::AlphaMode::Opaque, 1.0f),
                         material(scene::AlphaMode::Opaque)};
    // Interleaved, at growing distance: blended and transmissive draws come out back to front.
    f.scene.draws = {drawAt(2, {0, 0, -3}), drawAt(0, {0, 0, -4}), drawAt(3, {0, 0, -5}), drawAt(1, {0, 0, -6}),
                     drawAt(2, {0, 0, -7}), drawAt(4, {0, 0, -8}), drawAt(3, {0, 0, -9}), drawAt(0, {0, 0, -10})};
    return f;
}

std::vector<uint32_t> drawsOf(std::span<const DrawListItem> items) {
    std::vector<uint32_t> out;
    for (const DrawListItem& item : items) out.push_back(item.draw);
    return out;
}

TEST(MaterialKeys, EqualMaterialsShareAKeyAndDifferentOnesDoNot) {
    Fixture f = mixedScene();
    f.keys = MaterialKeys::of(f.scene);
    ASSERT_EQ(f.keys.ofMaterial.size(), 5u);
    EXPECT_EQ(f.keys.keys.size(), 4u);  // materials 0 and 4 are alike
    EXPECT_EQ(f.keys.ofMaterial[0], f.keys.ofMaterial[4]);
    EXPECT_TRUE(f.keys[1].alphaMask);
    EXPECT_TRUE(f.keys[2].blend);
    EXPECT_TRUE(f.keys[3].transmissive);
    EXPECT_EQ(f.keys[3].layers, uint32_t(scene::kLayerTransmission));
}

TEST(MaterialKeys, UnlitMaterialsPayForNoLayerOrNormalMap) {
    scene::Material m = material(scene::AlphaMode::Opaque, 1.0f, /*unlit=*/true);
    m.normal.image = 0;
    const MaterialKey key = materialKeyOf(m);
    EXPECT_TRUE(key.unlit);
    EXPECT_FALSE(key.normalMap);
    EXPECT_EQ(key.layers, 0u);
    EXPECT_FALSE(key.transmissive);
}

TEST(DrawList, RangesHoldTheirAlphaModesInDrawingOrder) {
    Fixture f = mixedScene();
    const DrawList list = f.build();
    EXPECT_EQ(drawsOf(list.range(DrawRange::Opaque)), (std::vector<uint32_t>{1, 7, 5}));  // by key, then material
    EXPECT_EQ(drawsOf(list.range(DrawRange::Masked)), (std::vector<uint32_t>{3}));
    EXPECT_EQ(drawsOf(list.range(DrawRange::Transmissive)), (std::vector<uint32_t>{6, 2}));  // back to front
    EXPECT_EQ(drawsOf(list.range(DrawRange::Blended)), (std::vector<uint32_t>{4, 0}));       // back to front
    EXPECT_EQ(list.items.size(), 8u);
    // The ranges tile the list in order.
    for (size_t r = 0; r < kDrawRangeCount; ++r) EXPECT_LE(list.rangeStart[r], list.rangeStart[r + 1]);
    EXPECT_EQ(list.rangeStart[kDrawRangeCount], list.items.size());
    EXPECT_EQ(list.ranges(DrawRange::Opaque, DrawRange::Masked).size(), 4u);
}

TEST(DrawList, PointsAndLinesHaveARangeAndKeysOfTheirOwn) {
    Fixture f = mixedScene();
    const auto shaped = [](scene::Draw d, scene::Topology topology, bool unshaded) {
        d.topology = topology;
        d.unshaded = unshaded;
        d.indexCount = 12;
        return d;
    };
    f.scene.draws.push_back(shaped(drawAt(0, {0, 0, -4}), scene::Topology::Lines, true));    // 8: opaque lines, no normals
    f.scene.draws.push_back(shaped(drawAt(1, {0, 0, -4}), scene::Topology::Points, false));  // 9: masked points with normals
    f.scene.draws.push_back(shaped(drawAt(2, {0, 0, -2}), scene::Topology::Lines, false));   // 10: blended lines
    const DrawList list = f.build();
    // Opaque and masked points and lines get their own range (drawn forward on both paths); blended
    // ones blend back to front with the blended triangles.
    EXPECT_EQ(drawsOf(list.range(DrawRange::PointsAndLines)), (std::vector<uint32_t>{8, 9}));
    EXPECT_EQ(drawsOf(list.range(DrawRange::Blended)), (std::vector<uint32_t>{4, 0, 10}));
    EXPECT_EQ(drawsOf(list.range(DrawRange::Opaque)), (std::vector<uint32_t>{1, 7, 5}));
    const MaterialKey& lines = f.keys.keys[list.range(DrawRange::PointsAndLines)[0].key];
    EXPECT_EQ(lines.topology, scene::Topology::Lines);
    EXPECT_TRUE(lines.unlit);  // no normals: unshaded
    const MaterialKey& points = f.keys.keys[list.range(DrawRange::PointsAndLines)[1].key];
    EXPECT_EQ(points.topology, scene::Topology::Points);
    EXPECT_FALSE(points.unlit);
    EXPECT_TRUE(points.alphaMask);
    // The triangles' keys are the materials' own; the variants name their topology.
    EXPECT_EQ(f.keys.keyOf(0, f.scene.draws[0]), f.keys.ofMaterial[0]);
    EXPECT_NE(f.keys.keyOf(0, f.scene.draws[8]), f.keys.ofMaterial[0]);
    EXPECT_EQ(shadingVariant(lines, {}).name(), "unlit+lines");
    EXPECT_EQ(list.stats.submittedTriangles, 8u * 12);
    EXPECT_EQ(list.stats.submittedLines, 12u);  // two line draws of 12 indices: 6 lines each
    EXPECT_EQ(list.stats.submittedPoints, 12u);
}

TEST(DrawList, TransmissiveAndBlendedMergeBackToFront) {
    Fixture f = mixedScene();
    const DrawList list = f.build();
    // What forward_transmission draws: both ranges, farthest first.
    EXPECT_EQ(drawsOf(list.backToFront(DrawRange::Transmissive, DrawRange::Blended)),
              (std::vector<uint32_t>{6, 4, 2, 0}));
}

TEST(DrawList, EqualDepthsKeepTheFirstRangeFirstAndTheScenesOrder) {
    Fixture f;
    f.scene.materials = {material(scene::AlphaMode::Blend), material(scene::AlphaMode::Opaque, 1.0f)};
    f.scene.draws = {drawAt(0, {0, 0, -5}), drawAt(1, {0, 0, -5}), drawAt(0, {0, 0, -5}), drawAt(1, {0, 0, -5})};
    const DrawList list = f.build();
    EXPECT_EQ(drawsOf(list.backToFront(DrawRange::Transmissive, DrawRange::Blended)), (std::vector<uint32_t>{1, 3, 0, 2}));
}

TEST(DrawList, WithoutTransmissionTransmissiveDrawsFollowTheirAlphaMode) {
    Fixture f = mixedScene();
    const DrawList list = f.build(/*transmission=*/false);  // a debug view
    EXPECT_TRUE(list.empty(DrawRange::Transmissive));
    EXPECT_EQ(drawsOf(list.range(DrawRange::Opaque)).size(), 5u);
    const auto opaque = drawsOf(list.range(DrawRange::Opaque));
    EXPECT_NE(std::find(opaque.begin(), opaque.end(), 2u), opaque.end());
}

TEST(DrawList, CullsOutsideTheFrustumAndCountsWhatItSubmits) {
    Fixture f = mixedScene();
    f.scene.draws.push_back(drawAt(0, {0, 0, 5}, 12));   // behind the eye
    f.scene.draws.push_back(drawAt(0, {50, 0, -5}, 12)); // far to the right
    scene::Draw hidden = drawAt(0, {0, 0, -5});
    hidden.hidden = true;
    f.scene.draws.push_back(hidden);
    const DrawList list = f.build();
    EXPECT_EQ(list.items.size(), 8u);
    EXPECT_EQ(list.stats.sceneDraws, 10u);
    EXPECT_EQ(list.stats.culledDraws, 2u);
    EXPECT_EQ(list.stats.submittedDraws, 8u);
    EXPECT_EQ(list.stats.sceneTriangles, 8u * 12 + 2 * 4);
    EXPECT_EQ(list.stats.submittedTriangles, 8u * 12);
    EXPECT_EQ(list.hiddenDraws, 1u);
    EXPECT_EQ(list.draws, 10u);

    const DrawList unculled = f.build(true, {.frustumCulling = false});
    EXPECT_EQ(unculled.items.size(), 10u);
    EXPECT_EQ(unculled.stats.culledDraws, 0u);
}

TEST(DrawList, DrawDataIndicesCountInstances) {
    Fixture f;
    f.scene.materials = {material(scene::AlphaMode::Opaque)};
    f.scene.draws = {drawAt(0, {0, 0, -5}), drawAt(0, {0, 0, -6}), drawAt(0, {0, 0, -7})};
    f.scene.draws[0].instanceCount = 3;  // entries 0..2 of the draw buffer
    f.scene.instances.assign(3, glm::mat4(1.0f));
    const DrawList list = f.build(true, {.frustumCulling = true, .lodErrorPixels = 0.0f});
    std::vector<uint32_t> drawData(3);
    for (const DrawListItem& item : list.items) drawData[item.draw] = item.drawData;
    EXPECT_EQ(drawData, (std::vector<uint32_t>{0, 3, 4}));
    EXPECT_EQ(list.items[0].instances, 3u);
    EXPECT_EQ(list.instances, 3u);
}

TEST(ShadingVariant, TheFramesBitsApplyOnlyToLitMaterials) {
    const FrameVariant frame{.model = options::ShadingModel::BlinnPhong, .lights = true, .ibl = true, .specularAa = true,
                             .samples = 4, .alphaToCoverage = true};
    const ShadingVariant lit = shadingVariant({.alphaMask = true}, frame);
    EXPECT_TRUE(lit.lights && lit.ibl && lit.specularAa && lit.alphaToCoverage);
    EXPECT_EQ(lit.model, options::ShadingModel::BlinnPhong);
    const ShadingVariant unlit = shadingVariant({.unlit = true}, frame);
    EXPECT_FALSE(unlit.lights || unlit.ibl || unlit.specularAa || unlit.alphaToCoverage);
    EXPECT_EQ(unlit.model, options::ShadingModel::Pbr);
    EXPECT_EQ(unlit.samples, 4u);
    EXPECT_EQ(unlit.name(), "unlit+msaa4");
}

}  // namespace
}  // namespace candela::passes
