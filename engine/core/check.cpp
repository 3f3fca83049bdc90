#include "core/check.h"

#include <cstdio>

#include <string>

namespace candela {

const char* vkResultName(VkResult result) {
    switch (result) {
#define CANDELA_RESULT(name) \
    case name:               \
        return #name;
        CANDELA_RESULT(VK_SUCCESS)
        CANDELA_RESULT(VK_NOT_READY)
        CANDELA_RESULT(VK_TIMEOUT)
        CANDELA_RESULT(VK_EVENT_SET)
        CANDELA_RESULT(VK_EVENT_RESET)
        CANDELA_RESULT(VK_INCOMPLETE)
        CANDELA_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        CANDELA_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        CANDELA_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        CANDELA_RESULT(VK_ERROR_DEVICE_LOST)
        CANDELA_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        CANDELA_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        CANDELA_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        CANDELA_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        CANDELA_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        CANDELA_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        CANDELA_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        CANDELA_RESULT(VK_ERROR_FRAGMENTED_POOL)
        CANDELA_RESULT(VK_ERROR_UNKNOWN)
        CANDELA_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        CANDELA_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        CANDELA_RESULT(VK_ERROR_FRAGMENTATION)
        CANDELA_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        CANDELA_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
        CANDELA_RESULT(VK_ERROR_SURFACE_LOST_KHR)
        CANDELA_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        CANDELA_RESULT(VK_SUBOPTIMAL_KHR)
        CANDELA_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
        CANDELA_RESULT(VK_ERROR_INCOMPATIBLE_DISPLAY_KHR)
        CANDELA_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
        CANDELA_RESULT(VK_ERROR_INVALID_SHADER_NV)
        CANDELA_RESULT(VK_ERROR_NOT_PERMITTED_KHR)
        CANDELA_RESULT(VK_ERROR_FULL_SCREEN_EXCLUSIVE_MODE_LOST_EXT)
        CANDELA_RESULT(VK_THREAD_IDLE_KHR)
        CANDELA_RESULT(VK_THREAD_DONE_KHR)
        CANDELA_RESULT(VK_OPERATION_DEFERRED_KHR)
        CANDELA_RESULT(VK_OPERATION_NOT_DEFERRED_KHR)
#undef CANDELA_RESULT
        default:
            return nullptr;
    }
}

void throwVulkanError(const char* expression, const char* file, int line, VkResult result) {
    const char* name = vkResultName(result);
    std::string message = std::string(expression) + " failed at " + file + ":" + std::to_string(line) + ": " +
                          (name ? std::string(name) : "VkResult(" + std::to_string(static_cast<int>(result)) + ")");
    throw VulkanError(std::move(message), result);
}

std::string formatBytes(uint64_t bytes) {
    char text[32];
    if (bytes < 1024)
        std::snprintf(text, sizeof(text), "%llu B", static_cast<unsigned long long>(bytes));
    else if (bytes < (1u << 20))
        std::snprintf(text, sizeof(text), "%.1f KiB", double(bytes) / 1024.0);
    else if (bytes < (1ull << 30))
        std::snprintf(text, sizeof(text), "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    else
        std::snprintf(text, sizeof(text), "%.1f GiB", double(bytes) / (1024.0 * 1024.0 * 1024.0));
    return text;
}

}  // namespace candela
