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

namespace candela::shader {
namespace {

TEST(ReflectionAnnotations, SourcesAreKeptInTheBuiltSpirv) {
    const std::vector<std::string> sources = embeddedSources(builtinShader("tonemap.frag"));
    ASSERT_GE(sources.size(), 2u);  // the shader and its headers
    EXPECT_NE(sources[0].find("void main()"), std::string::npos);  // the program's own file first
    const bool hasHeader = std::any_of(sources.begin(), sources.end(), [](const std::string& s) {
        return s.find("struct TonemapParams") != std::string::npos;
    });
    EXPECT_TRUE(hasHeader);
}

TEST(ReflectionAnnotations, PushConstantMembersCarryTheirAnnotations) {
    const ShaderReflection r = reflectSpirv(builtinShader("tonemap.frag"), "tonemap.frag");
    const BlockMember* background = member(r.pushConstants.members, "params.background");
    const BlockMember* exposure = member(r.pushConstants.members, "params.exposureEv");
    const BlockMember* scale = member(r.pushConstants.members, "params.exposureScale");  // set by the pass
    ASSERT_TRUE(background && exposure && scale);
    EXPECT_EQ(background->structName, "TonemapParams");
    EXPECT_TRUE(background->annotation.color);
    EXPECT_EQ(background->offset, 0u);
    EXPECT_EQ(background->vectorSize, 4u);
    EXPECT_EQ(exposure->offset, 16u);
    EXPECT_EQ(exposure->annotation.min, -10.0f);
    EXPECT_EQ(exposure->annotation.max, 10.0f);
    EXPECT_EQ(scale->offset, 20u);
    EXPECT_TRUE(scale->annotation.ignore);
}

TEST(ReflectionAnnotations, StorageBufferElementsOfTheForwardShader) {
    const ShaderReflection r = reflectSpirv(builtinShader("forward.frag"), "forward.frag");
    const auto binding = [&](const std::string& name) -> const DescriptorBinding* {
        for (const DescriptorBinding& b : r.bindings)
            if (b.name == name) return &b;
        return nullptr;
    };
    const DescriptorBinding* lights = binding("Lights");
    ASSERT_NE(lights, nullptr);
    ASSERT_EQ(lights->members.size(), 1u);
    const BlockMember& array = lights->members[0];
    EXPECT_EQ(array.arraySize, 0u);  // runtime-sized
    EXPECT_EQ(array.arrayStride, 64u);
    const BlockMember* color = member(array.elementMembers, "color");
    const BlockMember* intensity = member(array.elementMembers, "intensity");
    const BlockMember* position = member(array.elementMembers, "positionRange");
    ASSERT_TRUE(color && intensity && position);
    EXPECT_TRUE(color->annotation.color);
    EXPECT_EQ(color->offset, 32u);
    EXPECT_EQ(color->vectorSize, 3u);
    EXPECT_EQ(intensity->offset, 44u);
    EXPECT_EQ(intensity->annotation.max, 1000.0f);
    EXPECT_TRUE(position->annotation.ignore);

    const DescriptorBinding* materials = binding("Materials");
    ASSERT_NE(materials, nullptr);
    const BlockMember* roughness = member(materials->members[0].elementMembers, "roughness");
    ASSERT_NE(roughness, nullptr);
    EXPECT_EQ(roughness->offset, 36u);
    EXPECT_EQ(roughness->annotation.min, 0.0f);
    EXPECT_EQ(roughness->annotation.max, 1.0f);
    // The forward push constants: the camera is set by code, the IBL intensity is a slider.
    EXPECT_TRUE(member(r.pushConstants.members, "push.viewProjection")->annotation.ignore);
    EXPECT_EQ(member(r.pushConstants.members, "push.ibl.intensity")->annotation.max, 4.0f);
}

TEST(ReflectionAnnotations, TruncatedOrGarbageSpirvYieldsNoSources) {
    const std::span<const uint32_t> spirv = builtinShader("tonemap.frag");
    for (size_t words : {size_t(0), size_t(3), size_t(5), spirv.size() / 3, spirv.size() / 2})
        EXPECT_NO_THROW(embeddedSources(spirv.subspan(0, words)));
    const uint32_t zeroCount[] = {0x07230203, 0, 0, 0, 0, 0x00000003u, 1, 2};
    EXPECT_TRUE(embeddedSources(zeroCount).empty());
    const uint32_t overlong[] = {0x07230203, 0, 0, 0, 0, (100u << 16) | 3u, 2, 460};
    EXPECT_TRUE(embeddedSources(overlong).empty());
}

}  // namespace
}  // namespace candela::shader
