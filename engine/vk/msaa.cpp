#include "vk/msaa.h"

namespace candela::vk {

std::string sampleCountList(VkSampleCountFlags supported) {
    std::string out = "1";
    for (uint32_t count = 2; count <= 64; count *= 2)
        if (supported & count) out += ", " + std::to_string(count);
    return out;
}

MsaaChoice chooseMsaa(VkPhysicalDeviceType type, VkSampleCountFlags supported, std::optional<uint32_t> requested) {
    const bool cpu = type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const uint32_t wanted = requested.value_or(cpu ? 1u : 4u);
    MsaaChoice choice;
    for (uint32_t count = 2; count <= wanted; count *= 2)
        if (supported & count) choice.samples = count;
    choice.clamped = choice.samples != wanted;
    const std::string samples = std::to_string(choice.samples) + (choice.samples == 1 ? " sample (no MSAA)" : " samples");
    if (choice.clamped)
        choice.reason = samples + ": " + std::to_string(wanted) + " asked, the device supports " + sampleCountList(supported);
    else if (requested)
        choice.reason = samples + " (--msaa)";
    else
        choice.reason = samples + (cpu ? " (default on CPU devices, which shade every sample in software; --msaa)"
                                       : " (default on GPUs; --msaa)");
    return choice;
}

}  // namespace candela::vk
