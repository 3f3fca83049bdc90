#pragma once
// The `candela` subcommands. Each returns the process exit code; errors are thrown (user errors
// as candela::UserError) and reported by main() (failures.h).

#include "cli.h"

#include <filesystem>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

namespace candela::app {

int runRender(const RenderOptions& options);
int runBench(const BenchOptions& options, const std::vector<std::string>& arguments);
int runView(const ViewOptions& options);
int runInfo(const InfoOptions& options);
int runIblReport(const IblReportOptions& options);
int runSoak(const SoakOptions& options);
int runScaleReport(const ScaleReportOptions& options);
int runQualityReport(const QualityReportOptions& options);
int runDiff(const DiffOptions& options);

// Writes `text` to the file `path` (replacing it); a UserError "PATH: cannot write" otherwise.
void writeText(const std::string& path, const std::string& text);
// A text file streamed into memory and written atomically (writeText) by commit(); nothing is
// written without it.
class TextFile : public std::ostringstream {
public:
    explicit TextFile(std::filesystem::path path) : mPath(std::move(path)) {}
    void commit() { writeText(mPath.string(), str()); }

private:
    std::filesystem::path mPath;
};
// Creates the report folder `out` and checks that each of `files` can be written in it; a
// UserError names the folder or file otherwise (ibl-report, scale-report).
void prepareReportFolder(const std::filesystem::path& out, std::initializer_list<const char*> files);

}  // namespace candela::app
