#pragma once
// Option types more than one command shares: the device flags every command takes, and the
// values of --env and --background.

#include "options/device_profile.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace candela::app {

// An option whose flag declares a default in its command's flag list gets it from there
// (parseCommandLine applies the defaults before reading the arguments); the initial values in the
// option structs are those of switches and of flags whose default is "not given".

struct CommonOptions {
    std::string device;            // --device INDEX|NAME
    std::string pipelineCache;     // --pipeline-cache DIR|off ("": the user's cache folder)
    bool validate = false;         // --validate
    bool verbose = false;          // --verbose
    bool quiet = false;            // --quiet: no progress lines
    uint32_t memoryBudgetMib = 0;  // --memory-budget MIB (0: the device's memory)
    std::optional<options::DeviceProfile> deviceProfile;  // --device-profile NAME (unset: CANDELA_DEVICE_PROFILE)
    bool operator==(const CommonOptions&) const = default;
};

// --env: the environment that lights the scene.
struct EnvironmentChoice {
    enum class Kind { Sky, None, File } kind = Kind::Sky;  // Sky: the built-in procedural sky
    std::string file;                                      // Kind::File: an equirectangular .hdr/.exr
    bool operator==(const EnvironmentChoice&) const = default;
};

// --background: what shows where the scene draws nothing.
struct Background {
    enum class Kind { Auto, Skybox, Transparent, Color } kind = Kind::Auto;  // Auto: the skybox with an environment, #262626 without
    std::array<float, 3> srgb{};  // Kind::Color: sRGB-encoded components in [0,1]
    bool operator==(const Background&) const = default;
};

inline constexpr std::pair<Background::Kind, const char*> kBackgroundNames[] = {
    {Background::Kind::Auto, "auto"}, {Background::Kind::Skybox, "skybox"}, {Background::Kind::Transparent, "transparent"}};

}  // namespace candela::app
