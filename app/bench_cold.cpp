#include "bench_cold.h"

#include "session.h"
#include "statistics.h"
#include "stopwatch.h"

#include "core/errors.h"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

extern char** environ;

namespace candela::app {
namespace {

namespace fs = std::filesystem;

// Runs this executable with `arguments`, stdout to /dev/null and stderr to `errors`; returns its
// exit status (-1: it could not start, or died of a signal).
int runSelf(const std::vector<std::string>& arguments, const fs::path& errors) {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw UserError("bench --cold: cannot find this executable (/proc/self/exe): " + ec.message());
    std::vector<std::string> words = {self.string()};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
    return WEXITSTATUS(status);
}

std::string firstLine(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

}  // namespace

int runColdBench(const BenchOptions& options, const std::vector<std::string>& benchArguments) {
    const fs::path folder = fs::temp_directory_path() / ("candela-bench-cold-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::vector<std::string> arguments = {"render"};
    for (const std::string& word : coldRenderArguments(benchArguments)) arguments.push_back(word);
    arguments.insert(arguments.end(), {"--out", (folder / "cold.png").string(), "--quiet"});
    const fs::path errors = folder / "stderr.txt";

    Session session(options.common, options.env);
    session.start();
    Renderer& renderer = session.renderer();
    std::vector<double> runMs, calibrationMs;
    const auto calibrate = [&] { calibrationMs.push_back(renderer.renderCalibration(options.width, options.height).submitWaitMs); };
    calibrate();  // its pipeline built: the first measured calibration is warm
    calibrationMs.clear();
    for (uint32_t i = 0; i < options.cold; ++i) {
        calibrate();
        const auto start = Clock::now();
        const int code = runSelf(arguments, errors);
        runMs.push_back(msSince(start));
        if (code != 0) {
            const std::string why = firstLine(errors);
            fs::remove_all(folder);
            throw UserError("bench --cold: `candela render` exited with " + std::to_string(code) + (why.empty() ? "" : ": " + why));
        }
    }
    calibrate();
    fs::remove_all(folder);

    const double calibration = median(calibrationMs);
    const std::vector<double> warm(runMs.begin() + 1, runMs.end());
    if (options.json) {
        nlohmann::ordered_json out;
        out["command"] = arguments;
        out["calibrationMs"] = calibrationMs;
        out["runMs"] = runMs;
        out["firstMs"] = runMs.front();
        out["firstRatio"] = runMs.front() / calibration;
        if (!warm.empty()) {
            out["warmMedianMs"] = median(warm);
            out["warmMinMs"] = *std::min_element(warm.begin(), warm.end());
            out["warmRatio"] = median(warm) / calibration;
        }
        std::printf("%s\n", out.dump(2).c_str());
        return session.exitCode(0);
    }
    std::string command = "candela";
    for (const std::string& word : arguments) command += " " + word;
    std::printf("cold: %u fresh processes of `%s`, from process start to the image written\n", options.cold, command.c_str());
    std::printf("  calibration: median %.2f ms (this process, %zu runs between them)\n", calibration, calibrationMs.size());
    std::printf("  first:       %.1f ms (%.1fx calibration; the caches as they were)\n", runMs.front(), runMs.front() / calibration);
    if (!warm.empty())
        std::printf("  then:        median %.1f ms (min %.1f; %.1fx calibration; pipeline and IBL caches warm)\n", median(warm),
                    *std::min_element(warm.begin(), warm.end()), median(warm) / calibration);
    return session.exitCode(0);
}

}  // namespace candela::app
