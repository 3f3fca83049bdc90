#pragma once
// The device selector's sources and the Vulkan drivers Candela can add to the loader by name.
//
// `--device SEL` (ContextDesc::deviceSelector) picks a device; without it CANDELA_DEVICE does (so a
// test binary or a script picks one without a flag). Debian's chromium package ships SwiftShader's
// Vulkan driver outside the loader's search path; a selector that names SwiftShader adds its
// manifest to the loader (VK_ADD_DRIVER_FILES) before the instance is created, so
// `--device swiftshader` works without setting the loader's variables by hand (docs/devices.md).

#include <functional>
#include <string>
#include <string_view>

namespace candela::vk {

// Where Debian's chromium package installs SwiftShader's driver manifest.
inline constexpr const char* kSwiftShaderManifest = "/usr/lib/chromium/vk_swiftshader_icd.json";

// `flag` when not empty, else the value of CANDELA_DEVICE (empty when unset).
std::string effectiveDeviceSelector(const std::string& flag);

// The loader's environment as this needs it: the value of a variable (nullptr when unset) and
// whether a file exists. Injected so the rule is tested without touching the process.
struct LoaderEnvironment {
    std::function<const char*(const char*)> get;
    std::function<bool(const std::string&)> exists;
};

// The manifest to append to VK_ADD_DRIVER_FILES for `selector`, or "": when `selector` contains
// "swiftshader" (any case), SwiftShader's manifest exists, and the loader's drivers are neither
// replaced (VK_ICD_FILENAMES, VK_DRIVER_FILES: the user chose the drivers) nor already given it.
std::string driverManifestToAdd(std::string_view selector, const LoaderEnvironment& env);

// Applies driverManifestToAdd to the process's environment. Call before vkCreateInstance.
void addNamedDriver(std::string_view selector);

}  // namespace candela::vk
