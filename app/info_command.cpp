// `candela info`: the Vulkan devices, the one chosen and why, and what is enabled on it.

#include "commands.h"
#include "session.h"

#include "core/cache_files.h"
#include "render/visibility_path.h"
#include "vk/check.h"
#include "vk/device_select.h"
#include "vk/timestamps.h"

#include <cstdio>

namespace candela::app {

namespace {
std::string apiVersion(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

}  // namespace

int runInfo(const InfoOptions& options) {
    vk::ContextDesc desc = contextDesc(options.common);
    desc.pipelineCacheFolder.clear();  // info builds no pipeline: it neither reads nor writes the cache
    vk::Context context(desc);
    // List every device the loader sees, with the reason it is or is not usable.
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(context.instance(), &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(context.instance(), &count, devices.data()));
    std::printf("Vulkan devices:\n");
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devices[i], &p);
        std::printf("  [%u] %s (%s, Vulkan %s)%s\n", i, p.deviceName, vk::deviceTypeName(p.deviceType),
                    apiVersion(p.apiVersion).c_str(), devices[i] == context.physicalDevice() ? "  <- chosen" : "");
    }
    const vk::DeviceReport& r = context.report();
    std::printf("chosen: %s (%s)\n  why: %s\n  API version: %s\n  driver: %s %s\n", r.name.c_str(), r.type.c_str(),
                r.reason.c_str(), apiVersion(r.apiVersion).c_str(), r.driverName.c_str(), r.driverInfo.c_str());
    std::printf("  queue families: graphics %u, compute %u, transfer %u\n", r.graphicsFamily, r.computeFamily,
                r.transferFamily);
    std::printf("  timestamps: %s\n", r.timestampValidBits
                                          ? (std::to_string(r.timestampValidBits) + " valid bits, period " +
                                             std::to_string(r.timestampPeriodNs) + " ns; " + vk::timestampBehaviour(context.caps().driver))
                                                .c_str()
                                          : "not supported");
    const vk::MsaaChoice msaa = vk::chooseMsaa(context.properties().deviceType, context.attachmentSampleCounts(), std::nullopt);
    std::printf("  MSAA: %s; supported: %s\n", msaa.reason.c_str(), vk::sampleCountList(context.attachmentSampleCounts()).c_str());
    const auto [shadingPath, shadingWhy] = defaultShadingPath(context);
    std::printf("  shading path: %s (%s; --shading-path)\n", options::shadingPathName(shadingPath), shadingWhy.c_str());
    const vk::DeviceCaps& caps = context.caps();
    std::printf("  device profile: %s (%s)\n", r.profile.c_str(), vk::deviceProfileSource(context.profile()));
    std::printf("  per-stage limits: %u samplers, %u sampled images, %u storage buffers, %u storage images\n",
                caps.limits.maxPerStageDescriptorSamplers, caps.limits.maxPerStageDescriptorSampledImages,
                caps.limits.maxPerStageDescriptorStorageBuffers, caps.limits.maxPerStageDescriptorStorageImages);
    std::printf("  sizes: storage buffer range %s, allocation %s, buffer %s, 2D image %u\n",
                formatBytes(caps.limits.maxStorageBufferRange).c_str(), formatBytes(caps.limits.maxMemoryAllocationSize).c_str(),
                formatBytes(caps.limits.maxBufferSize).c_str(), caps.limits.maxImageDimension2D);
    std::printf("  memory: %s; %s\n",
                caps.hasMemoryType(VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT) ? "lazily allocated memory for transient attachments"
                                                                            : "no lazily allocated memory",
                caps.hasMemoryType(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
                    ? "per-frame data in host-visible device-local memory"
                    : "per-frame data in system memory");
    const auto heaps = context.allocator().heapBudgets();
    std::printf("  heap budgets (VK_EXT_memory_budget):%s", heaps.empty() ? " not available\n" : "");
    for (size_t i = 0; i < heaps.size(); ++i)
        std::printf(" heap %zu %s of %s%s", i, formatBytes(heaps[i].first).c_str(), formatBytes(heaps[i].second).c_str(),
                    i + 1 == heaps.size() ? "\n" : ";");
    std::printf("  fallbacks:");
    if (context.choices().fallbacks.empty()) std::printf(" none (the device has every format feature Candela prefers)");
    std::printf("\n");
    for (const std::string& f : context.choices().fallbacks) std::printf("    %s\n", f.c_str());
    std::printf("  features enabled:");
    for (const std::string& f : r.enabledFeatures) std::printf(" %s", f.c_str());
    std::printf("\n  extensions enabled:");
    if (r.enabledExtensions.empty()) std::printf(" (none)");
    for (const std::string& e : r.enabledExtensions) std::printf(" %s", e.c_str());
    std::printf("\n  layers enabled:");
    if (r.enabledLayers.empty()) std::printf(" (none)");
    for (const std::string& l : r.enabledLayers) std::printf(" %s", l.c_str());
    std::printf("\n");
    return 0;
}

}  // namespace candela::app
