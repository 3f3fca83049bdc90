// Specialization at load (shader/specialize.h) on the layered forward program: frozen constants
// fold away the code of the layers a variant lacks, and with it their descriptors; constants not
// frozen stay specialization constants.
#include "shader/builtin_shaders.h"
#include "shader/reflection.h"
#include "shader/specialize.h"
#include "shared/aov_targets.h"
#include "shared/shading_tables.h"
#include "shared/specialization_ids.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace candela::shader {
namespace {

constexpr uint32_t kLayersId = CANDELA_SPEC_LAYERS, kDebugViewId = CANDELA_SPEC_DEBUG_VIEW;

bool declares(const ShaderReflection& r, const std::string& name) {
    return std::any_of(r.bindings.begin(), r.bindings.end(), [&](const DescriptorBinding& b) { return b.name == name; });
}

uint32_t samplers(const ShaderReflection& r) {
    uint32_t n = 0;
    for (const DescriptorBinding& b : r.bindings) n += b.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER ? b.count : 0;
    return n;
}

// Whether `spirv` still decorates a constant with SpecId `id`.
bool hasSpecId(const std::vector<uint32_t>& spirv, uint32_t id) {
    for (size_t i = 5; i < spirv.size(); i += spirv[i] >> 16)
        if ((spirv[i] & 0xFFFFu) == 71 && (spirv[i] >> 16) == 4 && spirv[i + 2] == 1 && spirv[i + 3] == id) return true;
    return false;
}

TEST(Specialize, FreezingTheLayersRemovesTheTexturesOfTheOthers) {
    const std::span<const uint32_t> generic = builtinShader("forward_layers.frag");
    const ShaderReflection all = reflectSpirv(generic, "generic");
    EXPECT_EQ(samplers(all), 25u);  // 5 core, 14 layer textures, 3 IBL maps, 3 layer maps

    const FrozenConstant sheen[] = {{kLayersId, CANDELA_LAYER_SHEEN}};
    const std::vector<uint32_t> spirv = specializeSpirv(generic, sheen, "sheen");
    const ShaderReflection r = reflectSpirv(spirv, "sheen");
    EXPECT_TRUE(declares(r, "sheenColorTexture"));
    EXPECT_TRUE(declares(r, "sheenRoughnessTexture"));
    EXPECT_TRUE(declares(r, "sheenLut"));
    EXPECT_TRUE(declares(r, "sheenCube"));
    EXPECT_FALSE(declares(r, "clearcoatTexture"));
    EXPECT_FALSE(declares(r, "transmissionBackground"));
    EXPECT_FALSE(declares(r, "iridescenceThicknessTexture"));
    // The core textures and IBL maps stay: their use hangs on constants that were not frozen.
    for (const char* name : {"baseColorTexture", "normalTexture", "emissiveTexture", "specularCube", "irradianceCube"})
        EXPECT_TRUE(declares(r, name)) << name;
    EXPECT_LE(samplers(r), 16u) << "fits the per-stage samplers every Vulkan device has";
    EXPECT_FALSE(hasSpecId(spirv, kLayersId));
    EXPECT_TRUE(hasSpecId(spirv, kDebugViewId));
}

TEST(Specialize, EveryOneLayerVariantFitsSixteenSamplers) {
    const std::span<const uint32_t> generic = builtinShader("forward_layers.frag");
    for (uint32_t bit = 1; bit <= 0x80u; bit <<= 1) {
        const FrozenConstant layer[] = {{kLayersId, bit}};
        const uint32_t count = samplers(reflectSpirv(specializeSpirv(generic, layer, "layer"), "layer"));
        std::printf("[ measured ] layer bit %u: %u samplers\n", bit, count);
        EXPECT_LE(count, 16u) << "layer bit " << bit;
    }
}

TEST(Specialize, AVariantWithEveryLayerKeepsEveryTexture) {
    const std::span<const uint32_t> generic = builtinShader("forward_layers.frag");
    const FrozenConstant every[] = {{kLayersId, 0xFFu}};
    const ShaderReflection r = reflectSpirv(specializeSpirv(generic, every, "every"), "every");
    EXPECT_EQ(samplers(r), 23u);
}

TEST(Specialize, ConstantsTheShaderDoesNotDeclareAreIgnored) {
    const std::span<const uint32_t> pattern = builtinShader("pattern.comp");
    const FrozenConstant unknown[] = {{77, 1}};
    const ShaderReflection r = reflectSpirv(specializeSpirv(pattern, unknown, "pattern"), "pattern");
    EXPECT_TRUE(declares(r, "outImage"));
}

TEST(Specialize, MalformedSpirvIsAnErrorNotACrash) {
    const uint32_t truncated[] = {0x07230203u, 0x00010600u, 0, 10, 0, (9u << 16) | 71u, 1};
    const FrozenConstant any[] = {{kLayersId, 1}};
    EXPECT_THROW(specializeSpirv(truncated, any, "truncated"), std::runtime_error);
}

// The Location of each fragment output the entry point names (the interface a pipeline sees).
std::vector<uint32_t> outputLocations(const std::vector<uint32_t>& spirv) {
    std::vector<uint32_t> interface, outputs, locations;
    for (size_t i = 5; i < spirv.size(); i += spirv[i] >> 16) {
        const uint32_t words = spirv[i] >> 16, opcode = spirv[i] & 0xFFFFu;
        if (opcode == 15) {  // OpEntryPoint: model, id, a nul-terminated name, then the interface
            size_t at = i + 3;
            while (at < i + words && (spirv[at] >> 24) != 0) ++at;
            interface.assign(spirv.begin() + long(at + 1), spirv.begin() + long(i + words));
        }
        if (opcode == 59 && spirv[i + 3] == 3) outputs.push_back(spirv[i + 2]);  // OpVariable, Output
    }
    for (size_t i = 5; i < spirv.size(); i += spirv[i] >> 16)
        if ((spirv[i] & 0xFFFFu) == 71 && spirv[i + 2] == 30 &&
            std::find(outputs.begin(), outputs.end(), spirv[i + 1]) != outputs.end() &&
            std::find(interface.begin(), interface.end(), spirv[i + 1]) != interface.end())
            locations.push_back(spirv[i + 3]);
    std::sort(locations.begin(), locations.end());
    return locations;
}

// The aov pass's program: frozen to the targets a frame asks for, it keeps only their outputs, which
// the remap packs into the attachments' locations.
TEST(Specialize, TheAovProgramKeepsTheTargetsAskedForPacked) {
    const std::span<const uint32_t> generic = builtinShader("aov.frag");
    EXPECT_EQ(outputLocations({generic.begin(), generic.end()}).size(), size_t(CANDELA_AOV_TARGET_COUNT));
    const FrozenConstant targets[] = {{CANDELA_SPEC_AOV_TARGETS, (1u << CANDELA_AOV_NORMAL) | (1u << CANDELA_AOV_INSTANCE)}};
    const std::vector<uint32_t> frozen = specializeSpirv(generic, targets, "aov");
    EXPECT_EQ(outputLocations(frozen), (std::vector<uint32_t>{CANDELA_AOV_NORMAL, CANDELA_AOV_INSTANCE}));
    std::vector<uint32_t> packed(CANDELA_AOV_TARGET_COUNT, CANDELA_AOV_TARGET_COUNT);
    packed[CANDELA_AOV_NORMAL] = 0;
    packed[CANDELA_AOV_INSTANCE] = 1;
    EXPECT_EQ(outputLocations(remapOutputLocations(frozen, packed, "aov")), (std::vector<uint32_t>{0, 1}));
}

}  // namespace
}  // namespace candela::shader
