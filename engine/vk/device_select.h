#pragma once
// Pure selection logic for physical devices and queue families (no Vulkan calls), so it is
// unit-tested with the family layouts of real GPUs, not only lavapipe's single family.

#include <vulkan/vulkan_core.h>

#include <string>
#include <string_view>
#include <vector>

namespace candela::vk {

struct DeviceCandidate {
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    uint32_t apiVersion = 0;
    std::string unsuitable;  // empty if the device has everything Candela needs, else why not
};

struct DeviceChoice {
    uint32_t index = 0;
    std::string reason;  // one line: why this device was chosen
};

// Picks a device. `selector` empty: the first suitable device by type preference
// discrete > integrated > virtual > CPU > other. `selector` all digits: that index.
// Otherwise: the first device whose name contains `selector` (case-insensitive).
// Throws UserError if the selector matches nothing, the match is unsuitable, or no device is suitable;
// its message names `source`, where the selector came from ("--device" or "CANDELA_DEVICE").
DeviceChoice chooseDevice(const std::vector<DeviceCandidate>& devices, std::string_view selector,
                          std::string_view source = "--device");

const char* deviceTypeName(VkPhysicalDeviceType type);

struct QueueFamilyChoice {
    uint32_t graphics = ~0u;  // graphics + compute (+ present when asked): the frame graph's queue
    uint32_t compute = ~0u;   // a compute family without graphics if any (async compute), else graphics
    uint32_t transfer = ~0u;  // a transfer-only family if any (DMA engine), else compute, else graphics
};

// `presentSupport[i]` tells whether family i can present (empty: presentation not needed).
// Throws std::runtime_error if no family supports graphics and compute (and present if needed).
QueueFamilyChoice chooseQueueFamilies(const std::vector<VkQueueFamilyProperties>& families,
                                      const std::vector<bool>& presentSupport = {});

}  // namespace candela::vk
