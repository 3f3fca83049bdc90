// --pipeline-cache end to end: the executable keeps its pipeline cache in the user's cache folder
// (here this process's XDG_CACHE_HOME: run_candela.h), in the folder the flag names, or nowhere;
// a damaged file there is replaced quietly.
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

// The pipeline cache files in `folder` (none when it does not exist).
std::vector<fs::path> cacheFiles(const fs::path& folder) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.path().filename().string().rfind("pipelines-", 0) == 0) out.push_back(entry.path());
    return out;
}

fs::path userFolder() { return fs::path(std::getenv("XDG_CACHE_HOME")) / "candela"; }

const std::string kSmallRender = "render --validate --width 16 --height 16 --env none --out ";

TEST(CliPipelineCache, DefaultsToTheUsersCacheFolderAndReplacesADamagedFileQuietly) {
    ASSERT_TRUE(candela::test::kPrivateCacheHome);
    candela::test::TempDir out("candela_cli_pcache");
    fs::remove_all(userFolder());
    Result r = run(kSmallRender + (out / "a.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    const std::vector<fs::path> files = cacheFiles(userFolder());
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(fileText(files[0]).substr(0, 12), std::string("CANDELA-PSO\0", 12));

    std::ofstream(files[0], std::ios::binary | std::ios::trunc) << "not a pipeline cache";
    r = run(kSmallRender + (out / "b.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_EQ(r.stderrText, "");  // ignored without a word...
    EXPECT_EQ(fileText(files[0]).substr(0, 12), std::string("CANDELA-PSO\0", 12));  // ...and replaced
    std::ofstream(files[0], std::ios::binary | std::ios::trunc) << "not a pipeline cache";
    r = run(kSmallRender + (out / "c.png").string() + " --verbose");
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    // With --verbose, one line (beside the camera's and the time-to-image profile's, which
    // --verbose prints too).
    EXPECT_NE(r.stderrText.find("ignored"), std::string::npos) << r.stderrText;
    size_t cacheLines = 0;
    for (size_t at = r.stderrText.find("candela: pipeline cache "); at != std::string::npos;
         at = r.stderrText.find("candela: pipeline cache ", at + 1))
        ++cacheLines;
    EXPECT_EQ(cacheLines, 1u) << r.stderrText;
    EXPECT_EQ(std::count(r.stderrText.begin(), r.stderrText.end(), '\n'), 4) << r.stderrText;
    EXPECT_NE(r.stderrText.find("candela: camera: --camera-orbit"), std::string::npos) << r.stderrText;
}

TEST(CliPipelineCache, TheFlagNamesTheFolderOrTurnsTheFileOff) {
    candela::test::TempDir out("candela_cli_pcache");
    fs::remove_all(userFolder());
    Result r = run(kSmallRender + (out / "a.png").string() + " --pipeline-cache " + (out / "cache").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_EQ(cacheFiles(out / "cache").size(), 1u);
    EXPECT_TRUE(cacheFiles(userFolder()).empty());
    r = run(kSmallRender + (out / "b.png").string() + " --pipeline-cache off --explain");
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_NE(r.stdoutText.find("pipeline cache: off (in memory only)"), std::string::npos) << r.stdoutText;
    EXPECT_TRUE(cacheFiles(userFolder()).empty());
    // info builds no pipeline: it leaves the cache alone.
    r = run("info");
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_TRUE(cacheFiles(userFolder()).empty());
}

}  // namespace
