#include "vk/device_select.h"

#include "vk/named_drivers.h"

#include "core/errors.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace candela::vk {
namespace {

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
        default: return 4;
    }
}

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
    return out;
}

bool allDigits(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

DeviceChoice requireSuitable(const std::vector<DeviceCandidate>& devices, uint32_t index, std::string_view source,
                             std::string reason) {
    const DeviceCandidate& device = devices[index];
    if (!device.unsuitable.empty())
        throw UserError(std::string(source) + ": device " + std::to_string(index) + " '" + device.name + "' cannot be used: " +
                        device.unsuitable);
    return {index, std::move(reason)};
}

}  // namespace

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
        default: return "other";
    }
}

DeviceChoice chooseDevice(const std::vector<DeviceCandidate>& devices, std::string_view selector, std::string_view source) {
    const std::string from(source);
    if (devices.empty()) throw UserError("no Vulkan device found (is a Vulkan driver such as mesa-vulkan-drivers installed?)");

    if (allDigits(selector)) {
        const unsigned long index = std::stoul(std::string(selector));
        if (index >= devices.size())
            throw UserError(from + " " + std::string(selector) + ": no such device index (there are " +
                            std::to_string(devices.size()) + " devices)");
        return requireSuitable(devices, static_cast<uint32_t>(index), source, "selected by index with " + from);
    }
    if (!selector.empty()) {
        const std::string needle = lower(selector);
        for (uint32_t i = 0; i < devices.size(); ++i)
            if (lower(devices[i].name).find(needle) != std::string::npos)
                return requireSuitable(devices, i, source, "name matches " + from + " '" + std::string(selector) + "'");
        throw UserError(from + " '" + std::string(selector) + "' matches no Vulkan device" +
                        (needle.find("swiftshader") != std::string::npos
                             ? " (SwiftShader's driver comes with Debian's chromium package: " + std::string(kSwiftShaderManifest) + ")"
                             : std::string()));
    }

    uint32_t best = ~0u;
    for (uint32_t i = 0; i < devices.size(); ++i) {
        if (!devices[i].unsuitable.empty()) continue;
        if (best == ~0u || typeRank(devices[i].type) < typeRank(devices[best].type)) best = i;
    }
    if (best == ~0u) {
        std::string why;
        for (const DeviceCandidate& d : devices) why += (why.empty() ? "" : "; ") + d.name + ": " + d.unsuitable;
        throw UserError("no suitable Vulkan device (" + why + ")");
    }
    return {best, std::string("most capable suitable device type (") + deviceTypeName(devices[best].type) +
                      "; preference: discrete > integrated > virtual > CPU)"};
}

QueueFamilyChoice chooseQueueFamilies(const std::vector<VkQueueFamilyProperties>& families,
                                      const std::vector<bool>& presentSupport) {
    QueueFamilyChoice choice;
    const auto has = [&](uint32_t i, VkQueueFlags flags) {
        return families[i].queueCount > 0 && (families[i].queueFlags & flags) == flags;
    };
    const auto lacks = [&](uint32_t i, VkQueueFlags flags) { return (families[i].queueFlags & flags) == 0; };
    const auto canPresent = [&](uint32_t i) { return presentSupport.empty() || presentSupport[i]; };

    for (uint32_t i = 0; i < families.size() && choice.graphics == ~0u; ++i)
        if (has(i, VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT) && canPresent(i)) choice.graphics = i;
    if (choice.graphics == ~0u)
        throw std::runtime_error(presentSupport.empty() ? "no queue family supports graphics and compute"
                                                        : "no queue family supports graphics, compute and present");

    choice.compute = choice.graphics;
    for (uint32_t i = 0; i < families.size(); ++i)
        if (has(i, VK_QUEUE_COMPUTE_BIT) && lacks(i, VK_QUEUE_GRAPHICS_BIT)) {
            choice.compute = i;
            break;
        }

    // Graphics and compute families support transfer implicitly; a family advertising only
    // transfer (and maybe sparse binding) is a dedicated copy engine.
    choice.transfer = choice.compute;
    for (uint32_t i = 0; i < families.size(); ++i)
        if (has(i, VK_QUEUE_TRANSFER_BIT) && lacks(i, VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) {
            choice.transfer = i;
            break;
        }
    return choice;
}

}  // namespace candela::vk
