#pragma once
// The figures `candela ibl-report` measured (report.csv): per quality setting, the precompute time
// as a ratio to the calibration pass and the errors against the reference. The viewer's
// environment panel shows them next to the settings; three runs are compiled in
// (assets/ibl-report), and `candela view --ibl-report FILE` adds one of the user's.

#include "ibl/ibl_settings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace candela::ui {

struct IblReportRow {
    std::string group;    // "prefilter, filtered IS", "cube size", ...
    std::string setting;  // "32 (default)", "64", "sh9:16", ...
    ibl::IblQuality quality;  // the settings measured (lod bias: the default)
    double precomputeMs = 0.0;
    double ratioToCalibration = 0.0;
    double specularMeanRelative = 0.0;
    double irradianceMeanRelative = 0.0;
    double lutMax = 0.0;  // max of the A and B errors
    double imageMeanRelative = 0.0;
};

struct IblReportTable {
    std::string name;         // the compiled-in report's name ("sky", "venice_sunset_1k"), or the CSV's path
    // What it was measured on, as assets::Environment::source names it ("procedural sky") or by a
    // file's stem ("venice_sunset_1k"); empty when not known (a CSV of the user's).
    std::string environment;
    std::vector<IblReportRow> rows;
    // The row measured with exactly `quality` (its lod bias aside), or null.
    const IblReportRow* find(const ibl::IblQuality& quality) const;
};

// Parses a report.csv. Throws UserError "NAME: ..." naming the line for a malformed file.
IblReportTable parseIblReport(std::string_view csv, std::string name);
// Reads and parses a file; UserError "PATH: ..." when it cannot be read or parsed.
IblReportTable loadIblReport(const std::filesystem::path& path);
// The compiled-in reports, their `environment` set.
std::vector<IblReportTable> builtinIblReports();
// Whether `table` was measured on the environment `source` (assets::Environment::source: a file's
// path, or "procedural sky").
bool measuredOn(const IblReportTable& table, std::string_view environmentSource);
// The report measured on `environmentSource`, or nullopt when none of `reports` was.
std::optional<size_t> findIblReportFor(const std::vector<IblReportTable>& reports, std::string_view environmentSource);
// What the environment panel says of `reports[shown]` while `environmentSource` is loaded (empty:
// no environment): "" when the table was measured on it, else one line saying what it was
// measured on instead and whether a table for the loaded one exists. Precondition: shown < size.
std::string iblReportNote(const std::vector<IblReportTable>& reports, size_t shown, std::string_view environmentSource);
// Their CSV text by environment name (generated from assets/ibl-report).
std::vector<std::pair<std::string_view, std::string_view>> builtinIblReportCsv();

}  // namespace candela::ui
