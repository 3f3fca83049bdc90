// Index values against maxDrawIndexedIndexValue (gpu_scene/gpu_scene.h checkIndexValues): a device
// without fullDrawIndexUint32 (the minimum profile) refuses a scene whose indices pass 2^24−1 with a
// one-line error instead of drawing it wrong; one with the feature draws it.
#include "gpu_scene/gpu_scene.h"
#include "vk/profile_caps.h"

#include "core/errors.h"

#include <gtest/gtest.h>

namespace candela::gpu_scene {
namespace {

vk::DeviceCaps deviceWithFullIndices() {
    vk::DeviceCaps caps;
    caps.features.fullDrawIndexUint32 = true;
    caps.limits.maxDrawIndexedIndexValue = 0xFFFFFFFFu;
    return caps;
}

scene::Scene sceneWithLargestIndex(uint32_t largest) {
    scene::Scene scene;
    scene.source = "big.glb";
    scene.indices = {0, 1, largest, 2, 3, 4};
    return scene;
}

TEST(IndexValues, MinimumProfileRefusesIndicesPast24Bits) {
    const vk::DeviceCaps minimum = vk::narrowCaps(deviceWithFullIndices(), options::DeviceProfile::Minimum);
    EXPECT_FALSE(minimum.features.fullDrawIndexUint32);
    EXPECT_EQ(minimum.limits.maxDrawIndexedIndexValue, (1u << 24) - 1);
    EXPECT_NO_THROW(checkIndexValues(sceneWithLargestIndex((1u << 24) - 1), minimum));
    try {
        checkIndexValues(sceneWithLargestIndex(1u << 24), minimum);
        FAIL() << "no error";
    } catch (const UserError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("big.glb"), std::string::npos) << message;
        EXPECT_NE(message.find("16777216"), std::string::npos) << message;
        EXPECT_NE(message.find("maxDrawIndexedIndexValue (16777215; no fullDrawIndexUint32)"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
}

TEST(IndexValues, FullDrawIndexUint32DrawsEveryIndex) {
    EXPECT_NO_THROW(checkIndexValues(sceneWithLargestIndex(0xFFFFFFFEu), deviceWithFullIndices()));
    EXPECT_NO_THROW(checkIndexValues(scene::Scene{}, vk::narrowCaps(deviceWithFullIndices(), options::DeviceProfile::Minimum)));
}

}  // namespace
}  // namespace candela::gpu_scene
