#pragma once
// The device profiles and their names, the one table the command line (--device-profile), the
// environment variable CANDELA_DEVICE_PROFILE, `candela info` and the tests read. Names only: no
// Vulkan. What a profile does to the device's capabilities is in vk/profile_caps.h.

#include "core/name_table.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace candela::options {

enum class DeviceProfile : uint8_t {
    Native,   // the device as it is
    Minimum,  // what Vulkan 1.3 guarantees every device
    Desktop,  // a current desktop GPU (NVIDIA GeForce RTX 4070 device report)
    Apple,    // Apple silicon through MoltenVK (Apple M1 device report)
};

inline constexpr std::pair<DeviceProfile, const char*> kDeviceProfileNames[] = {{DeviceProfile::Native, "native"},
                                                                                {DeviceProfile::Minimum, "minimum"},
                                                                                {DeviceProfile::Desktop, "desktop"},
                                                                                {DeviceProfile::Apple, "apple"}};

// The profile named `name` in kDeviceProfileNames; nullopt for anything else.
constexpr std::optional<DeviceProfile> parseDeviceProfile(std::string_view name) {
    return valueNamed(kDeviceProfileNames, name);
}
constexpr const char* deviceProfileName(DeviceProfile profile) { return nameOf(kDeviceProfileNames, profile); }

// "native, minimum, desktop, apple".
inline std::string deviceProfileList() {
    std::string out;
    for (const auto& [profile, name] : kDeviceProfileNames) out += (out.empty() ? "" : ", ") + std::string(name);
    return out;
}

}  // namespace candela::options
