// `candela ibl-report`: what each image-based-lighting quality setting costs and what error it
// leaves. For every setting of a sweep (prefilter samples with and without filtered importance
// sampling, cube size, irradiance as SH9 or cube, BRDF LUT size and samples) it measures the
// precompute time (CPU wall around submit+wait, median of --repeats runs, also as a ratio to the
// calibration pass) and compares the maps with the double-precision reference (ibl/ibl_errors.h),
// then renders the default scene and compares it with a ground-truth render that integrates the
// reflectance equation per pixel. Writes report.csv, report.md and log-log plots to --out.

#include "commands.h"

#include "core/check.h"
#include "core/log.h"
#include "ibl/ibl_errors.h"
#include "io/image_file.h"
#include "io/plot.h"
#include "scene/builtin_scenes.h"
#include "scene/procedural_sky.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace candela::app {
namespace {

struct Setting {
    std::string group;  // series of the plots
    std::string label;
    ibl::IblQuality quality;
};

struct ImageError {
    double rmse = -1;          // relative luminance RMSE over covered pixels (dominated by highlights)
    double meanRelative = -1;  // mean |x − ref| / (ref + 1% of the mean) (every pixel alike)
    double maxRelative = -1;   // max |x − ref| / (ref + 1% of the mean)
};

struct Result {
    Setting setting;
    double wallMs = 0;        // median precompute submit+wait
    double gpuMs = 0;         // median sum of the precompute passes' GPU timestamps
    double setupMs = 0;       // median CPU time before submit (upload, hashing, sample tables)
    double ratio = 0;         // median of precompute / an interleaved calibration run
    std::vector<ibl::LevelErrors> specular;
    ibl::ErrorStats irradiance;
    ibl::LutErrors lut;
    ImageError image;
    double specularRmse() const {  // mean relative RMSE over the roughness > 0 levels
        double sum = 0;
        int n = 0;
        for (const ibl::LevelErrors& level : specular)
            if (level.roughness > 0) sum += level.stats.rmse, ++n;
        return n ? sum / n : -1;
    }
    double specularMeanRelative() const {  // mean over the roughness > 0 levels
        double sum = 0;
        int n = 0;
        for (const ibl::LevelErrors& level : specular)
            if (level.roughness > 0) sum += level.stats.meanRelative, ++n;
        return n ? sum / n : -1;
    }
    double specularMax() const {
        double m = 0;
        for (const ibl::LevelErrors& level : specular)
            if (level.roughness > 0) m = std::max(m, level.stats.maxRelative);
        return m;
    }
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? -1 : v[v.size() / 2];
}

std::vector<Setting> sweep(bool quick) {
    std::vector<Setting> settings;
    const ibl::IblQuality base;
    auto add = [&](const std::string& group, const std::string& label, auto&& change) {
        ibl::IblQuality q = base;
        change(q);
        settings.push_back({group, label, q});
    };
    const std::vector<uint32_t> fis = quick ? std::vector<uint32_t>{16, 64} : std::vector<uint32_t>{8, 16, 32, 64, 128, 256, 512, 1024, 2048};
    for (uint32_t n : fis) add("prefilter, filtered IS", std::to_string(n), [&](ibl::IblQuality& q) { q.prefilterSamples = n; });
    const std::vector<uint32_t> plain = quick ? std::vector<uint32_t>{64} : std::vector<uint32_t>{64, 256, 1024, 2048};
    for (uint32_t n : plain)
        add("prefilter, plain IS", std::to_string(n), [&](ibl::IblQuality& q) {
            q.prefilterSamples = n;
            q.filteredSampling = false;
        });
    const std::vector<uint32_t> cubes = quick ? std::vector<uint32_t>{64} : std::vector<uint32_t>{64, 128, 512, 1024};
    for (uint32_t size : cubes) add("cube size", std::to_string(size), [&](ibl::IblQuality& q) { q.cubeSize = size; });
    const std::vector<uint32_t> sh = quick ? std::vector<uint32_t>{8} : std::vector<uint32_t>{8, 16, 64, 128};
    for (uint32_t size : sh) add("irradiance SH9", "sh9:" + std::to_string(size), [&](ibl::IblQuality& q) { q.shSourceSize = size; });
    const std::vector<uint32_t> cube = quick ? std::vector<uint32_t>{64} : std::vector<uint32_t>{16, 64, 256, 1024};
    for (uint32_t n : cube)
        add("irradiance cube", "cube:" + std::to_string(n), [&](ibl::IblQuality& q) {
            q.irradiance = ibl::IrradianceMode::Cube;
            q.irradianceSamples = n;
        });
    const std::vector<std::pair<uint32_t, uint32_t>> luts =
        quick ? std::vector<std::pair<uint32_t, uint32_t>>{{32, 64}}
              : std::vector<std::pair<uint32_t, uint32_t>>{{32, 128}, {64, 256}, {128, 128}, {128, 2048}, {256, 512}};
    for (auto [size, n] : luts)
        add("BRDF LUT", "lut " + std::to_string(size) + "x" + std::to_string(n), [&](ibl::IblQuality& q) {
            q.lutSize = size;
            q.lutSamples = n;
        });
    // The default itself, once (prefilter series holds it when 64 samples are swept).
    if (std::none_of(settings.begin(), settings.end(), [&](const Setting& s) { return s.quality == base; }))
        settings.insert(settings.begin(), {"prefilter, filtered IS", std::to_string(base.prefilterSamples), base});
    return settings;
}

// Relative luminance errors of `image` against `reference` over pixels both cover fully.
ImageError imageError(const std::vector<float>& image, const std::vector<float>& reference) {
    auto luminance = [](const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };
    double sumRef = 0, sumSq = 0, n = 0;
    for (size_t i = 0; i + 3 < reference.size(); i += 4) {
        if (reference[i + 3] < 1.0f || image[i + 3] < 1.0f) continue;
        const double r = luminance(&reference[i]), g = luminance(&image[i]);
        sumRef += r;
        sumSq += (g - r) * (g - r);
        ++n;
    }
    ImageError e;
    if (n == 0 || sumRef <= 0) return e;
    const double mean = sumRef / n;
    e.rmse = std::sqrt(sumSq / n) / mean;
    e.maxRelative = 0;
    double sumRelative = 0;
    for (size_t i = 0; i + 3 < reference.size(); i += 4) {
        if (reference[i + 3] < 1.0f || image[i + 3] < 1.0f) continue;
        const double r = luminance(&reference[i]), g = luminance(&image[i]);
        const double relative = std::abs(g - r) / (r + 0.01 * mean);
        e.maxRelative = std::max(e.maxRelative, relative);
        sumRelative += relative;
    }
    e.meanRelative = sumRelative / n;
    return e;
}

// A quick look at a linear frame: exposure 1, Reinhard, sRGB-encoded 8-bit.
void writePreview(const std::filesystem::path& path, const CapturedFrame& frame) {
    std::vector<uint8_t> rgba(frame.rgba32f.size());
    for (size_t i = 0; i < rgba.size(); ++i) {
        const float x = i % 4 == 3 ? frame.rgba32f[i] : frame.rgba32f[i] / (1.0f + frame.rgba32f[i]);
        const float encoded = i % 4 == 3 ? x : (x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f);
        rgba[i] = static_cast<uint8_t>(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f);
    }
    io::writePng(path, frame.width, frame.height, rgba);
}

// Where an image differs from the reference: |x − ref| / (ref + 1% of the mean) per pixel, as grey
// levels with 1.0 (100%) white; red where the image is brighter, blue where it is darker than 10%.
void writeErrorMap(const std::filesystem::path& path, const CapturedFrame& frame, const std::vector<float>& reference) {
    auto luminance = [](const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };
    double sum = 0, n = 0;
    for (size_t i = 0; i + 3 < reference.size(); i += 4)
        if (reference[i + 3] >= 1.0f) sum += luminance(&reference[i]), ++n;
    const double floor = n > 0 ? 0.01 * sum / n : 1e-6;
    std::vector<uint8_t> rgba(frame.rgba32f.size(), 0);
    for (size_t i = 0; i + 3 < reference.size(); i += 4) {
        rgba[i + 3] = 255;
        if (reference[i + 3] < 1.0f) continue;
        const double r = luminance(&reference[i]), g = luminance(&frame.rgba32f[i]);
        const double e = std::min(std::abs(g - r) / (r + floor), 1.0);
        const auto level = static_cast<uint8_t>(e * 255.0);
        rgba[i] = rgba[i + 1] = rgba[i + 2] = level;
        if (e > 0.1) rgba[g > r ? i + 0 : i + 2] = 255;
    }
    io::writePng(path, frame.width, frame.height, rgba);
}

const ibl::CachedImage* findImage(const std::vector<ibl::CachedImage>& images, const std::string& prefix) {
    for (const ibl::CachedImage& image : images)
        if (image.name.rfind(prefix, 0) == 0) return &image;
    return nullptr;
}

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

}  // namespace

