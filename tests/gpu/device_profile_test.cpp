// A context created under a device profile (ContextDesc::profile): its caps are the profile's
// ceiling, a program over its per-stage limits is refused by name, and an environment wider than
// its images may be is halved before the precompute reads it. These run under the minimum profile
// whatever CANDELA_DEVICE_PROFILE says.
#include "gpu_test.h"

#include "assets/builtin_scenes.h"
#include "core/errors.h"
#include "ibl_maps/ibl_maps.h"
#include "render/renderer.h"
#include "reports/ibl_reference.h"

#include <cmath>

namespace candela::test {
namespace {

class MinimumProfileTest : public GpuTest {
protected:
    void SetUp() override {
        mContext = std::make_unique<vk::Context>(vk::ContextDesc{.validation = true, .profile = options::DeviceProfile::Minimum});
    }
};

TEST_F(MinimumProfileTest, TheContextSeesTheProfile) {
    EXPECT_EQ(context().profile(), options::DeviceProfile::Minimum);
    EXPECT_EQ(context().report().profile, "minimum");
    EXPECT_EQ(context().caps().limits.maxPerStageDescriptorSamplers, 16u);
    EXPECT_EQ(context().caps().limits.maxImageDimension2D, 4096u);
    EXPECT_FALSE(context().alphaToOne());
    EXPECT_TRUE(context().choices().specializeLayeredProgram);
}

TEST_F(MinimumProfileTest, AProgramOverAPerStageLimitIsRefusedByName) {
    // The layered program with every layer: 25 samplers in the fragment stage.
    try {
        const vk::Program program(context(), {"forward_layers.vert", "forward_layers.frag"});
        FAIL() << "expected a throw";
    } catch (const UserError& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("(device profile minimum) cannot run forward_layers.vert+forward_layers.frag: 25 samplers in "
                            "the fragment stage, the device allows 16 (maxPerStageDescriptorSamplers)"),
                  std::string::npos)
            << text;
    }
}

TEST_F(MinimumProfileTest, AnEnvironmentWiderThanTheDeviceAllowsIsHalvedToFit) {
    // Metric: the IBL settings the maps were computed with name the limit, and the frame is finite
    // and lit by the environment (constant 0.5: the sphere is grey, not black).
    const assets::Environment env = reports::reference::makeEnvironment(8192, 32, [](const glm::dvec3&) { return glm::dvec3(0.5); });
    const scene::Scene scene = assets::makeSphereGrid(1);
    Renderer renderer(context());
    const CapturedFrame frame =
        renderer.capture({.width = 32, .height = 32, .floatOutput = true, .scene = &scene, .environment = &env});
    bool lit = false;
    for (size_t i = 0; i < frame.rgba32f.size(); ++i) {
        ASSERT_TRUE(std::isfinite(frame.rgba32f[i]));
        lit = lit || (i % 4 == 0 && frame.rgba32f[i] > 0.05f);
    }
    EXPECT_TRUE(lit);
    bool named = false;
    for (const std::string& line : renderer.iblMaps().explanation()) named = named || line.find("equirect<=4096") != std::string::npos;
    EXPECT_TRUE(named);
}

}  // namespace
}  // namespace candela::test
