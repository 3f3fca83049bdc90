// The device selector's sources and SwiftShader's driver added by name (vk/named_drivers.h), with
// the loader's environment injected.
#include "vk/named_drivers.h"
#include "vk/device_select.h"

#include "core/errors.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace candela::vk {
namespace {

struct FakeEnvironment {
    std::map<std::string, std::string> variables;
    bool manifestInstalled = true;
    LoaderEnvironment view() const {
        return {.get = [this](const char* name) {
                    const auto it = variables.find(name);
                    return it == variables.end() ? static_cast<const char*>(nullptr) : it->second.c_str();
                },
                .exists = [this](const std::string& path) { return manifestInstalled && path == kSwiftShaderManifest; }};
    }
};

TEST(NamedDrivers, ASelectorNamingSwiftShaderAddsItsManifest) {
    const FakeEnvironment env;
    EXPECT_EQ(driverManifestToAdd("swiftshader", env.view()), kSwiftShaderManifest);
    EXPECT_EQ(driverManifestToAdd("SwiftShader Device", env.view()), kSwiftShaderManifest);
    EXPECT_EQ(driverManifestToAdd("llvmpipe", env.view()), "");
    EXPECT_EQ(driverManifestToAdd("", env.view()), "");
    EXPECT_EQ(driverManifestToAdd("0", env.view()), "");
}

TEST(NamedDrivers, NothingIsAddedWhenTheUserChoseTheDriversOrItIsMissingOrThere) {
    FakeEnvironment env;
    env.variables["VK_ICD_FILENAMES"] = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";
    EXPECT_EQ(driverManifestToAdd("swiftshader", env.view()), "");
    env.variables = {{"VK_DRIVER_FILES", "/somewhere/else.json"}};
    EXPECT_EQ(driverManifestToAdd("swiftshader", env.view()), "");
    env.variables = {{"VK_ADD_DRIVER_FILES", std::string("/a.json:") + kSwiftShaderManifest}};
    EXPECT_EQ(driverManifestToAdd("swiftshader", env.view()), "");
    env.variables = {{"VK_ADD_DRIVER_FILES", "/a.json"}};
    EXPECT_EQ(driverManifestToAdd("swiftshader", env.view()), kSwiftShaderManifest);
    env.variables.clear();
    env.manifestInstalled = false;
    EXPECT_EQ(driverManifestToAdd("swiftshader", env.view()), "");
}

TEST(NamedDrivers, ErrorsNameWhereTheSelectorCameFromAndWhereSwiftShaderComesFrom) {
    const std::vector<DeviceCandidate> devices{{"llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU, 0, ""}};
    try {
        chooseDevice(devices, "swiftshader", "CANDELA_DEVICE");
        FAIL() << "no error";
    } catch (const UserError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("CANDELA_DEVICE 'swiftshader' matches no Vulkan device"), std::string::npos) << what;
        EXPECT_NE(what.find("chromium"), std::string::npos) << what;
    }
    EXPECT_NE(chooseDevice(devices, "llvm", "CANDELA_DEVICE").reason.find("CANDELA_DEVICE"), std::string::npos);
}

}  // namespace
}  // namespace candela::vk
