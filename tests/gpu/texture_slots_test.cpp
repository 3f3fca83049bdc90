// GpuScene's uploads walk the texture tables (shaders/shared/shading_tables.h): a material whose
// every slot names an image and a KHR_texture_transform of its own gets each image bound in its
// slot and each transform in its slot of MaterialData / MaterialLayerData; a material without
// textures gets the defaults, a flat normal in the normal-map slots and white in the others. The
// tables against the shaders' bindings: tests/unit/passes/shading_tables_test.cpp.
#include "gpu_test.h"

#include "gpu_scene/gpu_scene.h"

#include <set>
#include <string>

namespace candela::test {
namespace {

TEST_F(GpuTest, GpuSceneUploadsEveryTextureSlotOfTheTables) {
    scene::Scene scene;
    scene::Material textured{.name = "every slot"};
    // Image i (one texel of red i), offset (i, 0.5), to the next slot.
    const auto give = [&](scene::TextureRef& ref) {
        const int i = int(scene.images.size());
        scene.images.push_back({.name = "slot " + std::to_string(i), .width = 1, .height = 1, .rgba8 = {uint8_t(i), 0, 0, 255}});
        ref.image = i;
        ref.transform.offset = glm::vec2(float(i), 0.5f);
    };
    for (const scene::TextureSlot& slot : scene::kCoreTextureSlots) give(textured.*slot.field);
    for (const scene::TextureSlot& slot : scene::kLayerTextureSlots) give(textured.*slot.field);
    textured.clearcoatFactor = 1.0f;  // a layer, so that the layer parameters are uploaded
    scene.materials = {textured, scene::Material{.name = "no textures"}};
    const gpu_scene::GpuScene gpu(context(), scene);

    std::set<VkImageView> views;
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) {
        views.insert(gpu.texture(0, slot).view);
        EXPECT_EQ(gpu.sceneMaterials()[0].uv[slot].r0.z, float(slot)) << scene::kCoreTextureSlots[slot].sampler;
    }
    ASSERT_EQ(gpu.sceneMaterialLayers().size(), 2u);
    for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) {
        views.insert(gpu.layerTexture(0, slot).view);
        EXPECT_EQ(gpu.sceneMaterialLayers()[0].uv[slot].r0.z, float(CANDELA_TEX_COUNT + slot))
            << scene::kLayerTextureSlots[slot].sampler;
    }
    EXPECT_EQ(views.size(), scene.images.size()) << "each slot bound to its own image";

    const VkImageView flat = gpu.texture(1, CANDELA_TEX_NORMAL).view;
    const VkImageView white = gpu.texture(1, CANDELA_TEX_BASE_COLOR).view;
    EXPECT_NE(flat, white);
    EXPECT_FALSE(views.count(flat) || views.count(white));
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot)
        EXPECT_EQ(gpu.texture(1, slot).view, scene::kCoreTextureSlots[slot].normalMap ? flat : white)
            << scene::kCoreTextureSlots[slot].sampler;
    for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot)
        EXPECT_EQ(gpu.layerTexture(1, slot).view, scene::kLayerTextureSlots[slot].normalMap ? flat : white)
            << scene::kLayerTextureSlots[slot].sampler;
}

}  // namespace
}  // namespace candela::test
