#include "vk/profile_caps.h"

#include "core/errors.h"

#include <algorithm>
#include <cstdlib>
#include <span>

namespace candela::vk {
namespace {

// Format feature shorthands for the tables below.
constexpr VkFormatFeatureFlags2 S = format_feature::kSampled, L = format_feature::kLinear,
                                ST = format_feature::kStorage, C = format_feature::kColor, B = format_feature::kBlend,
                                D = format_feature::kDepth;
// Blit and transfer: every format with any feature supports transfer (Vulkan 1.1).
constexpr VkFormatFeatureFlags2 X = VK_FORMAT_FEATURE_2_BLIT_SRC_BIT | VK_FORMAT_FEATURE_2_BLIT_DST_BIT |
                                    VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT;
constexpr VkFormatFeatureFlags2 XS = VK_FORMAT_FEATURE_2_BLIT_SRC_BIT | VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT |
                                     VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT;

struct FormatCeiling {
    VkFormat format;
    VkFormatFeatureFlags2 features;
};

struct ProfileData {
    DeviceLimits limits;
    DeviceFeatures features;
    DeviceExtensions extensions;
    bool lazyMemory;  // lazily allocated memory types stay visible
    std::span<const FormatCeiling> formats;
    const char* source;
};

// Vulkan 1.3's required format support ("Required Format Support" in the specification's Formats
// chapter). Depth: the specification requires DEPTH_STENCIL_ATTACHMENT on at least one of
// X8_D24_UNORM_PACK32 and D32_SFLOAT; the profile keeps D32_SFLOAT's (every desktop and Apple
// device has it) and takes X8_D24's away.
constexpr FormatCeiling kMinimumFormats[] = {
    {VK_FORMAT_R8G8B8A8_UNORM, S | L | ST | C | B | X},
    {VK_FORMAT_R8G8B8A8_SRGB, S | L | C | B | X},
    {VK_FORMAT_B8G8R8A8_UNORM, S | L | C | B | X},
    {VK_FORMAT_B8G8R8A8_SRGB, S | L | C | B | X},
    {VK_FORMAT_A2B10G10R10_UNORM_PACK32, S | L | C | B | X},
    {VK_FORMAT_R16_SFLOAT, S | L | C | B | X},
    {VK_FORMAT_R16G16_SFLOAT, S | L | C | B | X},
    {VK_FORMAT_R16G16B16A16_SFLOAT, S | L | ST | C | B | X},
    {VK_FORMAT_R32_SFLOAT, S | ST | C | X},
    {VK_FORMAT_R32G32_SFLOAT, S | ST | C | X},
    {VK_FORMAT_R32G32B32A32_SFLOAT, S | ST | C | X},
    {VK_FORMAT_D32_SFLOAT, S | D | XS},
    {VK_FORMAT_X8_D24_UNORM_PACK32, 0},
    {VK_FORMAT_D16_UNORM, S | D | XS},
    {VK_FORMAT_R32G32_UINT, S | ST | C | X},
};

// Vulkan 1.3's required limits ("Required Limits" in the specification's Limits chapter) and
// maintenance3/maintenance4's 1 GiB for allocations and buffers; every optional feature off.
constexpr ProfileData kMinimum{
    .limits = {.maxPerStageDescriptorSamplers = 16,
               .maxPerStageDescriptorSampledImages = 16,
               .maxPerStageDescriptorStorageBuffers = 4,
               .maxPerStageDescriptorStorageImages = 4,
               .maxPerStageDescriptorUniformBuffers = 12,
               .maxPerStageResources = 128,
               .maxBoundDescriptorSets = 4,
               .maxStorageBufferRange = uint64_t(1) << 27,
               .minStorageBufferOffsetAlignment = 256,
               .maxUniformBufferRange = 16384,
               .maxPushConstantsSize = 128,
               .maxImageDimension2D = 4096,
               .maxImageDimensionCube = 4096,
               .maxComputeWorkGroupCount = {65535, 65535, 65535},
               .maxDrawIndexedIndexValue = (1u << 24) - 1,
               .maxSamplerAnisotropy = 1.0f,
               .framebufferColorSampleCounts = VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT,
               .framebufferDepthSampleCounts = VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT,
               .sampledImageIntegerSampleCounts = VK_SAMPLE_COUNT_1_BIT,
               .maxMemoryAllocationSize = uint64_t(1) << 30,
               .maxBufferSize = uint64_t(1) << 30,
               .maxMemoryAllocationCount = 4096},
    .features = {},
    .extensions = {},
    .lazyMemory = false,
    .formats = kMinimumFormats,
    .source = "Vulkan 1.3 specification: Required Limits, Required Format Support; optional features off"};

// Device reports (vulkan.gpuinfo.org) as stored in KhronosGroup/Vulkan-Profiles, folder
// profiles/VP_LUNARG_desktop_baseline_2023/: the reports' optimal-tiling format features, limits,
// features and extensions. Neither report lists memory types.
constexpr VkFormatFeatureFlags2 kDesktopColor = S | L | ST | C | B | X;
constexpr VkFormatFeatureFlags2 kDesktopDepth = S | L | D | X;

// vp_gpuinfo_nvidia_geforce_rtx_4070_551_61_0_0_windows_11.json (commit e1cf59d9): NVIDIA GeForce
// RTX 4070, driver 551.61, Windows 11, Vulkan 1.3.277. The sRGB formats have no storage.
constexpr FormatCeiling kDesktopFormats[] = {
    {VK_FORMAT_R8G8B8A8_UNORM, kDesktopColor},      {VK_FORMAT_R8G8B8A8_SRGB, kDesktopColor & ~ST},
    {VK_FORMAT_B8G8R8A8_UNORM, kDesktopColor},      {VK_FORMAT_B8G8R8A8_SRGB, kDesktopColor & ~ST},
    {VK_FORMAT_A2B10G10R10_UNORM_PACK32, kDesktopColor}, {VK_FORMAT_R16_SFLOAT, kDesktopColor},
    {VK_FORMAT_R16G16_SFLOAT, kDesktopColor},       {VK_FORMAT_R16G16B16A16_SFLOAT, kDesktopColor},
    {VK_FORMAT_R32_SFLOAT, kDesktopColor},          {VK_FORMAT_R32G32_SFLOAT, kDesktopColor},
    {VK_FORMAT_R32G32B32A32_SFLOAT, kDesktopColor}, {VK_FORMAT_D32_SFLOAT, kDesktopDepth},
    {VK_FORMAT_X8_D24_UNORM_PACK32, kDesktopDepth}, {VK_FORMAT_D16_UNORM, kDesktopDepth},
    {VK_FORMAT_R32G32_UINT, S | ST | C | X},
};
constexpr ProfileData kDesktop{
    .limits = {.maxPerStageDescriptorSamplers = 1048576,
               .maxPerStageDescriptorSampledImages = 1048576,
               .maxPerStageDescriptorStorageBuffers = 1048576,
               .maxPerStageDescriptorStorageImages = 1048576,
               .maxPerStageDescriptorUniformBuffers = 1048576,
               .maxPerStageResources = 4294967295u,
               .maxBoundDescriptorSets = 32,
               .maxStorageBufferRange = 4294967295u,
               .minStorageBufferOffsetAlignment = 0,  // not transcribed: the device's own stands
               .maxUniformBufferRange = 65536,
               .maxPushConstantsSize = 256,
               .maxImageDimension2D = 32768,
               .maxImageDimensionCube = 32768,
               .maxComputeWorkGroupCount = {2147483647u, 65535, 65535},
               .maxDrawIndexedIndexValue = 4294967295u,
               .maxSamplerAnisotropy = 16.0f,
               .framebufferColorSampleCounts = 0xF,  // 1, 2, 4, 8
               .framebufferDepthSampleCounts = 0xF,
               .sampledImageIntegerSampleCounts = 0xF,  // 1, 2, 4, 8
               .maxMemoryAllocationSize = 4292870144u,
               .maxBufferSize = 1099511562240u,
               .maxMemoryAllocationCount = 4096},
    .features = {.samplerAnisotropy = true,
                 .alphaToOne = true,
                 .fullDrawIndexUint32 = true,
                 .shaderStorageImageExtendedFormats = true,
                 .geometryShader = true},
    .extensions = {.memoryBudget = true},
    .lazyMemory = false,
    .formats = kDesktopFormats,
    .source = "gpuinfo report of an NVIDIA GeForce RTX 4070 (driver 551.61, Windows 11) in KhronosGroup/Vulkan-Profiles"};

// vp_gpuinfo_apple_m1_0_2_2015_osx_14_3.json (commit f3c8c9c1): Apple M1 through MoltenVK 1.2.7,
// macOS 14.3, Vulkan 1.2.275 (the report has no maxBufferSize; maxMemoryAllocationSize stands in).
// 16 samplers per stage (Metal's limit without argument buffers) but 128 sampled images; no
// X8_D24 depth. MoltenVK exposes Metal's memoryless storage as a lazily allocated memory type on
// Apple GPUs, so lazily allocated types stay visible.
constexpr FormatCeiling kAppleFormats[] = {
    {VK_FORMAT_R8G8B8A8_UNORM, kDesktopColor},      {VK_FORMAT_R8G8B8A8_SRGB, kDesktopColor},
    {VK_FORMAT_B8G8R8A8_UNORM, kDesktopColor},      {VK_FORMAT_B8G8R8A8_SRGB, kDesktopColor},
    {VK_FORMAT_A2B10G10R10_UNORM_PACK32, kDesktopColor}, {VK_FORMAT_R16_SFLOAT, kDesktopColor},
    {VK_FORMAT_R16G16_SFLOAT, kDesktopColor},       {VK_FORMAT_R16G16B16A16_SFLOAT, kDesktopColor},
    {VK_FORMAT_R32_SFLOAT, kDesktopColor},          {VK_FORMAT_R32G32_SFLOAT, kDesktopColor},
    {VK_FORMAT_R32G32B32A32_SFLOAT, kDesktopColor}, {VK_FORMAT_D32_SFLOAT, kDesktopDepth},
    {VK_FORMAT_X8_D24_UNORM_PACK32, 0},    {VK_FORMAT_D16_UNORM, kDesktopDepth},
    {VK_FORMAT_R32G32_UINT, S | ST | C | X},
};
constexpr ProfileData kApple{
    .limits = {.maxPerStageDescriptorSamplers = 16,
               .maxPerStageDescriptorSampledImages = 128,
               .maxPerStageDescriptorStorageBuffers = 31,
               .maxPerStageDescriptorStorageImages = 8,
               .maxPerStageDescriptorUniformBuffers = 31,
               .maxPerStageResources = 159,
               .maxBoundDescriptorSets = 8,
               .maxStorageBufferRange = 4294967295u,
               .minStorageBufferOffsetAlignment = 0,  // not transcribed: the device's own stands
               .maxUniformBufferRange = 4294967295u,
               .maxPushConstantsSize = 4096,
               .maxImageDimension2D = 16384,
               .maxImageDimensionCube = 16384,
               .maxComputeWorkGroupCount = {1073741824u, 1073741824u, 1073741824u},
               .maxDrawIndexedIndexValue = 4294967295u,
               .maxSamplerAnisotropy = 16.0f,
               .framebufferColorSampleCounts = 0x7,  // 1, 2, 4
               .framebufferDepthSampleCounts = 0x7,
               .sampledImageIntegerSampleCounts = 0x7,  // 1, 2, 4
               .maxMemoryAllocationSize = 8589934592u,
               .maxBufferSize = 8589934592u,
               .maxMemoryAllocationCount = 1073741824u},
    .features = {.samplerAnisotropy = true,
                 .alphaToOne = true,
                 .fullDrawIndexUint32 = true,
                 .shaderStorageImageExtendedFormats = true,
                 .geometryShader = false},
    .extensions = {.memoryBudget = true, .portabilitySubset = true},
    .lazyMemory = true,
    .formats = kAppleFormats,
    .source = "gpuinfo report of an Apple M1 (MoltenVK 1.2.7, macOS 14.3) in KhronosGroup/Vulkan-Profiles"};

const ProfileData* dataOf(options::DeviceProfile profile) {
    switch (profile) {
        case options::DeviceProfile::Minimum: return &kMinimum;
        case options::DeviceProfile::Desktop: return &kDesktop;
        case options::DeviceProfile::Apple: return &kApple;
        default: return nullptr;
    }
}

template <class T>
void lower(T& value, T ceiling) {
    value = std::min(value, ceiling);
}

}  // namespace

const char* deviceProfileSource(options::DeviceProfile profile) {
    const ProfileData* data = dataOf(profile);
    return data ? data->source : "the device as it reports itself";
}

options::DeviceProfile deviceProfileFromEnvironment() {
    const char* value = std::getenv("CANDELA_DEVICE_PROFILE");
    if (!value || !*value) return options::DeviceProfile::Native;
    if (const std::optional<options::DeviceProfile> p = options::parseDeviceProfile(value)) return *p;
    throw UserError(std::string("CANDELA_DEVICE_PROFILE=") + value + ": no such device profile (profiles: " +
                    options::deviceProfileList() + ")");
}

DeviceCaps narrowCaps(const DeviceCaps& device, options::DeviceProfile profile) {
    const ProfileData* data = dataOf(profile);
    if (!data) return device;
    DeviceCaps caps = device;
    DeviceLimits& l = caps.limits;
    const DeviceLimits& p = data->limits;
    lower(l.maxPerStageDescriptorSamplers, p.maxPerStageDescriptorSamplers);
    lower(l.maxPerStageDescriptorSampledImages, p.maxPerStageDescriptorSampledImages);
    lower(l.maxPerStageDescriptorStorageBuffers, p.maxPerStageDescriptorStorageBuffers);
    lower(l.maxPerStageDescriptorStorageImages, p.maxPerStageDescriptorStorageImages);
    lower(l.maxPerStageDescriptorUniformBuffers, p.maxPerStageDescriptorUniformBuffers);
    lower(l.maxPerStageResources, p.maxPerStageResources);
    lower(l.maxBoundDescriptorSets, p.maxBoundDescriptorSets);
    lower(l.maxStorageBufferRange, p.maxStorageBufferRange);
    // An alignment is a floor: the profile's can only make it coarser.
    l.minStorageBufferOffsetAlignment = std::max(l.minStorageBufferOffsetAlignment, p.minStorageBufferOffsetAlignment);
    lower(l.maxUniformBufferRange, p.maxUniformBufferRange);
    lower(l.maxPushConstantsSize, p.maxPushConstantsSize);
    lower(l.maxImageDimension2D, p.maxImageDimension2D);
    lower(l.maxImageDimensionCube, p.maxImageDimensionCube);
    for (int i = 0; i < 3; ++i) lower(l.maxComputeWorkGroupCount[i], p.maxComputeWorkGroupCount[i]);
    lower(l.maxDrawIndexedIndexValue, p.maxDrawIndexedIndexValue);
    lower(l.maxSamplerAnisotropy, p.maxSamplerAnisotropy);
    l.framebufferColorSampleCounts &= p.framebufferColorSampleCounts;
    l.framebufferDepthSampleCounts &= p.framebufferDepthSampleCounts;
    l.sampledImageIntegerSampleCounts &= p.sampledImageIntegerSampleCounts;
    lower(l.maxMemoryAllocationSize, p.maxMemoryAllocationSize);
    lower(l.maxBufferSize, p.maxBufferSize);
    lower(l.maxMemoryAllocationCount, p.maxMemoryAllocationCount);

    DeviceFeatures& f = caps.features;
    f.samplerAnisotropy = f.samplerAnisotropy && data->features.samplerAnisotropy;
    f.alphaToOne = f.alphaToOne && data->features.alphaToOne;
    f.fullDrawIndexUint32 = f.fullDrawIndexUint32 && data->features.fullDrawIndexUint32;
    f.shaderStorageImageExtendedFormats =
        f.shaderStorageImageExtendedFormats && data->features.shaderStorageImageExtendedFormats;
    f.geometryShader = f.geometryShader && data->features.geometryShader;
    if (!f.fullDrawIndexUint32) lower(l.maxDrawIndexedIndexValue, (1u << 24) - 1);
    if (!f.samplerAnisotropy) l.maxSamplerAnisotropy = 1.0f;

    caps.extensions.memoryBudget = caps.extensions.memoryBudget && data->extensions.memoryBudget;
    caps.hostWrittenTextures = false;  // a profile stands for a GPU (DeviceCaps::hostWrittenTextures)
    // VK_KHR_portability_subset is not narrowed: a device that has it must have it enabled.

    if (!data->lazyMemory)
        for (uint32_t i = 0; i < caps.memory.memoryTypeCount; ++i)
            if (caps.memory.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT)
                caps.memoryTypeMask &= ~(1u << i);

    for (auto& [format, features] : caps.formats) {
        VkFormatFeatureFlags2 ceiling = 0;
        for (const FormatCeiling& c : data->formats)
            if (c.format == format) ceiling = c.features;
        features &= ceiling;
    }
    return caps;
}

}  // namespace candela::vk
