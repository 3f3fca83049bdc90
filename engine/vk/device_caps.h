#pragma once
// DeviceCaps: what Candela may use of the chosen device — the limits, optional features,
// extensions, memory types and format features it reads — queried once at start-up
// (queryDeviceCaps) and possibly narrowed by a device profile (device_profile.h). Every choice
// that depends on the device reads these, never the driver directly, so a profile can make
// lavapipe behave like a smaller GPU.
//
// Plain data and pure functions except queryDeviceCaps.

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace candela::vk {

// Every format Candela creates an image in, samples, stores to or renders to (and the candidates
// its fallbacks may pick). Their features are recorded in DeviceCaps::formats.
inline constexpr VkFormat kCandelaFormats[] = {
    VK_FORMAT_R8G8B8A8_UNORM,      VK_FORMAT_R8G8B8A8_SRGB,       VK_FORMAT_B8G8R8A8_UNORM,
    VK_FORMAT_B8G8R8A8_SRGB,       VK_FORMAT_A2B10G10R10_UNORM_PACK32, VK_FORMAT_R16_SFLOAT,
    VK_FORMAT_R16G16_SFLOAT,       VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32_SFLOAT,
    VK_FORMAT_R32G32_SFLOAT,       VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_D32_SFLOAT,
    VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D16_UNORM,        VK_FORMAT_R32G32_UINT,
};

// Format-feature shorthands for the tables of the profiles and the choices.
namespace format_feature {
inline constexpr VkFormatFeatureFlags2 kSampled = VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT;
inline constexpr VkFormatFeatureFlags2 kLinear = VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
inline constexpr VkFormatFeatureFlags2 kStorage = VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT;
inline constexpr VkFormatFeatureFlags2 kColor = VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT;
inline constexpr VkFormatFeatureFlags2 kBlend = VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BLEND_BIT;
inline constexpr VkFormatFeatureFlags2 kDepth = VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT;
}  // namespace format_feature

// The limits Candela reads (a subset of VkPhysicalDeviceLimits and the Vulkan 1.1–1.3 properties).
struct DeviceLimits {
    uint32_t maxPerStageDescriptorSamplers = 0;
    uint32_t maxPerStageDescriptorSampledImages = 0;
    uint32_t maxPerStageDescriptorStorageBuffers = 0;
    uint32_t maxPerStageDescriptorStorageImages = 0;
    uint32_t maxPerStageDescriptorUniformBuffers = 0;
    uint32_t maxPerStageResources = 0;
    uint32_t maxBoundDescriptorSets = 0;
    uint64_t maxStorageBufferRange = 0;
    // A storage-buffer descriptor's offset must be a multiple of this (a power of two, at most 256).
    uint64_t minStorageBufferOffsetAlignment = 256;
    uint64_t maxUniformBufferRange = 0;
    uint32_t maxPushConstantsSize = 0;
    uint32_t maxImageDimension2D = 0;
    uint32_t maxImageDimensionCube = 0;
    uint32_t maxComputeWorkGroupCount[3] = {0, 0, 0};
    uint32_t maxDrawIndexedIndexValue = 0;
    float maxSamplerAnisotropy = 1.0f;
    VkSampleCountFlags framebufferColorSampleCounts = 0;
    VkSampleCountFlags framebufferDepthSampleCounts = 0;
    // Sample counts of integer images a shader may sample (the visibility path's MSAA visibility image).
    VkSampleCountFlags sampledImageIntegerSampleCounts = 0;
    uint64_t maxMemoryAllocationSize = 0;  // Vulkan 1.1 (maintenance3)
    uint64_t maxBufferSize = 0;            // Vulkan 1.3 (maintenance4)
    uint32_t maxMemoryAllocationCount = 0;
};

// The optional features Candela can use (each enabled at device creation only when true here).
struct DeviceFeatures {
    bool samplerAnisotropy = false;
    bool alphaToOne = false;
    bool fullDrawIndexUint32 = false;
    bool shaderStorageImageExtendedFormats = false;
    // The fragment shader's gl_PrimitiveID (SPIR-V's Geometry capability), which the visibility
    // buffer stores (docs/shading-paths.md).
    bool geometryShader = false;
};

// The optional device extensions Candela can use.
struct DeviceExtensions {
    bool memoryBudget = false;       // VK_EXT_memory_budget
    bool portabilitySubset = false;  // VK_KHR_portability_subset (must be enabled when present)
    bool swapchain = false;          // VK_KHR_swapchain (needed to present; profiles leave it as it is)
};

struct DeviceCaps {
    // The driver (VkPhysicalDeviceDriverProperties::driverID; 0: unknown), for its known defects.
    VkDriverId driver = VkDriverId(0);
    DeviceLimits limits;
    DeviceFeatures features;
    DeviceExtensions extensions;
    VkPhysicalDeviceMemoryProperties memory{};
    // Memory types Candela may allocate from (bit i: type i). A profile hides types (e.g. lazily
    // allocated ones) by clearing their bits.
    uint32_t memoryTypeMask = 0;
    // Optimal-tiling features of each of kCandelaFormats.
    std::vector<std::pair<VkFormat, VkFormatFeatureFlags2>> formats;
    // Whether sampled RGBA8 textures (UNORM and sRGB) may be host-written (ImageDesc::hostWritten:
    // linear tiling in host-visible memory, written in place, no staging copy): on a CPU device
    // (lavapipe: its images are host memory, laid out linearly either way) whose linear tiling
    // samples both formats with linear filtering, with full mip chains up to maxImageDimension2D,
    // and which has a host-visible, coherent, cached, device-local memory type (cached: the chains
    // read each level back to make the next). SwiftShader's linear images
    // have one mip, so it has not. Profiles clear it: they stand for GPUs, which sample linear images
    // slowly when at all.
    bool hostWrittenTextures = false;

    // The optimal-tiling features of `format` (0 for a format not in kCandelaFormats).
    VkFormatFeatureFlags2 formatFeatures(VkFormat format) const;
    // Whether `format` has every feature in `required`.
    bool supports(VkFormat format, VkFormatFeatureFlags2 required) const {
        return (formatFeatures(format) & required) == required;
    }
    // Whether an allowed memory type has all of `flags`.
    bool hasMemoryType(VkMemoryPropertyFlags flags) const;
    VkSampleCountFlags attachmentSampleCounts() const {
        return limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts;
    }
};

// Reads the caps of `device` (limits, features, extensions, memory types, format features).
DeviceCaps queryDeviceCaps(VkPhysicalDevice device);

// Names of format features for messages ("SAMPLED_IMAGE_FILTER_LINEAR").
std::string formatFeatureNames(VkFormatFeatureFlags2 features);
// "R32G32B32A32_SFLOAT" for the formats in kCandelaFormats, else the number.
std::string formatName(VkFormat format);

}  // namespace candela::vk
