#pragma once
// Error checking for Vulkan calls and user-facing errors.
// VK_CHECK is always on (release builds too): a failed call throws VulkanError whose message
// names the call, file:line and the VkResult, e.g.
//   "vkCreateImage(device, &info, nullptr, &image) failed at engine/vk/image.cpp:42: VK_ERROR_OUT_OF_DEVICE_MEMORY"

#include <vulkan/vulkan_core.h>

#include <stdexcept>
#include <string>

namespace candela {

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

// "144 B", "12.0 KiB", "12.5 MiB", "1.5 GiB"
std::string formatBytes(uint64_t bytes);

// An error caused by the user's input (flags, files): the message is one line naming the
// problem (and the file, if any). Front ends print it and exit non-zero.
class UserError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Candela broke a contract between two of its own parts — a pass naming a descriptor binding its
// shader does not declare, push constants of the wrong size, an object placed in memory too small
// for it. A bug, never the user's input: front ends report it as an internal error.
class InternalError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

[[noreturn]] void throwVulkanError(const char* expression, const char* file, int line, VkResult result);

}  // namespace candela

#define VK_CHECK(expr)                                                              \
    do {                                                                            \
        const VkResult vkCheckResult_ = (expr);                                     \
        if (vkCheckResult_ < 0) ::candela::throwVulkanError(#expr, __FILE__, __LINE__, vkCheckResult_); \
    } while (false)
