#pragma once
// `candela ibl-report`: the data of one report and the files it writes (CSV, markdown, log-log
// plots, previews). The measuring is in ibl_report_command.cpp.

#include "ibl/ibl_settings.h"
#include "render/renderer.h"
#include "reports/ibl_errors.h"

#include <filesystem>
#include <string>
#include <vector>

namespace candela::app::report {

struct Setting {
    std::string group;  // series of the plots
    std::string label;
    ibl::IblQuality quality;
};

// What a viewer sees of an image's error against the ground truth: both display-encoded as the tonemap
// pass encodes them (PBR Neutral at exposure 0, sRGB, 8 bits; reports/image_error.h) and compared with
// LDR-ꟻLIP (reports/flip.h, the papers' viewing conditions) over the pixels both cover; and the 99th
// percentile of the relative luminance error. A small bright highlight (a sun's reflection) is a
// few hundred pixels: it moves the maximum and the 99.9th percentile, hardly the mean.
struct VisibleError {
    double flipMean = 0, flipP99 = 0, flipP999 = 0, flipMax = 0;
    double relativeP99 = 0;
};

struct Result {
    Setting setting;
    double wallMs = 0;        // median precompute submit+wait
    double wallLowMs = 0, wallHighMs = 0;  // its quartiles over the rounds (statistics.h spreadOf)
    double gpuMs = 0;         // median sum of the precompute passes' GPU timestamps
    double setupMs = 0;       // median CPU time before submit (upload, hashing, sample tables)
    double ratio = 0;         // wallMs / Context::calibrationMs
    double ratioLow = 0, ratioHigh = 0;    // wallLowMs and wallHighMs over it (the spread)
    std::vector<reports::LevelErrors> specular;
    reports::ErrorStats irradiance;
    reports::LutErrors lut;
    reports::ErrorStats image;  // relative luminance errors of the default scene against the ground truth
    VisibleError visible;   // the same image's visible error against the ground truth
    // ... and against the same scene through the split sum with converged maps (Context::converged):
    // what the maps alone leave visible (a blocky, speckled sun), without the split sum's own error.
    VisibleError visibleMaps;
    double specularRmse() const {  // mean relative RMSE over the roughness > 0 levels
        double sum = 0;
        int n = 0;
        for (const reports::LevelErrors& level : specular)
            if (level.roughness > 0) sum += level.stats.rmse, ++n;
        return n ? sum / n : -1;
    }
    double specularMeanRelative() const {  // mean over the roughness > 0 levels
        double sum = 0;
        int n = 0;
        for (const reports::LevelErrors& level : specular)
            if (level.roughness > 0) sum += level.stats.meanRelative, ++n;
        return n ? sum / n : -1;
    }
    double specularMax() const {
        double m = 0;
        for (const reports::LevelErrors& level : specular)
            if (level.roughness > 0) m = std::max(m, level.stats.maxRelative);
        return m;
    }
};

// What the report describes besides the rows.
struct Context {
    std::string environment;  // source and size
    std::string device;
    double calibrationMs = 0;  // 1280×720 calibration pass, median of every run (one per precompute timed)
    double calibrationLowMs = 0, calibrationHighMs = 0;  // their quartiles
    uint32_t repeats = 0;
    uint32_t width = 0, height = 0;  // end-to-end images
    uint32_t referenceSamples = 0;
    reports::ErrorStats convergence;  // the ground truth against itself at a quarter of the samples
    VisibleError visibleConvergence;
    std::string converged;  // the settings of the converged-maps render (IblQuality::canonical)
    double convergedSpecularMax = 0;  // its maps' worst relative error (Result::specularMax)
};

// Relative luminance errors (reports::errorStats) of `image` against `reference` (RGBA floats) over the
// pixels both cover fully.
reports::ErrorStats imageError(const std::vector<float>& image, const std::vector<float>& reference);
// VisibleError of `image` against `reference` (RGBA floats, premultiplied, width × height).
VisibleError visibleError(const std::vector<float>& image, const std::vector<float>& reference, uint32_t width,
                          uint32_t height);
// A quick look at a linear frame: exposure 1, Reinhard, sRGB-encoded 8-bit PNG.
void writePreview(const std::filesystem::path& path, const CapturedFrame& frame);
// Per-pixel relative error against `reference` as a PNG: |x − ref| / (ref + 1% of the mean) as grey
// levels (1.0 white), red where the image is brighter and blue where it is darker by more than 10%.
void writeErrorMap(const std::filesystem::path& path, const CapturedFrame& frame, const std::vector<float>& reference);

// report.csv, report.md and specular/irradiance/lut/image.png in `out`. Throws UserError naming a
// file that cannot be written.
void writeCsv(const std::filesystem::path& out, const std::vector<Result>& results);
void writeMarkdown(const std::filesystem::path& out, const Context& context, const std::vector<Result>& results);
void writePlots(const std::filesystem::path& out, const std::vector<Result>& results);

}  // namespace candela::app::report
