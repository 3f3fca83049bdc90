// Reflection of the SPIR-V compiled at build time from shaders/.
#include "shader/builtin_shaders.h"
#include "shader/reflection.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace candela::shader {
namespace {

const BlockMember* member(const std::vector<BlockMember>& members, const std::string& name) {
    auto it = std::find_if(members.begin(), members.end(), [&](const BlockMember& m) { return m.name == name; });
    return it == members.end() ? nullptr : &*it;
}

TEST(Reflection, EveryBuiltinShaderReflects) {
    ASSERT_FALSE(builtinShaderNames().empty());
    for (std::string_view name : builtinShaderNames()) EXPECT_NO_THROW(reflectSpirv(builtinShader(name), std::string(name)));
}

TEST(Reflection, PatternComputeStorageImageAndPushConstants) {
    const ShaderReflection r = reflectSpirv(builtinShader("pattern.comp"), "pattern.comp");
    EXPECT_EQ(r.stage, VK_SHADER_STAGE_COMPUTE_BIT);
    ASSERT_EQ(r.bindings.size(), 1u);
    EXPECT_EQ(r.bindings[0].name, "outImage");
    EXPECT_EQ(r.bindings[0].set, 0u);
    EXPECT_EQ(r.bindings[0].binding, 0u);
    EXPECT_EQ(r.bindings[0].type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    // PatternParams { uvec2 extent; float exposure; float pad0; } in std430.
    EXPECT_EQ(r.pushConstants.size, 16u);
    EXPECT_EQ(r.pushConstants.stages, VK_SHADER_STAGE_COMPUTE_BIT);
    const BlockMember* extent = member(r.pushConstants.members, "params.extent");
    const BlockMember* exposure = member(r.pushConstants.members, "params.exposure");
    ASSERT_NE(extent, nullptr);
    ASSERT_NE(exposure, nullptr);
    EXPECT_EQ(extent->offset, 0u);
    EXPECT_EQ(extent->type, BaseType::UInt);
    EXPECT_EQ(extent->vectorSize, 2u);
    EXPECT_EQ(exposure->offset, 8u);
    EXPECT_EQ(exposure->size, 4u);
    EXPECT_EQ(exposure->type, BaseType::Float);
}

TEST(Reflection, MergedGraphicsStagesCombineBindings) {
    const ShaderReflection stages[] = {reflectSpirv(builtinShader("fullscreen.vert"), "fullscreen.vert"),
                                       reflectSpirv(builtinShader("encode.frag"), "encode.frag")};
    const ShaderReflection merged = mergeReflections(stages);
    ASSERT_EQ(merged.bindings.size(), 1u);
    EXPECT_EQ(merged.bindings[0].name, "hdrImage");
    EXPECT_EQ(merged.bindings[0].type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(merged.bindings[0].stages, VK_SHADER_STAGE_FRAGMENT_BIT);
    EXPECT_EQ(merged.pushConstants.size, 0u);
}

TEST(Reflection, MismatchedStagesAreRejected) {
    ShaderReflection a, b;
    a.bindings.push_back({.name = "x", .set = 0, .binding = 0, .type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
    b.bindings.push_back({.name = "y", .set = 0, .binding = 0, .type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER});
    const ShaderReflection both[] = {a, b};
    EXPECT_THROW(mergeReflections(both), std::runtime_error);
}

TEST(Reflection, GarbageIsAnErrorNotACrash) {
    const uint32_t garbage[] = {0xdeadbeef, 1, 2, 3, 4, 5};
    EXPECT_THROW(reflectSpirv(garbage, "garbage"), std::runtime_error);
    EXPECT_THROW(reflectSpirv({}, "empty"), std::runtime_error);
}

}  // namespace
}  // namespace candela::shader