int runIblReport(const IblReportOptions& options) {
    const std::filesystem::path out = options.out;
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) throw UserError(out.string() + ": cannot create the report folder: " + ec.message());
    for (const char* file : {"report.csv", "report.md", "specular.png", "irradiance.png", "lut.png", "image.png"})
        io::checkWritable(out / file);

    const scene::Environment environment =
        options.env == "sky" ? scene::makeProceduralSky() : scene::loadEnvironment(options.env);
    for (const std::string& warning : environment.warnings) log::warn(warning);
    const scene::Environment reference = ibl::referenceEnvironment(environment);
    ibl::ReferenceCache cache;

    vk::Context context(contextDesc(options.common));
    Renderer renderer(context);
    const scene::Scene scene = scene::makeSphereGrid();
    RenderSettings frame{.width = options.width, .height = options.height, .floatOutput = true, .scene = &scene};
    frame.environment = &environment;
    frame.ibl.skybox = false;        // compare the lit scene only
    frame.ibl.multiscatter = false;  // the ground truth integrates the single-scattering BRDF
    frame.defaultLights = false;

    auto calibrate = [&] {
        std::vector<double> ms;
        for (int i = 0; i < 3; ++i) ms.push_back(renderer.renderCalibration(1280, 720).submitWaitMs);
        return median(ms);
    };
    const double calibration = calibrate();

    // Ground truth: the reflectance equation integrated per pixel against the environment itself
    // (its brightest texels summed, the rest sampled); its convergence is shown by the same render
    // at a quarter of the samples.
    renderer.setReferenceEnvironment(environment);
    renderer.precomputeIbl(environment, ibl::IblQuality{});
    frame.iblQuality = ibl::IblQuality{};
    frame.ibl.referenceSamples = options.referenceSamples;
    const auto truthStart = std::chrono::steady_clock::now();
    const CapturedFrame truth = renderer.capture(frame);
    const double truthMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - truthStart).count();
    frame.ibl.referenceSamples = options.referenceSamples / 4;
    const ImageError convergence = imageError(renderer.capture(frame).rgba32f, truth.rgba32f);
    frame.ibl.referenceSamples = 0;
    io::writeExr(out / "ground_truth.exr", truth.width, truth.height, truth.rgba32f);
    writePreview(out / "ground_truth.png", truth);
    std::printf("ground truth: %u samples per lobe per pixel and %u texels summed, %.0f ms; a quarter of the samples "
                "differs by %.2e relative RMSE, %.2e mean relative error\n", options.referenceSamples,
                renderer.iblMaps().referenceTexelCount(), truthMs, convergence.rmse, convergence.meanRelative);

    std::vector<Result> results;
    for (const Setting& setting : sweep(options.quick)) {
        Result r{.setting = setting};
        std::vector<double> wall, gpu, setup, ratio;
        for (uint32_t i = 0; i < options.repeats; ++i) {
            // Interleaved with a calibration run, so each repeat's time is also a ratio to work
            // done under the same load.
            const double calibrationMs = renderer.renderCalibration(1280, 720).submitWaitMs;
            const auto start = std::chrono::steady_clock::now();
            const FrameTiming t = renderer.precomputeIbl(environment, setting.quality);
            const double total = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            wall.push_back(t.submitWaitMs);
            ratio.push_back(t.submitWaitMs / calibrationMs);
            setup.push_back(total - t.submitWaitMs);
            double sum = 0;
            for (double ms : t.timings.gpuMs) sum += std::max(ms, 0.0);
            gpu.push_back(sum);
        }
        r.wallMs = median(wall), r.gpuMs = median(gpu), r.setupMs = median(setup), r.ratio = median(ratio);
        const std::vector<ibl::CachedImage> maps = renderer.iblMaps().readBack();
        r.specular = ibl::specularErrors(*findImage(maps, "specular"), environment, reference, 128, cache);
        r.irradiance = ibl::irradianceErrors(*findImage(maps, "irradiance"), reference, 256, cache);
        r.lut = ibl::lutErrors(*findImage(maps, "brdf_lut"), std::max(setting.quality.lutSize / 16, 1u));
        frame.iblQuality = setting.quality;
        const CapturedFrame image = renderer.capture(frame);
        r.image = imageError(image.rgba32f, truth.rgba32f);
        if (setting.quality == ibl::IblQuality{}) {
            io::writeExr(out / "default.exr", image.width, image.height, image.rgba32f);
            writePreview(out / "default.png", image);
            writeErrorMap(out / "default_error.png", image, truth.rgba32f);
        }
        std::printf("%-24s %-10s precompute %8.1f ms = %5.2fx calibration (setup %6.1f ms); specular RMSE %.2e mean %.2e; "
                    "irradiance RMSE %.2e; LUT max %.1e; image RMSE %.2e mean %.2e\n",
                    setting.group.c_str(), setting.label.c_str(), r.wallMs, r.ratio, r.setupMs, r.specularRmse(),
                    r.specularMeanRelative(), r.irradiance.rmse, std::max(r.lut.maxA, r.lut.maxB), r.image.rmse, r.image.meanRelative);
        std::fflush(stdout);
        results.push_back(std::move(r));
    }

    // CSV: one row per setting, errors per roughness level at the end.
    std::ofstream csv(out / "report.csv");
    csv << "group,setting,cube,levels,prefilter_samples,filtered,irradiance,sh_size,irradiance_samples,lut_size,"
           "lut_samples,precompute_ms,precompute_gpu_ms,setup_ms,ratio_to_calibration,specular_rmse,specular_mean_relative,"
           "specular_max,irradiance_rmse,irradiance_mean_relative,irradiance_max,lut_max_a,lut_max_b,lut_rms_a,lut_rms_b,image_rmse,image_mean_relative,image_max";
    for (const ibl::LevelErrors& level : results.front().specular)
        csv << ",rmse_r" << fixed(level.roughness, 2) << ",mean_r" << fixed(level.roughness, 2) << ",max_r"
            << fixed(level.roughness, 2);
    csv << "\n";
    for (const Result& r : results) {
        const ibl::IblQuality& q = r.setting.quality;
        csv << '"' << r.setting.group << "\"," << r.setting.label << ',' << q.cubeSize << ',' << q.levels() << ','
            << q.prefilterSamples << ',' << (q.filteredSampling ? 1 : 0) << ',' << ibl::irradianceModeName(q.irradiance)
            << ',' << q.shSourceSize << ',' << q.irradianceSamples << ',' << q.lutSize << ',' << q.lutSamples << ','
            << fixed(r.wallMs, 2) << ',' << fixed(r.gpuMs, 2) << ',' << fixed(r.setupMs, 2) << ','
            << fixed(r.ratio, 3) << ',' << sci(r.specularRmse()) << ',' << sci(r.specularMeanRelative()) << ','
            << sci(r.specularMax()) << ',' << sci(r.irradiance.rmse) << ',' << sci(r.irradiance.meanRelative) << ','
            << sci(r.irradiance.maxRelative) << ',' << sci(r.lut.maxA) << ','
            << sci(r.lut.maxB) << ',' << sci(r.lut.rmsA) << ',' << sci(r.lut.rmsB) << ',' << sci(r.image.rmse) << ','
            << sci(r.image.meanRelative) << ',' << sci(r.image.maxRelative);
        for (const ibl::LevelErrors& level : r.specular)
            csv << ',' << sci(level.stats.rmse) << ',' << sci(level.stats.meanRelative) << ',' << sci(level.stats.maxRelative);
        csv << "\n";
    }
    if (!csv) throw UserError((out / "report.csv").string() + ": cannot write");

    // Markdown.
    std::ostringstream md;
    md << "# IBL quality report\n\nEnvironment: " << environment.source << " (" << environment.width << "x"
       << environment.height << "). Device: " << context.report().name << ". Calibration pass (1280x720): "
       << fixed(calibration, 1) << " ms. Precompute times are the median of " << options.repeats
       << " runs of submit+wait; errors are relative to the double-precision reference (ibl/ibl_errors.h): "
          "specular = mean relative luminance RMSE over roughness > 0 levels (max = max relative error), "
          "irradiance over 256 directions, LUT = max absolute error of A and B, image = the default scene "
          "(multiscatter off, no skybox) at "
       << options.width << "x" << options.height << " against the ground truth (" << options.referenceSamples
       << " samples per lobe per pixel, the brightest texels summed; a quarter of the samples differs by "
       << sci(convergence.rmse) << "): relative luminance RMSE (dominated by the sun's highlights) and mean "
          "relative error (every pixel alike, 1% of the mean added to the denominator).\n\n";
    md << "| group | setting | precompute ms | × calibration | specular RMSE | specular mean rel. | specular max | "
          "irradiance RMSE | irradiance mean rel. | LUT max | image RMSE | image mean rel. |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const ibl::IblQuality defaults;
    for (const Result& r : results)
        md << "| " << r.setting.group << " | " << r.setting.label << (r.setting.quality == defaults ? " (default)" : "")
           << " | " << fixed(r.wallMs, 1) << " | " << fixed(r.ratio, 2) << " | " << sci(r.specularRmse()) << " | "
           << sci(r.specularMeanRelative()) << " | " << sci(r.specularMax()) << " | " << sci(r.irradiance.rmse) << " | "
           << sci(r.irradiance.meanRelative) << " | "
           << sci(std::max(r.lut.maxA, r.lut.maxB)) << " | " << sci(r.image.rmse) << " | " << sci(r.image.meanRelative) << " |\n";
    md << "\nPlots: specular.png, irradiance.png, lut.png, image.png (error against precompute time, log-log, "
          "Pareto front marked, the default ringed).\n";
    std::ofstream(out / "report.md") << md.str();

    // Plots: one per error measure, every setting, series by group.
    auto plot = [&](const char* file, const char* title, const char* yLabel, auto&& error,
                    const std::vector<std::string>& groups) {
        io::PlotSpec spec{.title = title,
                          .xLabel = "precompute time / calibration pass (median of interleaved runs)",
                          .yLabel = yLabel};
        spec.series = groups;
        spec.series.push_back("other groups");
        for (const Result& r : results) {
            const auto g = std::find(groups.begin(), groups.end(), r.setting.group);
            const bool isDefault = r.setting.quality == defaults;
            if (g == groups.end() && !isDefault) continue;
            if (isDefault) spec.highlight = spec.points.size();
            spec.points.push_back({r.ratio, error(r), isDefault ? "default" : r.setting.label,
                                   uint32_t(g - groups.begin())});
        }
        io::writeLogLogPlot(out / file, spec);
    };
    const std::vector<std::string> specularGroups{"prefilter, filtered IS", "prefilter, plain IS", "cube size"};
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
    std::printf("wrote %s/report.csv, report.md, specular.png, irradiance.png, lut.png, image.png\n", out.c_str());
    if (context.validationMessageCount() > 0) {
        log::error(std::to_string(context.validationMessageCount()) + " validation messages");
        return 3;
    }
    return 0;
}

}  // namespace candela::app
