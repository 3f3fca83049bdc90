// IBL quality settings (validation, cache-key text).

#include "core/errors.h"
#include "ibl/ibl_settings.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela::ibl {
namespace {

TEST(IblSettings, DefaultsAreValidAndLevelsAreCappedByTheCubeSize) {
    IblQuality q;
    EXPECT_NO_THROW(q.validate());
    EXPECT_EQ(q.levels(), 8u);
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
    EXPECT_TRUE(differs([](IblQuality& q) { q.prefilterSamples = 32; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.filteredSampling = false; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.lodBias = 1.0f; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.brightTexels = 0; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.irradiance = IrradianceMode::Sh9; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.irradianceSamples = 1024; }));
    EXPECT_TRUE(differs([](IblQuality& q) { q.lutSamples = 64; }));
    // The SH9 source size does not matter in cube mode (the default), nor the cube's settings in
    // SH9 mode: they must not split the cache.
    EXPECT_FALSE(differs([](IblQuality& q) { q.shSourceSize = 64; }));
    IblQuality sh9 = base;
    sh9.irradiance = IrradianceMode::Sh9;
    IblQuality sh9MoreSamples = sh9;
    sh9MoreSamples.irradianceSamples = 1024;
    EXPECT_EQ(sh9.canonical(), sh9MoreSamples.canonical());
    IblQuality sh9OtherSize = sh9;
    sh9OtherSize.shSourceSize = 64;
    EXPECT_NE(sh9.canonical(), sh9OtherSize.canonical());
    EXPECT_EQ(base.lutCanonical(), "lut=128x256");
}

}  // namespace
}  // namespace candela::ibl
