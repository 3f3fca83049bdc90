// `candela diff A B`: two images, or two folders of images matched by relative path, compared with
// ꟻLIP (reports/flip.h) and the plain pixel numbers (reports/pixel_difference.h). One line per pair
// and a summary on stdout; optional error maps (magma PNG) and JSON. docs/pipelines.md#candela-diff.

#include "commands.h"
#include "diff_page.h"

#include "assets/image_file.h"
#include "core/errors.h"
#include "core/log.h"
#include "reports/compared_image.h"
#include "reports/image_diff.h"
#include "reports/magma.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace candela::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

reports::DiffSettings diffSettings(const DiffOptions& o) {
    reports::DiffSettings s;
    s.viewing = {o.monitorDistance, o.monitorWidth, o.monitorResolution};
    s.ppdGiven = o.ppd.has_value();
    s.pixelsPerDegree = o.ppd ? *o.ppd : reports::pixelsPerDegree(s.viewing);
    s.thresholdLevels = o.threshold;
    s.maxFlip = o.maxFlip;
    s.maxFraction = o.maxFraction;
    return s;
}

// The pairs to compare: two files, or the images of two folders matched by relative path.
std::vector<reports::MatchedFile> pairsToCompare(const DiffOptions& o) {
    for (const std::string& path : {o.reference, o.test}) {
        std::error_code ec;
        if (!fs::exists(path, ec)) throw UserError(path + ": no such file or folder");
    }
    std::error_code ec;
    const bool referenceFolder = fs::is_directory(o.reference, ec), testFolder = fs::is_directory(o.test, ec);
    if (referenceFolder != testFolder)
        throw UserError((referenceFolder ? o.reference : o.test) + ": is a folder and " + (referenceFolder ? o.test : o.reference) +
                        " is not: compare two images or two folders");
    if (!referenceFolder) {
        for (const std::string& path : {o.reference, o.test})
            if (!reports::comparedFormat(path)) throw UserError(path + ": not a .png or .exr file");
        if (*reports::comparedFormat(o.reference) != *reports::comparedFormat(o.test))
            throw UserError(o.test + ": compare PNG with PNG and EXR with EXR (the other is " + o.reference + ")");
        return {{fs::path(o.test).filename().string(), fs::path(o.reference), fs::path(o.test)}};
    }
    std::vector<reports::MatchedFile> files = reports::matchFolders(o.reference, o.test);
    if (files.empty()) throw UserError(o.reference + ", " + o.test + ": no .png or .exr images in either folder");
    return files;
}

// Where a pair's error map goes: its relative path under DIR, an EXR's with .png added.
fs::path errorMapPath(const std::string& folder, const reports::DiffPair& pair) {
    return fs::path(folder) / (pair.hdr ? pair.name + ".png" : pair.name);
}

void writeErrorMap(const fs::path& path, const reports::DiffPair& pair, const std::vector<float>& error) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw UserError(path.parent_path().string() + ": cannot create the folder: " + ec.message());
    assets::writePng(path, pair.width, pair.height, reports::magmaImage(error));
}

std::string pairLine(const reports::DiffPair& p, double thresholdLevels) {
    std::string line = reports::diffStatusName(p.status).text;
    line.resize(15, ' ');  // the statuses in a column
    line += p.name;
    if (!p.compared()) return line + ": " + p.message;
    line += ": " + std::to_string(p.width) + "x" + std::to_string(p.height) + (p.hdr ? " HDR" : "") + ", FLIP mean " +
            formatNumber("%.6f", p.flip.mean) + " (weighted median " + formatNumber("%.4f", p.flip.weightedMedian) + ", max " +
            formatNumber("%.4f", p.flip.max) + "), PSNR " + (std::isinf(p.pixels.psnr) ? "inf" : formatNumber("%.2f", p.pixels.psnr)) +
            " dB, max channel difference " + formatNumber(p.hdr ? "%.4g" : "%.0f", p.pixels.maxChannelDifference) + ", " +
            formatNumber("%.4g", p.pixels.fractionOverThreshold * 100.0) + "% of pixels over " + formatNumber("%g", thresholdLevels) +
            (p.hdr ? "/255" : " levels");
    return p.message.empty() ? line : line + " -- " + p.message;
}

// A float as the shortest decimal that reads back as it (0.7f as 0.7, not 0.699999988).
double shortest(float value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::strtod(std::string(text, end).c_str(), nullptr);
}

ordered_json pairJson(const reports::DiffPair& p) {
    ordered_json j;
    j["name"] = p.name;
    j["reference"] = p.referencePath;
    j["test"] = p.testPath;
    j["status"] = reports::diffStatusName(p.status).key;
    j["passed"] = p.status == reports::DiffStatus::Ok;
    j["message"] = p.message;
    j["format"] = p.hdr ? "exr" : "png";
    j["width"] = p.width;
    j["height"] = p.height;
    j["errorMap"] = p.errorMapPath.empty() ? ordered_json() : ordered_json(p.errorMapPath);
    if (!p.compared()) return j;
    // The percentiles and extremes are values of the float error map.
    j["flip"] = {{"mean", p.flip.mean},
                 {"weightedMedian", shortest(float(p.flip.weightedMedian))},
                 {"weightedQuartile1", shortest(float(p.flip.weightedQuartile1))},
                 {"weightedQuartile3", shortest(float(p.flip.weightedQuartile3))},
                 {"min", shortest(float(p.flip.min))},
                 {"max", shortest(float(p.flip.max))},
                 {"histogram", p.flip.histogram}};
    if (p.exposures)
        j["exposures"] = {{"start", shortest(p.exposures->start)}, {"stop", shortest(p.exposures->stop)}, {"count", p.exposures->count}};
    j["psnr"] = std::isinf(p.pixels.psnr) ? ordered_json() : ordered_json(p.pixels.psnr);
    j["maxChannelDifference"] = p.pixels.maxChannelDifference;
    j["pixelsOverThreshold"] = p.pixels.pixelsOverThreshold;
    j["fractionOverThreshold"] = p.pixels.fractionOverThreshold;
    return j;
}

