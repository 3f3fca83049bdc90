// Device profiles narrow a device's capabilities, and the choices read the narrowed caps: checked
// on a made-up generous device (everything a lavapipe-like driver reports) without a device.
#include "vk/device_choices.h"
#include "vk/profile_caps.h"

#include <gtest/gtest.h>

namespace candela::vk {
namespace {

constexpr VkFormatFeatureFlags2 kEverything =
    VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
    VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT |
    VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BLEND_BIT | VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT |
    VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT;

// A device with generous limits, every feature, every format feature and a lazily allocated type.
DeviceCaps generousDevice() {
    DeviceCaps caps;
    caps.limits = {.maxPerStageDescriptorSamplers = 1u << 20,
                   .maxPerStageDescriptorSampledImages = 1u << 20,
                   .maxPerStageDescriptorStorageBuffers = 1u << 20,
                   .maxPerStageDescriptorStorageImages = 1u << 20,
                   .maxPerStageDescriptorUniformBuffers = 1u << 20,
                   .maxPerStageResources = 1u << 20,
                   .maxBoundDescriptorSets = 32,
                   .maxStorageBufferRange = uint64_t(1) << 32,
                   .minStorageBufferOffsetAlignment = 16,
                   .maxUniformBufferRange = 65536,
                   .maxPushConstantsSize = 256,
                   .maxImageDimension2D = 16384,
                   .maxImageDimensionCube = 16384,
                   .maxComputeWorkGroupCount = {1u << 30, 1u << 30, 1u << 30},
                   .maxDrawIndexedIndexValue = ~0u,
                   .maxSamplerAnisotropy = 16,
                   .framebufferColorSampleCounts = 0x7F,
                   .framebufferDepthSampleCounts = 0x7F,
                   .sampledImageIntegerSampleCounts = 0x7F,
                   .maxMemoryAllocationSize = uint64_t(1) << 33,
                   .maxBufferSize = uint64_t(1) << 40,
                   .maxMemoryAllocationCount = 1u << 20};
    caps.features = {.samplerAnisotropy = true, .alphaToOne = true, .fullDrawIndexUint32 = true,
                     .shaderStorageImageExtendedFormats = true, .geometryShader = true};
    caps.extensions = {.memoryBudget = true};
    caps.hostWrittenTextures = true;
    caps.memory.memoryTypeCount = 2;
    caps.memory.memoryTypes[0].propertyFlags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    caps.memory.memoryTypes[1].propertyFlags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT;
    caps.memoryTypeMask = 0x3;
    for (VkFormat f : kCandelaFormats) caps.formats.emplace_back(f, kEverything);
    return caps;
}

TEST(DeviceProfile, NamesRoundTripAndUnknownNamesAreRefused) {
    for (const auto& [profile, name] : options::kDeviceProfileNames) EXPECT_EQ(options::parseDeviceProfile(name), profile) << name;
    EXPECT_FALSE(options::parseDeviceProfile("Minimum").has_value());
    EXPECT_FALSE(options::parseDeviceProfile("").has_value());
}

TEST(DeviceProfile, NativeChangesNothing) {
    const DeviceCaps device = generousDevice();
    const DeviceCaps caps = narrowCaps(device, options::DeviceProfile::Native);
    EXPECT_EQ(caps.limits.maxPerStageDescriptorSamplers, device.limits.maxPerStageDescriptorSamplers);
    EXPECT_EQ(caps.memoryTypeMask, device.memoryTypeMask);
    EXPECT_TRUE(caps.hostWrittenTextures);
    EXPECT_TRUE(chooseForDevice(caps).fallbacks.empty());
}

// Profiles stand for GPUs: their textures go through staging copies, as on a GPU, even on lavapipe.
TEST(DeviceProfile, EveryProfileTakesHostWrittenTexturesAway) {
    for (const auto& [profile, name] : options::kDeviceProfileNames)
        if (profile != options::DeviceProfile::Native) {
            EXPECT_FALSE(narrowCaps(generousDevice(), profile).hostWrittenTextures) << name;
        }
}

TEST(DeviceProfile, MinimumIsWhatVulkan13Guarantees) {
    const DeviceCaps caps = narrowCaps(generousDevice(), options::DeviceProfile::Minimum);
    EXPECT_EQ(caps.limits.maxPerStageDescriptorSamplers, 16u);
    EXPECT_EQ(caps.limits.maxPerStageDescriptorSampledImages, 16u);
    EXPECT_EQ(caps.limits.maxPerStageDescriptorStorageBuffers, 4u);
    EXPECT_EQ(caps.limits.maxStorageBufferRange, uint64_t(128) << 20);
    EXPECT_EQ(caps.limits.minStorageBufferOffsetAlignment, 256u);  // an alignment narrows upwards
    EXPECT_EQ(narrowCaps(generousDevice(), options::DeviceProfile::Desktop).limits.minStorageBufferOffsetAlignment, 16u);
    EXPECT_EQ(caps.limits.maxMemoryAllocationSize, uint64_t(1) << 30);
    EXPECT_EQ(caps.limits.maxBufferSize, uint64_t(1) << 30);
    EXPECT_EQ(caps.limits.maxImageDimension2D, 4096u);
    EXPECT_EQ(caps.limits.maxComputeWorkGroupCount[0], 65535u);
    EXPECT_EQ(caps.limits.maxDrawIndexedIndexValue, (1u << 24) - 1);  // fullDrawIndexUint32 off
    EXPECT_EQ(caps.limits.maxSamplerAnisotropy, 1.0f);                 // samplerAnisotropy off
    EXPECT_EQ(caps.attachmentSampleCounts(), VkSampleCountFlags(VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT));
    EXPECT_FALSE(caps.features.samplerAnisotropy || caps.features.alphaToOne || caps.features.fullDrawIndexUint32 ||
                 caps.features.shaderStorageImageExtendedFormats);
    EXPECT_FALSE(caps.extensions.memoryBudget);
    // The lazily allocated type is hidden; the other stays.
    EXPECT_EQ(caps.memoryTypeMask, 0x1u);
    EXPECT_FALSE(caps.hasMemoryType(VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT));
    // No linear filtering of 32-bit floats; no storage in the extended formats.
    EXPECT_FALSE(caps.supports(VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT));
    EXPECT_FALSE(caps.supports(VK_FORMAT_R32_SFLOAT, VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT));
    EXPECT_FALSE(caps.supports(VK_FORMAT_R16G16_SFLOAT, VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT));
    EXPECT_TRUE(caps.supports(VK_FORMAT_R16G16B16A16_SFLOAT,
                              VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT));
    EXPECT_EQ(missingCapability(caps), "");
}

TEST(DeviceProfile, AProfileOnlyTakesAway) {
    // A device smaller than the desktop profile keeps its own figures under it.
    DeviceCaps small = generousDevice();
    small.limits.maxPerStageDescriptorSamplers = 16;
    small.features.alphaToOne = false;
    const DeviceCaps caps = narrowCaps(small, options::DeviceProfile::Desktop);
    EXPECT_EQ(caps.limits.maxPerStageDescriptorSamplers, 16u);
    EXPECT_FALSE(caps.features.alphaToOne);
    // And a profile's larger figure is not given to it.
    EXPECT_EQ(caps.limits.maxBoundDescriptorSets, 32u);
}

TEST(DeviceProfile, AppleHasSixteenSamplersButManyImagesAndKeepsLazyMemory) {
    const DeviceCaps caps = narrowCaps(generousDevice(), options::DeviceProfile::Apple);
    EXPECT_EQ(caps.limits.maxPerStageDescriptorSamplers, 16u);
    EXPECT_EQ(caps.limits.maxPerStageDescriptorSampledImages, 128u);
    EXPECT_TRUE(caps.hasMemoryType(VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT));
    EXPECT_FALSE(caps.supports(VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT));
    EXPECT_EQ(caps.attachmentSampleCounts(), VkSampleCountFlags(0x7));
}

TEST(DeviceChoices, FallbacksFollowTheMissingFormatFeatures) {
    const DeviceChoices native = chooseForDevice(generousDevice());
    EXPECT_EQ(native.floatCube, VK_FORMAT_R32G32B32A32_SFLOAT);
    EXPECT_EQ(native.sheenLut, VK_FORMAT_R32_SFLOAT);
    EXPECT_EQ(native.brdfLut, VK_FORMAT_R16G16_SFLOAT);

    const DeviceChoices minimum = chooseForDevice(narrowCaps(generousDevice(), options::DeviceProfile::Minimum));
    EXPECT_EQ(minimum.floatCube, VK_FORMAT_R16G16B16A16_SFLOAT);
    EXPECT_EQ(minimum.sheenLut, VK_FORMAT_R16G16B16A16_SFLOAT);
    EXPECT_EQ(minimum.brdfLut, VK_FORMAT_R16G16B16A16_SFLOAT);
    ASSERT_EQ(minimum.fallbacks.size(), 5u);
    EXPECT_NE(minimum.fallbacks[2].find("BRDF LUT: R16G16B16A16_SFLOAT instead of R16G16_SFLOAT (no STORAGE_IMAGE)"),
              std::string::npos)
        << minimum.fallbacks[2];
    // The layered program's 25 samplers exceed 16: its variants are specialized to their layers.
    EXPECT_TRUE(minimum.specializeLayeredProgram);
    EXPECT_NE(minimum.fallbacks[3].find("samplers in the fragment stage, the device allows 16"), std::string::npos)
        << minimum.fallbacks[3];
    // No gl_PrimitiveID in the fragment stage (geometryShader): the forward path only.
    EXPECT_NE(minimum.visibilityUnsupported.find("geometryShader"), std::string::npos) << minimum.visibilityUnsupported;
    EXPECT_NE(minimum.fallbacks[4].find("shading: the forward path only"), std::string::npos) << minimum.fallbacks[4];
    EXPECT_FALSE(native.specializeLayeredProgram);
    EXPECT_TRUE(native.visibilityUnsupported.empty()) << native.visibilityUnsupported;
    // Apple: 16 samplers (but every format): the layered program's fallback, and the forward path
    // only (MoltenVK has no geometry shaders).
    const DeviceChoices apple = chooseForDevice(narrowCaps(generousDevice(), options::DeviceProfile::Apple));
    EXPECT_TRUE(apple.specializeLayeredProgram);
    ASSERT_EQ(apple.fallbacks.size(), 2u);
    EXPECT_NE(apple.visibilityUnsupported.find("geometryShader"), std::string::npos);
    // The desktop report (RTX 4070) has everything the visibility path needs.
    EXPECT_TRUE(chooseForDevice(narrowCaps(generousDevice(), options::DeviceProfile::Desktop)).visibilityUnsupported.empty());

    // Only the missing feature moves a choice: RG16F with storage keeps the BRDF LUT.
    DeviceCaps partial = narrowCaps(generousDevice(), options::DeviceProfile::Minimum);
    for (auto& [format, features] : partial.formats)
        if (format == VK_FORMAT_R16G16_SFLOAT) features |= VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT;
    EXPECT_EQ(chooseForDevice(partial).brdfLut, VK_FORMAT_R16G16_SFLOAT);
}

TEST(DeviceChoices, ADeviceWithoutAFormatCandelaNeedsIsRefusedWithTheReason) {
    DeviceCaps caps = generousDevice();
    for (auto& [format, features] : caps.formats)
        if (format == VK_FORMAT_D32_SFLOAT) features &= ~VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT;
    EXPECT_EQ(missingCapability(caps), "D32_SFLOAT lacks DEPTH_STENCIL_ATTACHMENT (needed for the depth buffer)");
}

shader::DescriptorBinding binding(uint32_t set, uint32_t index, VkDescriptorType type, VkShaderStageFlags stages,
                                  uint32_t count = 1) {
    shader::DescriptorBinding b;
    b.name = "b" + std::to_string(set) + "_" + std::to_string(index);
    b.set = set;
    b.binding = index;
    b.type = type;
    b.count = count;
    b.stages = stages;
    return b;
}

TEST(DeviceChoices, ProgramsOverAPerStageLimitAreNamed) {
    const DeviceCaps minimum = narrowCaps(generousDevice(), options::DeviceProfile::Minimum);
    std::vector<shader::DescriptorBinding> bindings;
    for (uint32_t i = 0; i < 16; ++i)
        bindings.push_back(binding(1, i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT));
    EXPECT_EQ(descriptorLimitViolation(bindings, 128, minimum), "");
    // Vertex-stage samplers count against the vertex stage, not the fragment stage.
    bindings.push_back(binding(2, 0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_VERTEX_BIT));
    EXPECT_EQ(descriptorLimitViolation(bindings, 128, minimum), "");
    bindings.push_back(binding(2, 1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT));
    EXPECT_EQ(descriptorLimitViolation(bindings, 128, minimum),
              "17 samplers in the fragment stage, the device allows 16 (maxPerStageDescriptorSamplers)");
    EXPECT_EQ(descriptorLimitViolation(bindings, 128, generousDevice()), "");
    EXPECT_EQ(descriptorLimitViolation({}, 129, minimum), "129 bytes of push constants, the device allows 128 (maxPushConstantsSize)");
    const std::vector<shader::DescriptorBinding> buffers = {
        binding(0, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT, 5)};
    EXPECT_EQ(descriptorLimitViolation(buffers, 0, minimum),
              "5 storage buffers in the fragment stage, the device allows 4 (maxPerStageDescriptorStorageBuffers)");
}

}  // namespace
}  // namespace candela::vk
