// `candela ibl-report`'s files: CSV, markdown, log-log plots with the Pareto front, previews.

#include "commands.h"
#include "ibl_report.h"
#include "statistics.h"

#include "assets/image_file.h"
#include "core/errors.h"
#include "reports/flip.h"
#include "reports/image_error.h"
#include "reports/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace candela::app::report {
namespace {

std::string fixed(double v, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
    return buffer;
}
std::string sci(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    return buffer;
}

// Luminance of the pixels two RGBA float images both cover fully (alpha 1), and which pixels.
struct CoveredPixels {
    std::vector<double> image, reference;
    std::vector<size_t> pixel;
};

CoveredPixels coveredPixels(const std::vector<float>& image, const std::vector<float>& reference) {
    CoveredPixels out;
    for (size_t i = 0; i + 3 < reference.size() && i + 3 < image.size(); i += 4) {
        if (reference[i + 3] < 1.0f || image[i + 3] < 1.0f) continue;
        out.image.push_back(reports::luminance({image[i], image[i + 1], image[i + 2]}));
        out.reference.push_back(reports::luminance({reference[i], reference[i + 1], reference[i + 2]}));
        out.pixel.push_back(i / 4);
    }
    return out;
}

}  // namespace

reports::ErrorStats imageError(const std::vector<float>& image, const std::vector<float>& reference) {
    const CoveredPixels pixels = coveredPixels(image, reference);
    return reports::errorStats(pixels.image, pixels.reference);
}

VisibleError visibleError(const std::vector<float>& image, const std::vector<float>& reference, uint32_t width,
                          uint32_t height) {
    const auto display = [&](const std::vector<float>& rgba) {
        const std::vector<uint8_t> encoded = reports::displayEncode({.width = width, .height = height, .rgba = rgba});
        reports::RgbImage linear{.width = width, .height = height, .rgb = std::vector<float>(encoded.size())};
        for (size_t i = 0; i < encoded.size(); ++i) linear.rgb[i] = reports::srgbToLinear(encoded[i]);
        return linear;
    };
    const std::vector<float> flip = reports::ldrFlip(display(reference), display(image), reports::pixelsPerDegree({}));
    const CoveredPixels pixels = coveredPixels(image, reference);
    std::vector<double> covered, relative;
    double sum = 0.0;
    for (double r : pixels.reference) sum += r;
    const double floor = pixels.reference.empty() ? 1e-6 : 0.01 * sum / double(pixels.reference.size());
    for (size_t k = 0; k < pixels.pixel.size(); ++k) {
        covered.push_back(flip[pixels.pixel[k]]);
        relative.push_back(std::abs(pixels.image[k] - pixels.reference[k]) / (pixels.reference[k] + floor));
    }
    VisibleError e;
    if (covered.empty()) return e;
    for (double v : covered) e.flipMean += v / double(covered.size());
    e.flipMax = *std::max_element(covered.begin(), covered.end());
    e.flipP99 = quantile(covered, 0.99);
    e.flipP999 = quantile(covered, 0.999);
    e.relativeP99 = quantile(relative, 0.99);
    return e;
}

void writePreview(const std::filesystem::path& path, const CapturedFrame& frame) {
    std::vector<uint8_t> rgba(frame.rgba32f.size());
    for (size_t i = 0; i < rgba.size(); ++i) {
        const float x = i % 4 == 3 ? frame.rgba32f[i] : frame.rgba32f[i] / (1.0f + frame.rgba32f[i]);
        const float encoded = i % 4 == 3 ? x : (x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f);
        rgba[i] = static_cast<uint8_t>(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f);
    }
    assets::writePng(path, frame.width, frame.height, rgba);
}

void writeErrorMap(const std::filesystem::path& path, const CapturedFrame& frame, const std::vector<float>& reference) {
    const CoveredPixels pixels = coveredPixels(frame.rgba32f, reference);
    double sum = 0;
    for (double r : pixels.reference) sum += r;
    const double floor = pixels.reference.empty() ? 1e-6 : 0.01 * sum / double(pixels.reference.size());
    std::vector<uint8_t> rgba(frame.rgba32f.size(), 0);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    for (size_t k = 0; k < pixels.pixel.size(); ++k) {
        const double r = pixels.reference[k], g = pixels.image[k];
        const double e = std::min(std::abs(g - r) / (r + floor), 1.0);
        const size_t i = pixels.pixel[k] * 4;
        rgba[i] = rgba[i + 1] = rgba[i + 2] = static_cast<uint8_t>(e * 255.0);
        if (e > 0.1) rgba[g > r ? i + 0 : i + 2] = 255;
    }
    assets::writePng(path, frame.width, frame.height, rgba);
}

