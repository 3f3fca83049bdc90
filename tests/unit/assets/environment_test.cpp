// Environments: every map in ../shared/assets/environments loads with sane statistics; the texel
// repair (sanitizeEnvironment) and the content hash behave as documented in environment.h.
#include "environment_test_util.h"
#include "core/cache_files.h"

#include <array>
#include <chrono>
#include <iostream>
#include <limits>

namespace candela::assets::test::environment_test {
namespace {

std::vector<fs::path> sharedMaps() {
    std::vector<fs::path> maps;
    if (const fs::path dir = sharedEnvironments(); !dir.empty())
        for (const fs::directory_entry& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".hdr" || entry.path().extension() == ".exr") maps.push_back(entry.path());
    std::sort(maps.begin(), maps.end());
    return maps;
}

float luminance(const float* t) { return 0.2126f * t[0] + 0.7152f * t[1] + 0.0722f * t[2]; }

TEST(EnvironmentAssets, EverySharedMapLoads) {
    const std::vector<fs::path> maps = sharedMaps();
    if (maps.empty()) GTEST_SKIP() << "no ../shared/assets/environments";
    for (const fs::path& path : maps) {
        SCOPED_TRACE(path.filename().string());
        const auto start = std::chrono::steady_clock::now();
        const Environment env = loadEnvironment(path);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

        EXPECT_EQ(env.width, 1024u);
        EXPECT_EQ(env.height, 512u);
        EXPECT_EQ(env.source, path.string());
        EXPECT_EQ(env.replacedTexels, 0u);
        EXPECT_TRUE(env.report.warnings.empty()) << env.report.warnings.front();
        uint32_t brightestX = 0, brightestY = 0;
        float brightest = -1.0f;
        for (uint32_t y = 0; y < env.height; ++y)
            for (uint32_t x = 0; x < env.width; ++x) {
                const float* t = env.texel(x, y);
                for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(t[c]) && t[c] >= 0.0f) << x << "," << y;
                if (luminance(t) > brightest) brightest = luminance(t), brightestX = x, brightestY = y;
            }
        // Solid-angle-weighted mean luminance: measured 0.084 (dikhololo_night) to 2.22 (studio_small_03).
        const double mean = meanLuminance(env);
        EXPECT_GT(mean, 0.02);
        EXPECT_LT(mean, 10.0);
        EXPECT_GT(brightest, 2.0 * mean) << "an HDR map has highlights well above its mean";
        // Pure skies: the sun (or at least the brightest texel) is above the horizon.
        if (path.stem().string().find("_puresky") != std::string::npos) {
            EXPECT_LT(brightestY, env.height / 2);
        }
        std::cout << "  " << path.filename().string() << ": " << ms << " ms, mean luminance " << mean << ", brightest "
                  << brightest << " at (" << brightestX << ", " << brightestY << ")\n";
    }
}

TEST(EnvironmentSanitize, CountsTexelsNotChannels) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    Environment env;
    env.source = "test";
    env.width = 4;
    env.height = 1;
    env.rgb = {nan, -1.0f, 2.0f, /**/ 1.0f, 2.0f, 3.0f, /**/ -0.0f, 0.0f, inf, /**/ 0.25f, -inf, 7.0f};
    EXPECT_EQ(sanitizeEnvironment(env), 3u);
    EXPECT_EQ(env.replacedTexels, 3u);
    EXPECT_EQ(env.rgb, (std::vector<float>{0, 0, 2, 1, 2, 3, 0, 0, 65504, 0.25f, 0, 7}));
    EXPECT_FALSE(std::signbit(env.rgb[6]));
    ASSERT_EQ(env.report.warnings.size(), 1u);
    EXPECT_EQ(env.report.warnings[0], "test: replaced 3 texels holding NaN, Inf or negative values (1 NaN and 2 negative values "
                               "set to 0, 1 +Inf set to 65504)");
    // A clean map is untouched and gets no warning; counts accumulate across calls.
    EXPECT_EQ(sanitizeEnvironment(env), 0u);
    EXPECT_EQ(env.replacedTexels, 3u);
    EXPECT_EQ(env.report.warnings.size(), 1u);
}

TEST(EnvironmentHash, DependsOnSizeAndEveryTexelBit) {
    Environment a;
    a.width = 2;
    a.height = 1;
    a.rgb = {1, 2, 3, 4, 5, 6};
    Environment b = a;
    b.source = "elsewhere";
    b.report.warnings = {"ignored"};
    EXPECT_EQ(contentHash(a), contentHash(b)) << "source and warnings are not content";
    Environment transposed = a;
    transposed.width = 1;
    transposed.height = 2;
    EXPECT_NE(contentHash(a), contentHash(transposed));
    Environment oneBit = a;
    oneBit.rgb[5] = std::nextafter(6.0f, 7.0f);
    EXPECT_NE(contentHash(a), contentHash(oneBit));
}

TEST(EnvironmentHash, IsWordHashOverLittleEndianWords) {
    // Pinned, so a change of the hash (which would orphan every on-disk IBL cache) is deliberate:
    // wordHash64 of the words 1, 1, 1.0f, 0.0f, 0.5f (width, height, texel), as computed outside.
    Environment env;
    env.width = 1;
    env.height = 1;
    env.rgb = {1.0f, 0.0f, 0.5f};
    EXPECT_EQ(hex16(contentHash(env)), "631650ab9ad6f45c");
    const std::array<uint8_t, 20> bytes = {1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0x80, 0x3f, 0, 0, 0, 0, 0, 0, 0, 0x3f};
    EXPECT_EQ(contentHash(env), wordHash64(0, bytes.data(), bytes.size()));
}

TEST(EnvironmentHash, SharedMapsHashDistinctly) {
    const std::vector<fs::path> maps = sharedMaps();
    if (maps.size() < 2) GTEST_SKIP() << "no ../shared/assets/environments";
    const uint64_t first = contentHash(loadEnvironment(maps[0]));
    EXPECT_EQ(first, contentHash(loadEnvironment(maps[0]))) << "deterministic";
    EXPECT_NE(first, contentHash(loadEnvironment(maps[1])));
}

}  // namespace
}  // namespace candela::assets::test::environment_test
