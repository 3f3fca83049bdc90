// The CPU-built sample tables of the IBL filtering passes (ibl_prefilter, ibl_irradiance_cube).

#include "passes/ibl/ibl_sample_tables.h"

#include "shared/ibl.h"

#include <cmath>
#include <numbers>

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

// The lobe table read as ibl_filter_cube.comp reads it (lobeWeight): θ → (π/2)(j/(size−1))², linear.
double tableWeight(const std::vector<float>& table, double theta) {
    if (theta >= 0.5 * std::numbers::pi) return 0.0;
    const double f = std::sqrt(theta * 2.0 / std::numbers::pi) * (table.size() - 1);
    const size_t j = std::min(size_t(f), table.size() - 2);
    return table[j] + (table[j + 1] - table[j]) * (f - double(j));
}

// 2π ∫ g(θ) lobe(θ) sin θ dθ over the hemisphere, in θ = (π/2)t² steps (fine where the lobes peak).
template <typename G>
double lobeMoment(const std::vector<float>& table, G g) {
    constexpr int kSteps = 200000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double t = (i + 0.5) / kSteps;
        const double theta = 0.5 * std::numbers::pi * t * t;
        sum += g(theta) * tableWeight(table, theta) * std::sin(theta) * std::numbers::pi * t / kSteps;
    }
    return 2.0 * std::numbers::pi * sum;
}

// Every lobe table, read as the shader reads it, is a density: it integrates to 1 over the sphere
// (tolerance 2e-3: the linear interpolation between entries at the narrowest lobe, α = 0.01).
TEST(IblLobeTables, IntegrateToOneAsTheShaderReadsThem) {
    for (FilterLobe lobe : {FilterLobe::Ggx, FilterLobe::Charlie, FilterLobe::Cosine})
        for (float roughness : {0.1f, 0.2f, 0.6f, 1.0f}) {
            const std::vector<float> table = lobeTable(lobe, roughness);
            ASSERT_EQ(table.size(), CANDELA_IBL_LOBE_TABLE_SIZE);
            EXPECT_NEAR(lobeMoment(table, [](double) { return 1.0; }), 1.0, 2e-3)
                << "lobe " << int(lobe) << " roughness " << roughness;
        }
}

// Independent checks of the tables' shapes: at α = 1 GGX's D is 1/π, so D (n·l)/4 normalised is
// the cosine lobe n·l/π; the cosine table is n·l/π itself.
TEST(IblLobeTables, GgxAtRoughnessOneIsTheCosineLobe) {
    const std::vector<float> ggx = lobeTable(FilterLobe::Ggx, 1.0f);
    const std::vector<float> cosine = lobeTable(FilterLobe::Cosine, 0.0f);
    for (size_t j = 0; j < ggx.size(); j += 37) {
        const double t = double(j) / (ggx.size() - 1);
        const double expected = std::cos(0.5 * std::numbers::pi * t * t) / std::numbers::pi;
        EXPECT_NEAR(ggx[j], expected, 1e-5) << j;
        EXPECT_NEAR(cosine[j], expected, 1e-6) << j;
    }
}

// The tables and the sample tables describe the same lobes: the mean n·l over a lobe table equals
// that of the samples (the prefilter's n·l-weighted GGX samples; the Charlie samples, each weight 1).
// Tolerance 1e-2: 4096 Hammersley samples.
TEST(IblLobeTables, AgreeWithTheSampleTables) {
    for (float roughness : {0.2f, 0.5f, 1.0f}) {
        const double tableMean = lobeMoment(lobeTable(FilterLobe::Ggx, roughness), [](double th) { return std::cos(th); });
        const SampleTable samples = prefilterSamples(roughness, 4096, 256, 9, true, 0.5f);
        double weighted = 0.0;
        for (const glm::vec4& s : samples.samples) weighted += double(s.z) * s.z;
        EXPECT_NEAR(tableMean, weighted / samples.totalWeight, 1e-2) << "GGX roughness " << roughness;

        const double charlieMean =
            lobeMoment(lobeTable(FilterLobe::Charlie, roughness), [](double th) { return std::cos(th); });
        const SampleTable charlie = charlieSamples(roughness, 4096, 256, 9, true, 0.5f);
        double mean = 0.0;
        for (const glm::vec4& s : charlie.samples) mean += s.z / double(charlie.samples.size());
        EXPECT_NEAR(charlieMean, mean, 1e-2) << "Charlie roughness " << roughness;
    }
}

}  // namespace
}  // namespace candela::passes
