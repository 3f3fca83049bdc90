// The README's commands, run as written: every ```sh block of README.md is one test, its commands
// run in order in an empty folder where `build/release/app/candela` is the real executable, with
// SAMPLES naming the shared sample assets (../shared/assets; skipped when absent) and
// CANDELA_VALIDATE=1 (the Khronos validation layer with synchronization validation). A command
// must exit 0 and print no validation message. Left out, by name: the set-up commands
// tools/build-and-render.sh and tools/build-and-test.sh (they build; kSetUpCommands). `candela
// view` commands are interactive (they run until the window is closed): each runs under a private
// Xvfb for kViewSeconds and must print no error and no validation message in that time (or exit
// 0), then is ended. Every ```python block is one test too: the block runs as a script with the
// Python the module was built for and PYTHONPATH at the build tree's package (python/), under the
// same rules. See docs/testing.md#the-readmes-commands.
#include "run_candela.h"
#include "test_paths.h"
#include "../viewer/xvfb.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace candela::test {
namespace {

namespace fs = std::filesystem;

// The README's set-up commands: they install packages and build, so the test does not run them.
const std::vector<std::string> kSetUpCommands = {"tools/build-and-render.sh", "tools/build-and-test.sh"};
constexpr const char* kExecutable = "build/release/app/candela";
constexpr int kViewSeconds = 6;
constexpr int kCommandTimeoutSeconds = 600;

struct Block {
    int line = 0;  // of the opening fence
    std::vector<std::string> commands;  // a ```sh block's
    bool python = false;                // a ```python block: `script`
    std::string script;
};

void PrintTo(const Block& block, std::ostream* os) { *os << "README.md line " << block.line; }

std::vector<std::string> readmeLines() {
    std::ifstream in(CANDELA_README);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The ```sh blocks: one command per line, a trailing backslash continues it; blank lines and
// lines that are only a comment are not commands. And the ```python blocks, each a script.
std::vector<Block> shBlocks(const std::vector<std::string>& lines) {
    std::vector<Block> blocks;
    bool inSh = false, inPython = false, inOther = false;
    std::string pending;
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (!inSh && !inPython && !inOther && startsWith(line, "```")) {
            inSh = line == "```sh";
            inPython = line == "```python";
            inOther = !inSh && !inPython;
            if (inSh || inPython) blocks.push_back({.line = int(i + 1), .python = inPython});
            continue;
        }
        if ((inSh || inPython || inOther) && line == "```") {
            inSh = inPython = inOther = false;
            continue;
        }
        if (inPython) blocks.back().script += line + "\n";
        if (!inSh) continue;
        if (!line.empty() && line.back() == '\\') {
            pending += line.substr(0, line.size() - 1);
            continue;
        }
        std::string command = pending + line;
        pending.clear();
        const size_t first = command.find_first_not_of(' ');
        if (first == std::string::npos || command[first] == '#') continue;
        blocks.back().commands.push_back(command.substr(first));
    }
    return blocks;
}

bool isSetUp(const std::string& command) {
    for (const std::string& setUp : kSetUpCommands)
        if (startsWith(command, setUp)) return true;
    return false;
}

bool isView(const std::string& command) { return startsWith(command, std::string(kExecutable) + " view"); }

// The blocks that hold a command the test runs.
std::vector<Block> runnableBlocks() {
    std::vector<Block> out;
    for (Block& block : shBlocks(readmeLines())) {
        bool runnable = block.python;
        for (const std::string& command : block.commands) runnable = runnable || !isSetUp(command);
        if (runnable) out.push_back(std::move(block));
    }
    return out;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

struct Outcome {
    bool exited = false;  // false: still running at the deadline (then ended)
    int exitCode = -1;
    std::string stderrText;
};

// Runs `command` through /bin/sh in `dir` (stdout and stderr to files there); waits up to
// `seconds`, then ends the command's process group.
Outcome runIn(const fs::path& dir, const std::string& command, int seconds) {
    const fs::path out = dir / ".readme_stdout", err = dir / ".readme_stderr";
    const pid_t pid = fork();
    if (pid == 0) {
        setpgid(0, 0);
        if (chdir(dir.c_str()) != 0) _exit(126);
        const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0) _exit(126);
        dup2(o, STDOUT_FILENO);
        dup2(e, STDERR_FILENO);
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    Outcome outcome;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    int status = 0;
    while (true) {
        if (waitpid(pid, &status, WNOHANG) == pid) {
            outcome.exited = true;
            outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
            break;
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            kill(-pid, SIGTERM);
            waitpid(pid, &status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    outcome.stderrText = readFile(err);
    return outcome;
}

// The lines of `text` that hold `needle`.
std::string linesWith(const std::string& text, const std::string& needle) {
    std::istringstream in(text);
    std::string out;
    for (std::string line; std::getline(in, line);)
        if (line.find(needle) != std::string::npos) out += line + "\n";
    return out;
}

class ReadmeBlock : public ::testing::TestWithParam<Block> {};

TEST_P(ReadmeBlock, EveryCommandRuns) {
    const fs::path samples = fs::weakly_canonical(::candela::test::sharedAssets());
    if (!fs::exists(samples / "models") || !fs::exists(samples / "environments"))
        GTEST_SKIP() << "the shared sample assets are missing (" << samples << ")";
    ASSERT_TRUE(kPrivateCacheHome);  // the executable's pipeline cache goes to a private folder
    setenv("SAMPLES", samples.c_str(), 1);
    setenv("CANDELA_VALIDATE", "1", 1);
    const TempDir dir("candela_readme");
    fs::create_directories(dir.path() / "build/release/app");
    fs::create_symlink(CANDELA_EXECUTABLE, dir.path() / kExecutable);

    std::vector<std::string> commands = GetParam().commands;
    if (GetParam().python) {
#ifdef CANDELA_PYTHON
        setenv("PYTHONPATH", CANDELA_PYTHON_PATH, 1);
        std::ofstream(dir.path() / ".readme_block.py") << GetParam().script;
        commands = {std::string(CANDELA_PYTHON) + " .readme_block.py"};
#else
        GTEST_SKIP() << "the Python module is not built";
#endif
    }

    XvfbEnvironment xvfb;  // started for the first `view` command when DISPLAY is unset
    bool xvfbStarted = false;
    for (const std::string& command : commands) {
        if (isSetUp(command)) continue;
        SCOPED_TRACE("README.md block at line " + std::to_string(GetParam().line) + ": " + command);
        const auto start = std::chrono::steady_clock::now();
        if (isView(command) && !xvfbStarted) {
            xvfb.SetUp();
            xvfbStarted = true;
            ASSERT_FALSE(HasFatalFailure());
        }
        const Outcome outcome = runIn(dir.path(), command, isView(command) ? kViewSeconds : kCommandTimeoutSeconds);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%6.1f s  %s\n", seconds, command.c_str());
        if (!isView(command)) {
            EXPECT_TRUE(outcome.exited) << "still running after " << kCommandTimeoutSeconds << " s";
            EXPECT_EQ(outcome.exitCode, 0) << outcome.stderrText;
        } else if (outcome.exited) {
            EXPECT_EQ(outcome.exitCode, 0) << outcome.stderrText;
        }
        // The executable prints each validation message ("validation error: …", "validation
        // warning: …") and their count ("N validation messages").
        EXPECT_EQ(linesWith(outcome.stderrText, "validation "), "");
        EXPECT_EQ(linesWith(outcome.stderrText, "error:"), "");
    }
    if (xvfbStarted) xvfb.TearDown();
}

// The README's examples are all in ```sh blocks (none escapes the test in an indented block), and
// the set-up commands the test leaves out are there.
TEST(ReadmeCommands, EveryExampleIsInAShBlock) {
    const std::vector<std::string> lines = readmeLines();
    ASSERT_FALSE(lines.empty()) << "cannot read " << CANDELA_README;
    size_t inBlocks = 0, everywhere = 0;
    for (const Block& block : shBlocks(lines))
        for (const std::string& command : block.commands) inBlocks += startsWith(command, kExecutable);
    for (const std::string& line : lines) {
        const size_t first = line.find_first_not_of(' ');
        everywhere += first != std::string::npos && startsWith(line.substr(first), kExecutable);
    }
    EXPECT_GT(inBlocks, 0u);
    EXPECT_EQ(inBlocks, everywhere) << "a README line starting with " << kExecutable << " is outside the ```sh blocks";
    for (const std::string& setUp : kSetUpCommands) {
        bool found = false;
        for (const Block& block : shBlocks(lines))
            for (const std::string& command : block.commands) found = found || command == setUp;
        EXPECT_TRUE(found) << setUp << " is no longer a README command: update kSetUpCommands";
    }
}

INSTANTIATE_TEST_SUITE_P(Readme, ReadmeBlock, ::testing::ValuesIn(runnableBlocks()),
                         [](const ::testing::TestParamInfo<Block>& block) { return "line" + std::to_string(block.param.line); });

}  // namespace
}  // namespace candela::test
