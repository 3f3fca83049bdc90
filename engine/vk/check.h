#pragma once
// Error checking for Vulkan calls. The errors that need no Vulkan (UserError, InternalError,
// formatBytes) are core/errors.h, included here.
// VK_CHECK is always on (release builds too): a failed call throws VulkanError whose message
// names the call, file:line and the VkResult, e.g.
//   "vkCreateImage(device, &info, nullptr, &image) failed at engine/vk/image.cpp:42: VK_ERROR_OUT_OF_DEVICE_MEMORY"

#include "core/errors.h"

#include <vulkan/vulkan_core.h>

#include <stdexcept>
#include <string>

namespace candela::vk {

// The VkResult's enumerator name ("VK_ERROR_DEVICE_LOST"), or "VkResult(<n>)" if unknown.
const char* vkResultName(VkResult result);

class VulkanError : public std::runtime_error {
public:
    VulkanError(std::string message, VkResult result) : std::runtime_error(std::move(message)), mResult(result) {}
    VkResult result() const { return mResult; }

private:
    VkResult mResult;
};

// Device memory could not be allocated: the device is out of memory, or the budget set with
// ContextDesc::deviceMemoryBudget (--memory-budget) would be exceeded. The message names the
// resource once a resource's constructor has added it. Front ends exit with code 4.
class OutOfDeviceMemory : public VulkanError {
public:
    explicit OutOfDeviceMemory(std::string message) : VulkanError(std::move(message), VK_ERROR_OUT_OF_DEVICE_MEMORY) {}
};

[[noreturn]] void throwVulkanError(const char* expression, const char* file, int line, VkResult result);

}  // namespace candela::vk

#define VK_CHECK(expr)                                                              \
    do {                                                                            \
        const VkResult vkCheckResult_ = (expr);                                     \
        if (vkCheckResult_ < 0) ::candela::vk::throwVulkanError(#expr, __FILE__, __LINE__, vkCheckResult_); \
    } while (false)