void writeCsv(const std::filesystem::path& out, const std::vector<Result>& results) {
    // One row per setting, errors per roughness level at the end.
    TextFile csv(out / "report.csv");
    csv << "group,setting,cube,levels,prefilter_samples,filtered,irradiance,sh_size,irradiance_samples,lut_size,"
           "lut_samples,precompute_ms,precompute_gpu_ms,setup_ms,ratio_to_calibration,ratio_min,ratio_max,specular_rmse,specular_mean_relative,"
           "specular_max,irradiance_rmse,irradiance_mean_relative,irradiance_max,lut_max_a,lut_max_b,lut_rms_a,lut_rms_b,image_rmse,image_mean_relative,image_max,"
           "image_relative_p99,image_flip_mean,image_flip_p99,image_flip_p999,image_flip_max,maps_flip_mean,maps_flip_p99,"
           "maps_flip_p999,maps_flip_max,bright_texels";
    for (const reports::LevelErrors& level : results.front().specular)
        csv << ",rmse_r" << fixed(level.roughness, 2) << ",mean_r" << fixed(level.roughness, 2) << ",max_r"
            << fixed(level.roughness, 2);
    csv << "\n";
    for (const Result& r : results) {
        const ibl::IblQuality& q = r.setting.quality;
        csv << '"' << r.setting.group << "\",\"" << r.setting.label << "\"," << q.cubeSize << ',' << q.levels() << ','
            << q.prefilterSamples << ',' << (q.filteredSampling ? 1 : 0) << ',' << ibl::irradianceModeName(q.irradiance)
            << ',' << q.shSourceSize << ',' << q.irradianceSamples << ',' << q.lutSize << ',' << q.lutSamples << ','
            << fixed(r.wallMs, 2) << ',' << fixed(r.gpuMs, 2) << ',' << fixed(r.setupMs, 2) << ','
            << fixed(r.ratio, 3) << ',' << fixed(r.ratioLow, 3) << ',' << fixed(r.ratioHigh, 3) << ',' << sci(r.specularRmse()) << ',' << sci(r.specularMeanRelative()) << ','
            << sci(r.specularMax()) << ',' << sci(r.irradiance.rmse) << ',' << sci(r.irradiance.meanRelative) << ','
            << sci(r.irradiance.maxRelative) << ',' << sci(r.lut.maxA) << ','
            << sci(r.lut.maxB) << ',' << sci(r.lut.rmsA) << ',' << sci(r.lut.rmsB) << ',' << sci(r.image.rmse) << ','
            << sci(r.image.meanRelative) << ',' << sci(r.image.maxRelative) << ',' << sci(r.visible.relativeP99) << ','
            << sci(r.visible.flipMean) << ',' << sci(r.visible.flipP99) << ',' << sci(r.visible.flipP999) << ','
            << sci(r.visible.flipMax) << ',' << sci(r.visibleMaps.flipMean) << ',' << sci(r.visibleMaps.flipP99) << ','
            << sci(r.visibleMaps.flipP999) << ',' << sci(r.visibleMaps.flipMax) << ',' << q.brightTexels;
        for (const reports::LevelErrors& level : r.specular)
            csv << ',' << sci(level.stats.rmse) << ',' << sci(level.stats.meanRelative) << ',' << sci(level.stats.maxRelative);
        csv << "\n";
    }
    csv.commit();

}

