#include "vk/named_drivers.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

namespace candela::vk {

std::string effectiveDeviceSelector(const std::string& flag) {
    if (!flag.empty()) return flag;
    const char* value = std::getenv("CANDELA_DEVICE");
    return value ? value : "";
}

std::string driverManifestToAdd(std::string_view selector, const LoaderEnvironment& env) {
    std::string lower(selector);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (lower.find("swiftshader") == std::string::npos) return "";
    for (const char* replacing : {"VK_ICD_FILENAMES", "VK_DRIVER_FILES"})
        if (const char* value = env.get(replacing); value && *value) return "";
    const char* added = env.get("VK_ADD_DRIVER_FILES");
    if (added && std::string_view(added).find(kSwiftShaderManifest) != std::string_view::npos) return "";
    return env.exists(kSwiftShaderManifest) ? kSwiftShaderManifest : "";
}

void addNamedDriver(std::string_view selector) {
    const LoaderEnvironment env{.get = [](const char* name) { return static_cast<const char*>(std::getenv(name)); },
                                .exists = [](const std::string& path) {
                                    std::error_code error;
                                    return std::filesystem::exists(path, error);
                                }};
    const std::string manifest = driverManifestToAdd(selector, env);
    if (manifest.empty()) return;
    const char* added = std::getenv("VK_ADD_DRIVER_FILES");
    const std::string value = added && *added ? std::string(added) + ":" + manifest : manifest;
    setenv("VK_ADD_DRIVER_FILES", value.c_str(), 1);
}

}  // namespace candela::vk
