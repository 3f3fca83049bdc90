#include "diff_page.h"

#include <cmath>
#include <cstdio>

namespace candela::app {
namespace {

namespace fs = std::filesystem;

reports::RowStatus rowStatus(const reports::DiffPair& pair) {
    switch (pair.status) {
        case reports::DiffStatus::Ok: return pair.warnings.empty() ? reports::RowStatus::Ok : reports::RowStatus::Warning;
        case reports::DiffStatus::OverThreshold: return reports::RowStatus::OverThreshold;
        case reports::DiffStatus::Missing:
        case reports::DiffStatus::SizeMismatch:
        case reports::DiffStatus::Unreadable: break;
    }
    return reports::RowStatus::Failed;
}

// A thumbnail of `file` ("" when there is none); browsers show PNG, not EXR.
reports::PageImage thumbnail(const std::string& label, const std::string& file, const fs::path& page, const char* none) {
    if (file.empty()) return {label, {}, none};
    if (fs::path(file).extension() != ".png") return {label, {}, fs::path(file).extension().string() + ": no preview"};
    return {label, reports::pathFromPage(file, page), ""};
}

}  // namespace

reports::HtmlPage diffPage(const reports::DiffReport& report, const fs::path& page) {
    reports::HtmlPage out;
    out.title = "candela diff: " + std::to_string(report.pairs.size()) + " pair" + (report.pairs.size() == 1 ? "" : "s");
    const auto count = [&](reports::DiffStatus status) { return std::to_string(report.count(status)); };
    out.summary.push_back(count(reports::DiffStatus::Ok) + " ok, " + count(reports::DiffStatus::OverThreshold) + " over threshold, " +
                          count(reports::DiffStatus::Missing) + " missing, " + count(reports::DiffStatus::SizeMismatch) +
                          " size mismatch, " + count(reports::DiffStatus::Unreadable) + " unreadable");
    const reports::DiffSettings& s = report.settings;
    char line[256];
    std::snprintf(line, sizeof line, "FLIP at %.2f pixels per degree; a pixel is over the threshold above %g levels", s.pixelsPerDegree,
                  s.thresholdLevels);
    std::string gate = line;
    if (s.maxFlip) gate += "; fails above a mean FLIP of " + std::to_string(*s.maxFlip).substr(0, 6);
    if (s.maxFraction) gate += "; fails above " + std::to_string(*s.maxFraction * 100.0).substr(0, 6) + "% of pixels over";
    out.summary.push_back(gate);
    out.columns = {{"FLIP mean", 4}, {"FLIP max", 4}, {"PSNR dB", 2}, {"max diff", 1}, {"% over", 3}};
    out.errorColumn = "FLIP mean";
    for (const reports::DiffPair& pair : report.pairs) {
        reports::PageRow row;
        row.name = pair.name;
        row.status = rowStatus(pair);
        row.error = pair.message;
        row.warnings = pair.warnings;
        row.images = {thumbnail("reference", pair.referencePath, page, "no reference"),
                      thumbnail("test", pair.testPath, page, "no test image"),
                      thumbnail("FLIP", pair.errorMapPath, page, pair.compared() ? "no error map" : "not compared")};
        for (const auto& [label, file] : {std::pair("reference", pair.referencePath), std::pair("test", pair.testPath),
                                          std::pair("FLIP map", pair.errorMapPath)})
            if (!file.empty()) row.links.push_back({label, reports::pathFromPage(file, page)});
        if (pair.compared()) {
            row.numbers["FLIP mean"] = pair.flip.mean;
            row.numbers["FLIP max"] = pair.flip.max;
            if (std::isfinite(pair.pixels.psnr)) row.numbers["PSNR dB"] = pair.pixels.psnr;
            row.numbers["max diff"] = pair.hdr ? pair.pixels.maxChannelDifference * 255.0 : pair.pixels.maxChannelDifference;
            row.numbers["% over"] = pair.pixels.fractionOverThreshold * 100.0;
        }
        out.rows.push_back(std::move(row));
    }
    return out;
}

}  // namespace candela::app
