// The CPU-built sample tables of the IBL filtering passes (ibl_prefilter, ibl_irradiance_cube).

#include "passes/ibl_sample_tables.h"

#include <gtest/gtest.h>

namespace candela::passes {
namespace {

TEST(IblSampleTables, PrefilterSamplesAreUnitAboveTheHorizonWithLodsInRange) {
    for (float roughness : {0.2f, 0.6f, 1.0f}) {
        const SampleTable table = prefilterSamples(roughness, 256, 256, 9, true, 0.5f);
        ASSERT_FALSE(table.samples.empty());
        EXPECT_LE(table.samples.size(), 256u);
        float weight = 0.0f;
        for (const glm::vec4& s : table.samples) {
            EXPECT_NEAR(glm::length(glm::vec3(s)), 1.0f, 1e-5f);
            EXPECT_GT(s.z, 0.0f);
            EXPECT_GE(s.w, 0.0f);
            EXPECT_LE(s.w, 8.0f);
            weight += s.z;
        }
        EXPECT_NEAR(weight, table.totalWeight, 1e-3f * weight);
    }
    // Rougher lobes spread wider (smaller mean n·l) and read coarser mips.
    auto mean = [](const SampleTable& t, int c) {
        double sum = 0;
        for (const glm::vec4& s : t.samples) sum += s[c];
        return sum / t.samples.size();
    };
    const SampleTable narrow = prefilterSamples(0.2f, 256, 256, 9, true, 0.5f);
    const SampleTable wide = prefilterSamples(1.0f, 256, 256, 9, true, 0.5f);
    EXPECT_GT(mean(narrow, 2), mean(wide, 2));
    EXPECT_LT(mean(narrow, 3), mean(wide, 3));
    // Plain importance sampling reads mip 0 only.
    for (const glm::vec4& s : prefilterSamples(0.6f, 64, 256, 9, false, 0.5f).samples) EXPECT_EQ(s.w, 0.0f);
}

TEST(IblSampleTables, CosineSamplesHaveTheCosineLobesMoments) {
    const SampleTable table = irradianceSamples(4096, 256, 9, true, 0.5f);
    ASSERT_EQ(table.samples.size(), 4096u);
    EXPECT_EQ(table.totalWeight, 4096.0f);
    double meanZ = 0, meanX = 0;
    for (const glm::vec4& s : table.samples) meanZ += s.z / 4096.0, meanX += s.x / 4096.0;
    EXPECT_NEAR(meanZ, 2.0 / 3.0, 1e-3);  // E[cos θ] under pdf cos θ / π
    EXPECT_NEAR(meanX, 0.0, 1e-3);
}

}  // namespace
}  // namespace candela::passes
