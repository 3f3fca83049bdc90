// `candela render` builds a glTF file's levels of detail only when they pay for the frames asked
// (geometry/lod_cost.h): a still draws the full detail and says so in --explain; a sequence long
// enough builds them and draws coarser levels.
#include "run_candela.h"
#include "temp_dir.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
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

}  // namespace
