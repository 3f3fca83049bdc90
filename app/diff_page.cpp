#include "diff_page.h"

#include <cmath>
#include <cstdio>

namespace candela::app {
namespace {

namespace fs = std::filesystem;

io::RowStatus rowStatus(const io::DiffPair& pair) {
    switch (pair.status) {
        case io::DiffStatus::Ok: return pair.warnings.empty() ? io::RowStatus::Ok : io::RowStatus::Warning;
        case io::DiffStatus::OverThreshold: return io::RowStatus::OverThreshold;
        case io::DiffStatus::Missing:
        case io::DiffStatus::SizeMismatch:
        case io::DiffStatus::Unreadable: break;
    }
    return io::RowStatus::Failed;
}

// A thumbnail of `file` ("" when there is none); browsers show PNG, not EXR.
io::PageImage thumbnail(const std::string& label, const std::string& file, const fs::path& page, const char* none) {
    if (file.empty()) return {label, {}, none};
    if (fs::path(file).extension() != ".png") return {label, {}, fs::path(file).extension().string() + ": no preview"};
    return {label, io::pathFromPage(file, page), ""};
}

}  // namespace

io::HtmlPage diffPage(const io::DiffReport& report, const fs::path& page) {
    io::HtmlPage out;
    out.title = "candela diff: " + std::to_string(report.pairs.size()) + " pair" + (report.pairs.size() == 1 ? "" : "s");
    const auto count = [&](io::DiffStatus status) { return std::to_string(report.count(status)); };
    out.summary.push_back(count(io::DiffStatus::Ok) + " ok, " + count(io::DiffStatus::OverThreshold) + " over threshold, " +
                          count(io::DiffStatus::Missing) + " missing, " + count(io::DiffStatus::SizeMismatch) +
                          " size mismatch, " + count(io::DiffStatus::Unreadable) + " unreadable");
    const io::DiffSettings& s = report.settings;
    char line[256];
    std::snprintf(line, sizeof line, "FLIP at %.2f pixels per degree; a pixel is over the threshold above %g levels", s.pixelsPerDegree,
                  s.thresholdLevels);
    std::string gate = line;
    if (s.maxFlip) gate += "; fails above a mean FLIP of " + std::to_string(*s.maxFlip).substr(0, 6);
    if (s.maxFraction) gate += "; fails above " + std::to_string(*s.maxFraction * 100.0).substr(0, 6) + "% of pixels over";
    out.summary.push_back(gate);
    out.columns = {{"FLIP mean", 4}, {"FLIP max", 4}, {"PSNR dB", 2}, {"max diff", 1}, {"% over", 3}};
    out.errorColumn = "FLIP mean";
    for (const io::DiffPair& pair : report.pairs) {
        io::PageRow row;
        row.name = pair.name;
        row.status = rowStatus(pair);
        row.error = pair.message;
        row.warnings = pair.warnings;
        row.images = {thumbnail("reference", pair.referencePath, page, "no reference"),
                      thumbnail("test", pair.testPath, page, "no test image"),
                      thumbnail("FLIP", pair.errorMapPath, page, pair.compared() ? "no error map" : "not compared")};
        for (const auto& [label, file] : {std::pair("reference", pair.referencePath), std::pair("test", pair.testPath),
                                          std::pair("FLIP map", pair.errorMapPath)})
            if (!file.empty()) row.links.push_back({label, io::pathFromPage(file, page)});
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