ordered_json reportJson(const reports::DiffReport& report) {
    const reports::DiffSettings& s = report.settings;
    ordered_json j;
    j["viewing"] = {{"pixelsPerDegree", shortest(s.pixelsPerDegree)},
                    {"from", s.ppdGiven ? "--ppd" : "monitor"},
                    {"monitorDistance", shortest(s.viewing.monitorDistance)},
                    {"monitorWidth", shortest(s.viewing.monitorWidth)},
                    {"monitorResolution", shortest(s.viewing.monitorResolution)}};
    j["thresholds"] = {{"thresholdLevels", s.thresholdLevels},
                       {"maxFlip", s.maxFlip ? ordered_json(*s.maxFlip) : ordered_json()},
                       {"maxFraction", s.maxFraction ? ordered_json(*s.maxFraction) : ordered_json()}};
    ordered_json pairs = ordered_json::array();
    for (const reports::DiffPair& p : report.pairs) pairs.push_back(pairJson(p));
    j["pairs"] = std::move(pairs);
    ordered_json totals = {{"pairs", report.pairs.size()}};
    for (const reports::DiffStatusName& status : reports::kDiffStatusNames) totals[status.key] = report.count(status.status);
    totals["passed"] = report.passed();
    j["totals"] = std::move(totals);
    return j;
}

}  // namespace

int runDiff(const DiffOptions& options) {
    if (options.reference.empty() || options.test.empty())
        throw UserError("diff: expected two images or two folders (candela diff A B)");
    reports::DiffReport report{diffSettings(options), {}};
    // The filters grow with the pixels per degree: 273 taps at 1000 against 21 at 67. More than
    // that (a 3840-pixel monitor 0.7 m wide seen from 10 m is 957) is refused.
    if (!(report.settings.pixelsPerDegree <= 1000.0f))
        throw UserError(formatNumber("diff: %g pixels per degree is more than 1000 (", report.settings.pixelsPerDegree) +
                        (options.ppd ? "--ppd)" : "from the --monitor flags)"));
    const std::vector<reports::MatchedFile> files = pairsToCompare(options);
    // A page shows the error maps: without --error-maps they go into a folder beside it.
    const std::string errorMaps = !options.errorMaps.empty() || options.html.empty()
                                      ? options.errorMaps
                                      : (fs::path(options.html).parent_path() / (fs::path(options.html).stem().string() + "-flip")).string();
    if (!errorMaps.empty()) {
        std::error_code ec;
        fs::create_directories(errorMaps, ec);
        if (ec || !fs::is_directory(errorMaps, ec))
            throw UserError(errorMaps + ": cannot create the error-map folder" + (ec ? ": " + ec.message() : ""));
    }
    for (const std::string& file : {options.report, options.html})
        if (!file.empty()) assets::checkWritable(file);

    std::vector<float> error;
    for (const reports::MatchedFile& file : files) {
        reports::DiffPair pair;
        if (!file.reference || !file.test) {
            pair = {.name = file.name,
                    .referencePath = file.reference ? file.reference->string() : "",
                    .testPath = file.test ? file.test->string() : "",
                    .status = reports::DiffStatus::Missing,
                    .message = file.reference ? "no test image in " + options.test : "no reference image in " + options.reference};
        } else {
            pair = reports::diffImages(*file.reference, *file.test, file.name, report.settings, &error);
            if (pair.compared() && !errorMaps.empty()) {
                const fs::path path = errorMapPath(errorMaps, pair);
                writeErrorMap(path, pair, error);
                pair.errorMapPath = path.string();
            }
        }
        for (const std::string& warning : pair.warnings) log::warn(warning);
        if (pair.status == reports::DiffStatus::Unreadable) log::error(pair.message);
        std::printf("%s\n", pairLine(pair, report.settings.thresholdLevels).c_str());
        std::fflush(stdout);
        report.pairs.push_back(std::move(pair));
    }

    const reports::DiffSettings& s = report.settings;
    std::printf("%zu pair%s: %zu ok, %zu over threshold, %zu missing, %zu size mismatch, %zu unreadable; FLIP at %.2f "
                "pixels per degree",
                report.pairs.size(), report.pairs.size() == 1 ? "" : "s", report.count(reports::DiffStatus::Ok),
                report.count(reports::DiffStatus::OverThreshold), report.count(reports::DiffStatus::Missing),
                report.count(reports::DiffStatus::SizeMismatch), report.count(reports::DiffStatus::Unreadable), s.pixelsPerDegree);
    if (!s.ppdGiven)
        std::printf(" (%g m from a %g m wide, %g-pixel monitor)", s.viewing.monitorDistance, s.viewing.monitorWidth,
                    s.viewing.monitorResolution);
    std::printf("\n");
    if (!options.report.empty()) writeText(options.report, reportJson(report).dump(2) + "\n");
    if (!options.html.empty()) reports::writeHtmlPage(options.html, diffPage(report, options.html), options.inlineImages);
    if (report.count(reports::DiffStatus::Unreadable)) return 2;
    return report.passed() ? 0 : 1;
}

}  // namespace candela::app
