// IBL quality settings (validation, cache-key text) and the CPU-built sample tables of the
// filtering passes.

#include "core/check.h"
#include "ibl/ibl_sample_tables.h"
#include "ibl/ibl_settings.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela::ibl {
namespace {

TEST(IblSettings, DefaultsAreValidAndLevelsAreCappedByTheCubeSize) {
    IblQuality q;
    EXPECT_NO_THROW(q.validate());
    EXPECT_EQ(q.levels(), 6u);
    q.cubeSize = 16;
    q.shSourceSize = 16;
    q.specularLevels = 10;
    EXPECT_EQ(q.levels(), 5u);  // 16, 8, 4, 2, 1
}

TEST(IblSettings, InvalidMembersAreNamedInTheError) {
    auto message = [](auto change) {
        IblQuality q;
        change(q);
        try {
            q.validate();
        } catch (const UserError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message([](IblQuality& q) { q.cubeSize = 100; }), "--ibl-cube-size 100: must be a power of two from 16 to 2048");
    EXPECT_EQ(message([](IblQuality& q) { q.shSourceSize = 512; }), "--ibl-sh-size 512: must be a power of two from 1 to 256");
    EXPECT_EQ(message([](IblQuality& q) { q.prefilterSamples = 0; }), "--ibl-prefilter-samples 0: must be from 1 to 65536");
    EXPECT_EQ(message([](IblQuality& q) { q.lutSize = 1; }), "--ibl-lut-size 1: must be from 2 to 1024");
    EXPECT_NE(message([](IblQuality& q) { q.lodBias = NAN; }).find("--ibl-lod-bias"), std::string::npos);
}

TEST(IblSettings, CanonicalTextSeparatesEverySettingThatChangesTheMaps) {
    const IblQuality base;
    const std::string text = base.canonical();
    auto differs = [&](auto change) {
        IblQuality q = base;
        change(q);
        return q.canonical() != text;
    };
    EXPECT_TRUE(differs([](IblQuality& q) { q.cubeSize = 512; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.prefilterSamples = 64; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.filteredSampling = false; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.lodBias = 1.0f; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.irradiance = IrradianceMode::Cube; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.shSourceSize = 64; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.lutSamples = 64; }));
    // The irradiance cube's settings do not matter in SH9 mode: they must not split the cache.
    EXPECT_FALSE(differs([](IblQuality& q) { q.irradianceSamples = 1024; }));
    EXPECT_EQ(base.lutCanonical(), "lut=128x256");
}

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
}  // namespace candela::ibl
