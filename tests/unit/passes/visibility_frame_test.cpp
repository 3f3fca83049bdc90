// The visibility path's per-frame tables (passes/visibility/visibility_frame.h): shading lists by
// variant and texture set, the per-entry table the compute shading reads, the tiling (no GPU).
#include "passes/visibility/visibility_frame.h"

#include <gtest/gtest.h>

namespace candela::passes {
namespace {

MaterialKeys keysOf(std::vector<MaterialKey> keys) {
    MaterialKeys out;
    out.keys = std::move(keys);
    for (uint32_t i = 0; i < out.keys.size(); ++i) out.ofMaterial.push_back(i);
    return out;
}

DrawListItem item(uint32_t draw, uint32_t material, uint32_t key, uint32_t drawData, uint32_t instances = 1) {
    return {.draw = draw, .material = material, .key = key, .firstIndex = 3 * draw, .indexCount = 3, .drawData = drawData,
            .instances = instances};
}

TEST(VisibilityFrame, ShadingVariantDropsWhatOnlyRasterizationUses) {
    const ShadingVariant masked{.alphaMask = true, .samples = 4, .alphaToCoverage = true};
    const ShadingVariant v = computeShadingVariant(masked);
    EXPECT_FALSE(v.alphaMask);
    EXPECT_FALSE(v.alphaToCoverage);
    EXPECT_EQ(v.samples, 4u);
    EXPECT_EQ(computeShadingVariant(ShadingVariant{.blend = true}), ShadingVariant{});
}

TEST(VisibilityFrame, ListsAreVariantsTimesTextureSets) {
    // Keys 0 and 1 differ only in the alpha test (one shading variant); key 2 has a normal map.
    const MaterialKeys keys = keysOf({{}, {.alphaMask = true}, {.normalMap = true}});
    const std::vector<uint32_t> textureSetOf = {0, 0, 1, 0};  // per material
    // Materials 0 and 1 (texture set 0) share a list; material 2 (key 2, set 1) has its own;
    // material 3 (key 0, set 0) joins the first.
    std::vector<DrawListItem> items = {item(0, 0, 0, 0), item(1, 1, 1, 1), item(2, 2, 2, 2), item(3, 3, 0, 5, 3)};
    items[3].key = 0;
    const auto tables = visibilityFrameTables(items, keys, textureSetOf, FrameVariant{.lights = true}, {});
    ASSERT_TRUE(tables);
    ASSERT_EQ(tables->lists.size(), 2u);
    EXPECT_EQ(tables->lists[0].textureSet, 0u);
    EXPECT_EQ(tables->lists[0].items, 3u);
    EXPECT_TRUE(tables->lists[1].variant.normalMap);
    EXPECT_EQ(tables->lists[1].textureSet, 1u);
    // Indexed like the draw buffer: the instanced draw fills entries 5, 6, 7; 3 and 4 stay empty.
    ASSERT_EQ(tables->draws.size(), 8u);
    EXPECT_EQ(tables->draws[1].list, 0u);
    EXPECT_EQ(tables->draws[2].list, 1u);
    for (uint32_t entry = 5; entry < 8; ++entry) {
        EXPECT_EQ(tables->draws[entry].firstIndex, 9u);
        EXPECT_EQ(tables->draws[entry].list, 0u);
    }
    EXPECT_EQ(tables->draws[3].firstIndex, 0u);
    EXPECT_EQ(tables->draws[0].vertexOffset, CANDELA_REST_VERTICES);
}

TEST(VisibilityFrame, DeformedDrawsAndMirroredOnesAreMarked) {
    const MaterialKeys keys = keysOf({{}});
    std::vector<DrawListItem> items = {item(0, 0, 0, 0), item(1, 0, 0, 1)};
    items[1].flipWinding = true;
    const std::vector<int32_t> vertexOffset = {CANDELA_REST_VERTICES, -40};
    const auto tables = visibilityFrameTables(items, keys, std::vector<uint32_t>{0}, FrameVariant{}, vertexOffset);
    ASSERT_TRUE(tables);
    EXPECT_EQ(tables->draws[0].vertexOffset, CANDELA_REST_VERTICES);
    EXPECT_EQ(tables->draws[1].vertexOffset, -40);
    EXPECT_EQ(tables->draws[0].flipWinding, 0u);
    EXPECT_EQ(tables->draws[1].flipWinding, 1u);
}

TEST(VisibilityFrame, MoreListsThanATileMaskHoldsAreRefused) {
    const MaterialKeys keys = keysOf({{}});
    std::vector<DrawListItem> items;
    std::vector<uint32_t> textureSetOf;
    for (uint32_t m = 0; m <= CANDELA_VISIBILITY_MAX_LISTS; ++m) {
        items.push_back(item(m, m, 0, m));
        textureSetOf.push_back(m);  // every material its own textures: a list each
    }
    EXPECT_FALSE(visibilityFrameTables(items, keys, textureSetOf, FrameVariant{}, {}));
    items.pop_back();
    const auto tables = visibilityFrameTables(items, keys, textureSetOf, FrameVariant{}, {});
    ASSERT_TRUE(tables);
    EXPECT_EQ(tables->lists.size(), CANDELA_VISIBILITY_MAX_LISTS);
}

TEST(VisibilityFrame, TilingCoversTheImage) {
    const shading::VisibilityFrame f = visibilityExtent(1281, 720, {8, 8}, 33);
    EXPECT_EQ(f.extent.z, 161u);  // ⌈1281 / 8⌉
    EXPECT_EQ(f.extent.w, 161u * 90u);
    EXPECT_EQ(f.lists.x, 33u);
    EXPECT_EQ(f.lists.y, 2u);  // 33 lists: two words
    EXPECT_EQ(visibilityExtent(8, 8, {8, 1}, 0).lists.y, 1u);
    EXPECT_EQ(visibilityExtent(8, 8, {8, 1}, 0).extent.w, 8u);
    EXPECT_EQ(visibilityTileSize(VK_PHYSICAL_DEVICE_TYPE_CPU), glm::uvec2(8, 1));
    EXPECT_EQ(visibilityTileSize(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU), glm::uvec2(8, 8));
}

}  // namespace
}  // namespace candela::passes