void writeMarkdown(const std::filesystem::path& out, const Context& c, const std::vector<Result>& results) {
    std::ostringstream md;
    md << "# IBL quality report\n\nEnvironment: " << c.environment << ". Device: " << c.device << ". Calibration pass (1280x720): "
       << fixed(c.calibrationMs, 1) << " ms median (interquartile " << fixed(c.calibrationLowMs, 1) << "–" << fixed(c.calibrationHighMs, 1)
       << " ms over the run, one run before each timed precompute). Precompute times: submit+wait in " << c.repeats
       << " rounds over every setting (alternately forwards and backwards); ms and × calibration are the median "
          "over the median calibration run, the quartiles of the rounds in brackets (nearest rank: for 3 rounds the "
          "lowest and highest). A setting is off the plots' "
          "Pareto front only when another is better by more than these spreads on one axis and not worse by more on "
          "the other. Errors "
          "are relative luminance errors against the double-precision reference (reports/ibl_errors.h): RMSE "
          "(dominated by the brightest values), mean relative and max relative error (each value against its "
          "reference plus 1% of the mean). Specular: averaged over the roughness > 0 levels, 128 texels each "
          "(max: the worst level); irradiance: 256 directions; LUT: max absolute error of A and B; image: the "
          "default scene (multiscatter off, no skybox) at "
       << c.width << "x" << c.height << " against the ground truth (" << c.referenceSamples
       << " samples per lobe per pixel, the brightest texels summed; a quarter of the samples differs by "
       << sci(c.convergence.rmse) << " relative RMSE, " << sci(c.convergence.meanRelative)
       << " mean relative error, ꟻLIP max " << fixed(c.visibleConvergence.flipMax, 3)
       << "). Visible error: both images display-encoded as the tonemap pass encodes them (PBR Neutral, "
          "exposure 0, sRGB 8-bit) and compared with LDR-ꟻLIP over the covered pixels: mean, 99th and 99.9th "
          "percentile and maximum (a sun's highlight is a few hundred pixels: it shows in the last two); rel. p99: "
          "the 99th percentile of the relative luminance error. Maps ꟻLIP: the same against the scene rendered through "
          "the split sum with converged maps ("
       << c.converged << "; their worst specular level is off the reference by " << sci(c.convergedSpecularMax)
       << "): what the maps alone leave visible, without the split sum's own error.\n\n";
    md << "| group | setting | precompute ms | × calibration | specular RMSE | specular mean rel. | specular max | "
          "irradiance RMSE | irradiance mean rel. | LUT max | image RMSE | image mean rel. | image rel. p99 | "
          "ꟻLIP mean | ꟻLIP p99 | ꟻLIP p99.9 | ꟻLIP max | maps ꟻLIP p99.9 | maps ꟻLIP max |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const ibl::IblQuality defaults;
    for (const Result& r : results)
        md << "| " << r.setting.group << " | " << r.setting.label << (r.setting.quality == defaults ? " (default)" : "")
           << " | " << fixed(r.wallMs, 1) << " | " << fixed(r.ratio, 2) << " (" << fixed(r.ratioLow, 2) << "–"
           << fixed(r.ratioHigh, 2) << ") | " << sci(r.specularRmse()) << " | "
           << sci(r.specularMeanRelative()) << " | " << sci(r.specularMax()) << " | " << sci(r.irradiance.rmse) << " | "
           << sci(r.irradiance.meanRelative) << " | "
           << sci(std::max(r.lut.maxA, r.lut.maxB)) << " | " << sci(r.image.rmse) << " | " << sci(r.image.meanRelative) << " | " << sci(r.visible.relativeP99)
           << " | " << fixed(r.visible.flipMean, 4) << " | " << fixed(r.visible.flipP99, 3) << " | "
           << fixed(r.visible.flipP999, 3) << " | " << fixed(r.visible.flipMax, 3) << " | "
           << fixed(r.visibleMaps.flipP999, 3) << " | " << fixed(r.visibleMaps.flipMax, 3) << " |\n";
    md << "\nPlots: specular.png, irradiance.png, lut.png, image.png (error against precompute time, log-log, "
          "Pareto front marked, the default ringed).\n";
    writeText((out / "report.md").string(), md.str());
}

void writePlots(const std::filesystem::path& out, const std::vector<Result>& results) {
    const ibl::IblQuality defaults;
    // One plot per error measure, every setting, series by group.
    auto plot = [&](const char* file, const char* title, const char* yLabel, auto&& error,
                    const std::vector<std::string>& groups) {
        reports::PlotSpec spec{.title = title,
                          .xLabel = "precompute time / median calibration pass (median of the rounds, bars: quartiles)",
                          .yLabel = yLabel};
        spec.series = groups;
        spec.series.push_back("other groups");
        for (const Result& r : results) {
            const auto g = std::find(groups.begin(), groups.end(), r.setting.group);
            const bool isDefault = r.setting.quality == defaults;
            if (g == groups.end() && !isDefault) continue;
            if (isDefault) spec.highlight = spec.points.size();
            spec.points.push_back({.x = r.ratio,
                                   .y = error(r),
                                   .label = isDefault ? "default" : r.setting.label,
                                   .series = uint32_t(g - groups.begin()),
                                   .xLow = r.ratioLow,
                                   .xHigh = r.ratioHigh});
        }
        reports::writeLogLogPlot(out / file, spec);
    };
    const std::vector<std::string> specularGroups{"prefilter, filtered IS", "prefilter, sun sampled", "previous default",
                                                  "bright texels", "prefilter, plain IS", "cube size"};
    plot("specular.png", "Specular prefilter: error vs time", "mean relative error (roughness > 0 levels)",
         [](const Result& r) { return r.specularMeanRelative(); }, specularGroups);
    plot("irradiance.png", "Irradiance: error vs time", "mean relative error",
         [](const Result& r) { return r.irradiance.meanRelative; },
         {"irradiance SH9", "irradiance cube"});
    plot("lut.png", "BRDF LUT: error vs time", "max absolute error of A, B",
         [](const Result& r) { return std::max(r.lut.maxA, r.lut.maxB); }, {"BRDF LUT"});
    std::vector<std::string> allGroups;
    for (const Result& r : results)
        if (std::find(allGroups.begin(), allGroups.end(), r.setting.group) == allGroups.end())
            allGroups.push_back(r.setting.group);
    plot("image.png", "Default scene: image error vs precompute time", "mean relative error vs ground truth",
         [](const Result& r) { return r.image.meanRelative; }, allGroups);
    plot("image_worst.png", "Default scene: worst visible error of the maps vs precompute time",
         "FLIP against converged maps, 99.9th percentile of the covered pixels",
         [](const Result& r) { return r.visibleMaps.flipP999; }, allGroups);
}

}  // namespace candela::app::report
