#pragma once
// The MSAA sample count of a frame's draw targets: what the user asked for (--msaa) or the
// device's default, clamped to what the device can render. Pure function of device facts.

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <optional>
#include <string>

namespace candela::vk {

struct MsaaChoice {
    uint32_t samples = 1;
    bool clamped = false;  // the requested count is not supported: `samples` is the nearest below
    std::string reason;    // one line for `info` and `--explain`, e.g. "4 samples (device default on GPUs)"
};

// The default is 4 on GPUs (discrete, integrated, virtual) and 1 on CPU devices such as lavapipe,
// which shade and store every sample in software. `requested` (1, 2, 4 or 8) or the default is
// clamped to the largest count in `supported` (VkSampleCountFlags of colour and depth attachments)
// at or below it; 1 is always supported.
MsaaChoice chooseMsaa(VkPhysicalDeviceType type, VkSampleCountFlags supported, std::optional<uint32_t> requested);

// "1, 4" for the counts in `supported`.
std::string sampleCountList(VkSampleCountFlags supported);

}  // namespace candela::vk
