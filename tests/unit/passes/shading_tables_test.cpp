// The shading's tables (shaders/shared/shading_tables.h), walked row by row against what is
// made of them: scene::Material's texture fields and slot accessors, the constants the shaders
// index with, the samplers the built-in forward programs declare (their SPIR-V reflection), the
// layer bits and names, and the debug views. GpuScene's uploads of every slot need a device:
// tests/gpu/texture_slots_test.cpp.
#include "options/debug_view.h"
#include "scene/scene.h"
#include "shader/builtin_shaders.h"
#include "shader/reflection.h"
#include "shared/scene_data.h"

#include <gtest/gtest.h>

#include <bit>
#include <map>
#include <set>
#include <span>
#include <string>

namespace candela::test {
namespace {

static_assert(std::size(shading::MaterialData{}.uv) == std::size(scene::kCoreTextureSlots));
static_assert(std::size(shading::MaterialLayerData{}.uv) == std::size(scene::kLayerTextureSlots));

// Row `slot` of `table` as the table macro states it, and its constant (CANDELA_TEX_*) is its slot.
void expectRow(std::span<const scene::TextureSlot> table, int slot, int constant, scene::TextureRef scene::Material::*field,
               uint32_t binding, bool normalMap) {
    EXPECT_EQ(constant, slot);
    ASSERT_LT(size_t(slot), table.size());
    EXPECT_EQ(table[size_t(slot)].field, field) << table[size_t(slot)].sampler << ": rows in slot order";
    EXPECT_EQ(table[size_t(slot)].binding, binding) << table[size_t(slot)].sampler;
    EXPECT_EQ(table[size_t(slot)].normalMap, normalMap) << table[size_t(slot)].sampler;
}

TEST(ShadingTables, TextureSlotsAreRowsInSlotOrder) {
#define CANDELA_CORE_ROW(NAME, field, slot, binding, normalMap) \
    expectRow(scene::kCoreTextureSlots, slot, CANDELA_TEX_##NAME, &scene::Material::field, binding, normalMap);
#define CANDELA_LAYER_ROW(NAME, field, slot, binding, normalMap) \
    expectRow(scene::kLayerTextureSlots, slot, CANDELA_LAYER_TEX_##NAME, &scene::Material::field, binding, normalMap);
    CANDELA_CORE_TEXTURES(CANDELA_CORE_ROW)
    CANDELA_LAYER_TEXTURES(CANDELA_LAYER_ROW)
#undef CANDELA_CORE_ROW
#undef CANDELA_LAYER_ROW
    EXPECT_EQ(CANDELA_TEX_COUNT, 5);
    EXPECT_EQ(CANDELA_LAYER_TEX_COUNT, 14);
}

TEST(ShadingTables, MaterialReadsEachSlotFromItsOwnField) {
    scene::Material m;
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) (m.*scene::kCoreTextureSlots[slot].field).image = 100 + slot;
    for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) (m.*scene::kLayerTextureSlots[slot].field).image = 200 + slot;
    std::set<int> images;  // every field written once: no two rows name the same field
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) {
        EXPECT_EQ(m.texture(slot).image, 100 + slot);
        images.insert(m.texture(slot).image);
    }
    for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) {
        EXPECT_EQ(m.layerTexture(slot).image, 200 + slot);
        images.insert(m.layerTexture(slot).image);
    }
    EXPECT_EQ(images.size(), size_t(CANDELA_TEX_COUNT + CANDELA_LAYER_TEX_COUNT));
    EXPECT_EQ(m.normal.image, 100 + CANDELA_TEX_NORMAL);
    EXPECT_EQ(m.clearcoatNormal.image, 200 + CANDELA_LAYER_TEX_CLEARCOAT_NORMAL);
}

// Set 1 of built-in shader `name`: binding → (name, type).
std::map<uint32_t, std::pair<std::string, VkDescriptorType>> materialSet(const std::string& name) {
    std::map<uint32_t, std::pair<std::string, VkDescriptorType>> out;
    for (const shader::DescriptorBinding& b : shader::reflectSpirv(shader::builtinShader(name), name).bindings)
        if (b.set == 1) out[b.binding] = {b.name, b.type};
    return out;
}

TEST(ShadingTables, ForwardProgramsDeclareEverySlotAtItsBinding) {
    std::map<uint32_t, std::pair<std::string, VkDescriptorType>> core, layered;
    for (const scene::TextureSlot& slot : scene::kCoreTextureSlots)
        core[slot.binding] = layered[slot.binding] = {slot.sampler, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
    layered[5] = {"MaterialLayers", VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
    for (const scene::TextureSlot& slot : scene::kLayerTextureSlots)
        layered[slot.binding] = {slot.sampler, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
    EXPECT_EQ(layered.size(), size_t(1 + CANDELA_TEX_COUNT + CANDELA_LAYER_TEX_COUNT)) << "bindings shared by two rows";
    EXPECT_EQ(materialSet("forward.frag"), core);
    EXPECT_EQ(materialSet("forward_reference.frag"), core);
    EXPECT_EQ(materialSet("forward_layers.frag"), layered);
}

TEST(ShadingTables, LayerBitsAreDistinctAndNamedInBitOrder) {
    uint32_t all = 0;
    std::vector<std::string_view> names;
#define CANDELA_LAYER_ROW(NAME, Name, bit, name)                                  \
    EXPECT_EQ(uint32_t(scene::kLayer##Name), CANDELA_LAYER_##NAME);               \
    EXPECT_EQ(std::popcount(uint32_t(bit)), 1) << name;                           \
    EXPECT_EQ(all & (bit), 0u) << name;                                           \
    EXPECT_GT(uint32_t(bit), all) << name << ": rows in bit order";               \
    all |= (bit);                                                                 \
    names.push_back(name);                                                        \
    EXPECT_EQ(scene::layerNames(bit), std::vector<std::string_view>{name});
    CANDELA_LAYER_BITS(CANDELA_LAYER_ROW)
#undef CANDELA_LAYER_ROW
    EXPECT_EQ(scene::layerNames(all), names);
    EXPECT_EQ(scene::layerNames(all).size(), 10u);
}

TEST(ShadingTables, DebugViewsRoundTripTheirNamesInValueOrder) {
    uint32_t expected = 0;
    for (const options::DebugViewRow& row : options::kDebugViews) {
        EXPECT_EQ(uint32_t(row.view), expected++) << row.name << ": kDebugView values count up from none";
        EXPECT_EQ(options::parseDebugView(row.name), row.view) << row.name;
        EXPECT_STREQ(options::debugViewName(row.view), row.name);
        EXPECT_EQ(options::debugViewIsLight(row.view), row.light) << row.name;
    }
    EXPECT_EQ(options::allDebugViews().size(), std::size(options::kDebugViews) - 1);
    EXPECT_EQ(options::parseDebugView("anisotropy-direction"), options::DebugView::Anisotropy);
    EXPECT_FALSE(options::parseDebugView("anisotropy"));
    for (options::DebugView light : {options::DebugView::Diffuse, options::DebugView::Specular, options::DebugView::Clearcoat,
                                    options::DebugView::Sheen})
        EXPECT_TRUE(options::debugViewIsLight(light));
}

}  // namespace
}  // namespace candela::test
