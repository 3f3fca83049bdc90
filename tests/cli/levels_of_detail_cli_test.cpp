// `candela render` builds a glTF file's levels of detail only when they pay for the frames asked
// (geometry/lod_cost.h): a still draws the full detail and says so in --explain; a sequence long
// enough builds them and draws coarser levels; with the on-disk cache (--lod-cache, on by default)
// stills of one file build them once every run's frames pay, and later runs read them.
#include "run_candela.h"
#include "temp_dir.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;
using candela::test::Result;
using candela::test::run;

class LevelsOfDetailCli : public testing::Test {
protected:
    Result render(const std::string& flags) {
        return run("render --validate --env none --width 64 --height 48 --explain --quiet --scene '" + mHelmet.string() + "' " +
                   flags);
    }
    fs::path mHelmet = candela::test::sharedAssets() / "models" / "DamagedHelmet" / "glTF-Binary" / "DamagedHelmet.glb";
    candela::test::TempDir mDir{"candela_lod_cli"};
};

TEST_F(LevelsOfDetailCli, AStillDrawsTheFullDetailWithoutBuildingLevels) {
    if (!fs::exists(mHelmet)) GTEST_SKIP() << "shared asset missing: " << mHelmet;
    const Result still = render("--out '" + (mDir.path() / "still.png").string() + "'");
    ASSERT_EQ(still.exitCode, 0) << still.stderrText;
    EXPECT_EQ(still.stderrText, "");
    EXPECT_NE(still.stdoutText.find("levels of detail: not built, every mesh drawn at full detail (drawing 15452 triangles at "
                                    "full detail for 1 frame costs about "),
              std::string::npos)
        << still.stdoutText;
    EXPECT_NE(still.stdoutText.find("15452 of 15452 triangles; 0 draws at a coarser level"), std::string::npos) << still.stdoutText;
}

TEST_F(LevelsOfDetailCli, ASequenceThatPaysForThemBuildsAndDrawsThem) {
    if (!fs::exists(mHelmet)) GTEST_SKIP() << "shared asset missing: " << mHelmet;
    // 8 frames of 15,452 triangles on lavapipe (0.55 µs each) cost some 68 ms; the build some 46
    // ms on one core. The helmet's one simplified level shows more than the default 0.5 px even at
    // 64 × 48: 8 px lets the frames draw it.
    const Result sequence = render("--frames 8 --lod-error 8 --out '" + (mDir.path() / "frame_%02d.png").string() + "'");
    ASSERT_EQ(sequence.exitCode, 0) << sequence.stderrText;
    EXPECT_EQ(sequence.stderrText, "");
    EXPECT_NE(sequence.stdoutText.find("levels of detail: built (drawing 15452 triangles at full detail for 8 frames costs about "),
              std::string::npos)
        << sequence.stdoutText;
    EXPECT_NE(sequence.stdoutText.find("1 draws at a coarser level"), std::string::npos) << sequence.stdoutText;
    // --lod off: never built, whatever the frames.
    const Result off = render("--lod off --frames 8 --out '" + (mDir.path() / "off_%02d.png").string() + "'");
    ASSERT_EQ(off.exitCode, 0) << off.stderrText;
    EXPECT_NE(off.stdoutText.find("levels of detail: not built (--lod off)"), std::string::npos) << off.stdoutText;
}

std::string bytesOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(LevelsOfDetailCli, StillsOfOneFileBuildThemOnceEveryRunsFramesPayAndLaterRunsReadThem) {
    if (!fs::exists(mHelmet)) GTEST_SKIP() << "shared asset missing: " << mHelmet;
    const fs::path cache = mDir.path() / "lod";
    const std::string flags = "--lod-error 8 --lod-cache '" + cache.string() + "' --out '";
    // 15,452 triangles: a still's frame costs some 8.5 ms, the build 46 ms on one core: a few runs.
    int built = 0;
    for (int run = 1; run <= 8 && !built; ++run) {
        const Result still = render(flags + (mDir.path() / ("run" + std::to_string(run) + ".png")).string() + "'");
        ASSERT_EQ(still.exitCode, 0) << still.stderrText;
        if (still.stdoutText.find("levels of detail: built (drawing 15452 triangles at full detail for " + std::to_string(run) +
                                  " frames") != std::string::npos) {
            built = run;
            EXPECT_NE(still.stdoutText.find("1 draws at a coarser level"), std::string::npos) << still.stdoutText;
        } else {
            EXPECT_NE(still.stdoutText.find("levels of detail: not built"), std::string::npos) << still.stdoutText;
            EXPECT_NE(still.stdoutText.find("0 draws at a coarser level"), std::string::npos) << still.stdoutText;
        }
        if (run > 1) {
            EXPECT_NE(still.stdoutText.find("; " + std::to_string(run - 1) + " of the frames drawn before, as the cache records)"),
                      std::string::npos)
                << still.stdoutText;
        }
    }
    ASSERT_GT(built, 1) << "stills never built the levels";
    const Result read = render(flags + (mDir.path() / "read.png").string() + "'");
    ASSERT_EQ(read.exitCode, 0) << read.stderrText;
    EXPECT_EQ(read.stderrText, "");
    EXPECT_NE(read.stdoutText.find("levels of detail: read from the cache (" + cache.string()), std::string::npos) << read.stdoutText;
    EXPECT_NE(read.stdoutText.find("1 draws at a coarser level"), std::string::npos) << read.stdoutText;
    EXPECT_EQ(bytesOf(mDir.path() / "read.png"), bytesOf(mDir.path() / ("run" + std::to_string(built) + ".png")))
        << "the chains read are those built";
    // --lod-cache off: this run's frame alone decides, whatever the folder holds.
    const Result off = render("--lod-error 8 --lod-cache off --out '" + (mDir.path() / "off.png").string() + "'");
    ASSERT_EQ(off.exitCode, 0) << off.stderrText;
    EXPECT_NE(off.stdoutText.find("levels of detail: not built, every mesh drawn at full detail (drawing 15452 triangles at full "
                                  "detail for 1 frame costs about "),
              std::string::npos)
        << off.stdoutText;
    // By default the user's cache folder holds the record.
    const Result byDefault = render("--out '" + (mDir.path() / "default.png").string() + "'");
    ASSERT_EQ(byDefault.exitCode, 0) << byDefault.stderrText;
    const fs::path userFolder = fs::path(std::getenv("XDG_CACHE_HOME")) / "candela" / "lod";
    ASSERT_TRUE(fs::is_directory(userFolder));
    EXPECT_EQ(std::distance(fs::directory_iterator(userFolder), fs::directory_iterator()), 1);
}

}  // namespace
