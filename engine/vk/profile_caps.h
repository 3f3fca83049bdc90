#pragma once
// What a device profile (options/device_profile.h) does to a device's capabilities: a ceiling on what
// Candela sees, so lavapipe (generous limits, every format filtered, descriptor pools never full)
// can play a smaller GPU. narrowCaps() takes the minimum of each limit and keeps a feature, an
// extension, a memory type or a format feature only when both the device and the profile have it.
// A profile can only take away: it cannot give lavapipe what it lacks.
//
// Pure: no Vulkan calls. The figures and their sources are in profile_caps.cpp and
// docs/device-layer.md.

#include "vk/device_caps.h"
#include "options/device_profile.h"

namespace candela::vk {

// Where the profile's figures come from (one line).
const char* deviceProfileSource(options::DeviceProfile profile);

// The profile named by CANDELA_DEVICE_PROFILE (Native when unset or empty). Throws UserError
// naming the variable when it names no profile.
options::DeviceProfile deviceProfileFromEnvironment();

// `device` seen through `profile`.
DeviceCaps narrowCaps(const DeviceCaps& device, options::DeviceProfile profile);

}  // namespace candela::vk
