#include "vk/device_caps.h"

#include "vk/check.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace candela::vk {

VkFormatFeatureFlags2 DeviceCaps::formatFeatures(VkFormat format) const {
    for (const auto& [f, flags] : formats)
        if (f == format) return flags;
    return 0;
}

bool DeviceCaps::hasMemoryType(VkMemoryPropertyFlags flags) const {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((memoryTypeMask & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return true;
    return false;
}

DeviceCaps queryDeviceCaps(VkPhysicalDevice device) {
    DeviceCaps caps;
    VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceVulkan13Properties p13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_PROPERTIES, .pNext = &driver};
    VkPhysicalDeviceVulkan11Properties p11{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES, .pNext = &p13};
    VkPhysicalDeviceProperties2 properties{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &p11};
    vkGetPhysicalDeviceProperties2(device, &properties);
    caps.driver = driver.driverID;
    const VkPhysicalDeviceLimits& l = properties.properties.limits;
    DeviceLimits& out = caps.limits;
    out.maxPerStageDescriptorSamplers = l.maxPerStageDescriptorSamplers;
    out.maxPerStageDescriptorSampledImages = l.maxPerStageDescriptorSampledImages;
    out.maxPerStageDescriptorStorageBuffers = l.maxPerStageDescriptorStorageBuffers;
    out.maxPerStageDescriptorStorageImages = l.maxPerStageDescriptorStorageImages;
    out.maxPerStageDescriptorUniformBuffers = l.maxPerStageDescriptorUniformBuffers;
    out.maxPerStageResources = l.maxPerStageResources;
    out.maxBoundDescriptorSets = l.maxBoundDescriptorSets;
    out.maxStorageBufferRange = l.maxStorageBufferRange;
    out.minStorageBufferOffsetAlignment = l.minStorageBufferOffsetAlignment;
    out.maxUniformBufferRange = l.maxUniformBufferRange;
    out.maxPushConstantsSize = l.maxPushConstantsSize;
    out.maxImageDimension2D = l.maxImageDimension2D;
    out.maxImageDimensionCube = l.maxImageDimensionCube;
    std::copy(std::begin(l.maxComputeWorkGroupCount), std::end(l.maxComputeWorkGroupCount), out.maxComputeWorkGroupCount);
    out.maxDrawIndexedIndexValue = l.maxDrawIndexedIndexValue;
    out.maxSamplerAnisotropy = l.maxSamplerAnisotropy;
    out.framebufferColorSampleCounts = l.framebufferColorSampleCounts;
    out.framebufferDepthSampleCounts = l.framebufferDepthSampleCounts;
    out.sampledImageIntegerSampleCounts = l.sampledImageIntegerSampleCounts;
    out.maxMemoryAllocationSize = p11.maxMemoryAllocationSize;
    out.maxBufferSize = p13.maxBufferSize;
    out.maxMemoryAllocationCount = l.maxMemoryAllocationCount;

    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    vkGetPhysicalDeviceFeatures2(device, &features);
    caps.features.samplerAnisotropy = features.features.samplerAnisotropy;
    caps.features.alphaToOne = features.features.alphaToOne;
    caps.features.fullDrawIndexUint32 = features.features.fullDrawIndexUint32;
    caps.features.shaderStorageImageExtendedFormats = features.features.shaderStorageImageExtendedFormats;
    caps.features.geometryShader = features.features.geometryShader;

    uint32_t count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()));
    const auto has = [&](const char* name) {
        return std::any_of(extensions.begin(), extensions.end(),
                           [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
    };
    caps.extensions.memoryBudget = has(VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    caps.extensions.portabilitySubset = has("VK_KHR_portability_subset");
    caps.extensions.swapchain = has(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

    vkGetPhysicalDeviceMemoryProperties(device, &caps.memory);
    caps.memoryTypeMask = caps.memory.memoryTypeCount >= 32 ? ~0u : (1u << caps.memory.memoryTypeCount) - 1u;

    for (VkFormat format : kCandelaFormats) {
        VkFormatProperties3 p3{.sType = VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3};
        VkFormatProperties2 p2{.sType = VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2, .pNext = &p3};
        vkGetPhysicalDeviceFormatProperties2(device, format, &p2);
        caps.formats.emplace_back(format, p3.optimalTilingFeatures);
    }

    const auto linearTextures = [&](VkFormat format) {
        VkFormatProperties3 p3{.sType = VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3};
        VkFormatProperties2 p2{.sType = VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2, .pNext = &p3};
        vkGetPhysicalDeviceFormatProperties2(device, format, &p2);
        const VkFormatFeatureFlags2 needed = format_feature::kSampled | format_feature::kLinear;
        VkImageFormatProperties image{};
        return (p3.linearTilingFeatures & needed) == needed &&
               vkGetPhysicalDeviceImageFormatProperties(device, format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_LINEAR,
                                                        VK_IMAGE_USAGE_SAMPLED_BIT, 0, &image) == VK_SUCCESS &&
               image.maxExtent.width >= out.maxImageDimension2D && image.maxExtent.height >= out.maxImageDimension2D &&
               image.maxMipLevels >= uint32_t(std::bit_width(out.maxImageDimension2D));
    };
    caps.hostWrittenTextures = properties.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU &&
                               caps.hasMemoryType(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                  VK_MEMORY_PROPERTY_HOST_COHERENT_BIT | VK_MEMORY_PROPERTY_HOST_CACHED_BIT) &&
                               linearTextures(VK_FORMAT_R8G8B8A8_UNORM) && linearTextures(VK_FORMAT_R8G8B8A8_SRGB);
    return caps;
}

std::string formatFeatureNames(VkFormatFeatureFlags2 features) {
    static constexpr std::pair<VkFormatFeatureFlags2, const char*> kNames[] = {
        {VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT, "SAMPLED_IMAGE"},
        {VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT, "SAMPLED_IMAGE_FILTER_LINEAR"},
        {VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT, "STORAGE_IMAGE"},
        {VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT"},
        {VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BLEND_BIT, "COLOR_ATTACHMENT_BLEND"},
        {VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT, "DEPTH_STENCIL_ATTACHMENT"},
        {VK_FORMAT_FEATURE_2_BLIT_SRC_BIT, "BLIT_SRC"},
        {VK_FORMAT_FEATURE_2_BLIT_DST_BIT, "BLIT_DST"},
        {VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT, "TRANSFER_SRC"},
        {VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT, "TRANSFER_DST"},
    };
    std::string out;
    for (const auto& [bit, name] : kNames)
        if (features & bit) out += (out.empty() ? "" : "|") + std::string(name);
    return out.empty() ? "none" : out;
}

std::string formatName(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8G8B8A8_UNORM: return "R8G8B8A8_UNORM";
        case VK_FORMAT_R8G8B8A8_SRGB: return "R8G8B8A8_SRGB";
        case VK_FORMAT_B8G8R8A8_UNORM: return "B8G8R8A8_UNORM";
        case VK_FORMAT_B8G8R8A8_SRGB: return "B8G8R8A8_SRGB";
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32: return "A2B10G10R10_UNORM_PACK32";
        case VK_FORMAT_R16_SFLOAT: return "R16_SFLOAT";
        case VK_FORMAT_R16G16_SFLOAT: return "R16G16_SFLOAT";
        case VK_FORMAT_R16G16B16A16_SFLOAT: return "R16G16B16A16_SFLOAT";
        case VK_FORMAT_R32_SFLOAT: return "R32_SFLOAT";
        case VK_FORMAT_R32G32_SFLOAT: return "R32G32_SFLOAT";
        case VK_FORMAT_R32G32B32A32_SFLOAT: return "R32G32B32A32_SFLOAT";
        case VK_FORMAT_D32_SFLOAT: return "D32_SFLOAT";
        case VK_FORMAT_X8_D24_UNORM_PACK32: return "X8_D24_UNORM_PACK32";
        case VK_FORMAT_D16_UNORM: return "D16_UNORM";
        case VK_FORMAT_R32G32_UINT: return "R32G32_UINT";
        default: return "format " + std::to_string(static_cast<int>(format));
    }
}

}  // namespace candela::vk
