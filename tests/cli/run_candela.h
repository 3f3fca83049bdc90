#pragma once
// Runs the real `candela` executable for the CLI tests: the build tree's (CANDELA_EXECUTABLE), or
// the one the environment variable CANDELA_EXECUTABLE names (the sanitized stage of
// tools/build-and-test.sh runs this binary against the sanitized executable).

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <utility>

namespace candela::test {

// The executable the tests run.
inline std::string candelaExecutable() {
    const char* chosen = std::getenv("CANDELA_EXECUTABLE");
    return chosen && *chosen ? chosen : CANDELA_EXECUTABLE;
}

// Empties the folder it is given at the start of every test.
class EmptyFolderPerTest : public testing::EmptyTestEventListener {
public:
    explicit EmptyFolderPerTest(std::filesystem::path folder) : mFolder(std::move(folder)) {}
    void OnTestStart(const testing::TestInfo&) override {
        std::error_code ec;
        std::filesystem::remove_all(mFolder, ec);
        std::filesystem::create_directories(mFolder, ec);
    }

private:
    std::filesystem::path mFolder;
};

// The executable's cache folder (XDG_CACHE_HOME: its pipeline, IBL and level-of-detail caches go
// there by default) is a folder of this test process, removed at exit: the tests never write into
// the user's cache. It is emptied before each test, so that a test sees the same caches whether
// it runs alone (ctest: one process a test) or after others in one process (the sanitized stage's
// shards): the level-of-detail cache counts the frames of earlier runs of a file, and another
// test's renders would change what this one builds.
inline const bool kPrivateCacheHome = [] {
    static const TempDir home("candela_cli_cache_home");
    ::setenv("XDG_CACHE_HOME", home.path().c_str(), 1);
    testing::UnitTest::GetInstance()->listeners().Append(new EmptyFolderPerTest(home.path()));  // owned by GoogleTest
    return true;
}();

struct Result {
    int exitCode = -1;
    std::string stderrText;
    std::string stdoutText;
};

// Runs candela with `args` (shell syntax); captures stderr and stdout.
inline Result run(const std::string& args) {
    const auto stdoutFile =
        std::filesystem::temp_directory_path() / ("candela_cli_stdout_" + std::to_string(::getpid()) + ".txt");
    const std::string command = candelaExecutable() + " " + args + " 2>&1 >" + stdoutFile.string();
    FILE* pipe = popen(command.c_str(), "r");
    Result result;
    std::array<char, 4096> buffer;
    while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) result.stderrText.append(buffer.data(), n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream out(stdoutFile);
    result.stdoutText.assign(std::istreambuf_iterator<char>(out), std::istreambuf_iterator<char>());
    std::filesystem::remove(stdoutFile);
    return result;
}

// The bytes of the file at `path` ("" when it cannot be read).
inline std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace candela::test
