// --ibl-cache end to end: on by default in the user's cache folder (here this process's
// XDG_CACHE_HOME: run_candela.h), the second run loads the maps instead of computing them and
// draws the same image; a damaged file is a quiet miss, recomputed and replaced; off keeps nothing.
#include "run_candela.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using candela::test::fileText;
using candela::test::Result;
using candela::test::run;

std::vector<fs::path> mapFiles(const fs::path& folder) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.path().extension() == ".cibl") out.push_back(entry.path());
    return out;
}

fs::path mapsFolder() { return fs::path(std::getenv("XDG_CACHE_HOME")) / "candela" / "ibl"; }

// The built-in sky's maps at a small quality (quick to compute under validation).
const std::string kRender = "render --validate --width 32 --height 24 --ibl-cube-size 32 --ibl-levels 4 --explain --out ";

bool printed(const Result& r, const std::string& text) { return r.stdoutText.find(text) != std::string::npos; }

TEST(CliIblCache, OnByDefaultTheSecondRunLoadsTheMapsAndDrawsTheSameImage) {
    ASSERT_TRUE(candela::test::kPrivateCacheHome);
    candela::test::TempDir out("candela_cli_iblcache");
    fs::remove_all(mapsFolder());
    const Result first = run(kRender + (out / "a.png").string());
    ASSERT_EQ(first.exitCode, 0) << first.stderrText;
    EXPECT_TRUE(printed(first, "ibl: maps computed by this frame's precompute passes")) << first.stdoutText;
    const std::vector<fs::path> files = mapFiles(mapsFolder());
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(fileText(files[0]).substr(0, 12), std::string("CANDELA-IBL\0", 12));

    const Result second = run(kRender + (out / "b.png").string());
    ASSERT_EQ(second.exitCode, 0) << second.stderrText;
    EXPECT_EQ(second.stderrText, "");
    EXPECT_TRUE(printed(second, "left out: IBL precompute (maps loaded from the cache " + files[0].string() + ")")) << second.stdoutText;
    EXPECT_EQ(fileText(out / "a.png"), fileText(out / "b.png")) << "the maps read back are the maps computed";

    // Damaged: a quiet miss, the maps computed again and the file replaced.
    std::ofstream(files[0], std::ios::binary | std::ios::trunc) << "not an IBL cache";
    const Result damaged = run(kRender + (out / "c.png").string());
    ASSERT_EQ(damaged.exitCode, 0) << damaged.stderrText;
    EXPECT_EQ(damaged.stderrText, "");
    EXPECT_TRUE(printed(damaged, "ibl: maps computed by this frame's precompute passes")) << damaged.stdoutText;
    EXPECT_EQ(fileText(files[0]).substr(0, 12), std::string("CANDELA-IBL\0", 12));
    EXPECT_EQ(fileText(out / "a.png"), fileText(out / "c.png"));

    // Another quality is another key: a second file beside the first.
    const Result other = run(kRender + (out / "d.png").string() + " --ibl-levels 5");
    ASSERT_EQ(other.exitCode, 0) << other.stderrText;
    EXPECT_TRUE(printed(other, "ibl: maps computed by this frame's precompute passes")) << other.stdoutText;
    EXPECT_EQ(mapFiles(mapsFolder()).size(), 2u);
}

TEST(CliIblCache, OffComputesTheMapsAndKeepsNothingADirKeepsThemThere) {
    ASSERT_TRUE(candela::test::kPrivateCacheHome);
    candela::test::TempDir out("candela_cli_iblcache_off");
    fs::remove_all(mapsFolder());
    for (int i = 0; i < 2; ++i) {
        const Result off = run(kRender + (out / "off.png").string() + " --ibl-cache off");
        ASSERT_EQ(off.exitCode, 0) << off.stderrText;
        EXPECT_TRUE(printed(off, "ibl: maps computed by this frame's precompute passes")) << off.stdoutText;
    }
    EXPECT_TRUE(mapFiles(mapsFolder()).empty());
    const fs::path dir = out / "maps";
    for (const char* line : {"ibl: maps computed by this frame's precompute passes", "left out: IBL precompute (maps loaded from the cache "}) {
        const Result r = run(kRender + (out / "dir.png").string() + " --ibl-cache '" + dir.string() + "'");
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
        EXPECT_TRUE(printed(r, line)) << r.stdoutText;
    }
    EXPECT_EQ(mapFiles(dir).size(), 1u);
    EXPECT_TRUE(mapFiles(mapsFolder()).empty());
}

}  // namespace
