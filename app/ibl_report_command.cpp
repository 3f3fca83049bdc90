// `candela ibl-report`: what each image-based-lighting quality setting costs and what error it
// leaves. For every setting of a sweep (prefilter samples with and without filtered importance
// sampling, cube size, irradiance as SH9 or cube, BRDF LUT size and samples) it measures the
// precompute time (CPU wall around submit+wait, in --repeats rounds over every setting: the median
// and its quartiles, over the median calibration pass of the run) and compares the maps
// with the double-precision reference (reports/ibl_errors.h), then renders the default scene and compares it with a ground-truth render that integrates the
// reflectance equation per pixel. Writes report.csv, report.md and log-log plots to --out.

#include "commands.h"
#include "session.h"
#include "stopwatch.h"

#include "core/errors.h"
#include "core/log.h"
#include "core/progress.h"
#include "ibl_report.h"
#include "statistics.h"
#include "assets/image_file.h"
#include "assets/builtin_scenes.h"

#include <algorithm>
#include "stopwatch.h"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace candela::app {
namespace {

using report::Result;
using report::Setting;

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
    // The defaults before the bright-texel split (kept as a row to compare with): 32 samples, 6 levels,
    // the sun sampled, SH9.
    add("previous default", "32/6/sh9", [&](ibl::IblQuality& q) {
        q.prefilterSamples = 32;
        q.specularLevels = 6;
        q.brightTexels = 0;
        q.irradiance = ibl::IrradianceMode::Sh9;
    });
    // The prefilter without the bright-texel split: the sun sampled like the rest.
    const std::vector<uint32_t> sampledSun = quick ? std::vector<uint32_t>{32} : std::vector<uint32_t>{8, 32, 128, 512, 2048};
    for (uint32_t n : sampledSun)
        add("prefilter, sun sampled", std::to_string(n), [&](ibl::IblQuality& q) {
            q.prefilterSamples = n;
            q.brightTexels = 0;
        });
    const std::vector<uint32_t> bright = quick ? std::vector<uint32_t>{16} : std::vector<uint32_t>{16, 64, 1024, 4096};
    for (uint32_t n : bright)
        add("bright texels", "bright " + std::to_string(n), [&](ibl::IblQuality& q) { q.brightTexels = n; });
    // Roughness levels: how finely the split sum's lookup interpolates between lobes (judged against the
    // ground truth; the converged-maps comparison holds the default's levels).
    const std::vector<uint32_t> levels = quick ? std::vector<uint32_t>{} : std::vector<uint32_t>{4, 6, 9};
    for (uint32_t n : levels)
        add("roughness levels", "levels " + std::to_string(n), [&](ibl::IblQuality& q) { q.specularLevels = n; });
    const std::vector<uint32_t> plain = quick ? std::vector<uint32_t>{64} : std::vector<uint32_t>{64, 256, 1024, 2048};
    for (uint32_t n : plain)
        add("prefilter, plain IS", std::to_string(n), [&](ibl::IblQuality& q) {
            q.prefilterSamples = n;
            q.filteredSampling = false;
        });
    const std::vector<uint32_t> cubes = quick ? std::vector<uint32_t>{64} : std::vector<uint32_t>{64, 128, 512, 1024};
    for (uint32_t size : cubes) add("cube size", std::to_string(size), [&](ibl::IblQuality& q) { q.cubeSize = size; });
    const std::vector<uint32_t> sh = quick ? std::vector<uint32_t>{8} : std::vector<uint32_t>{8, 16, 32, 64, 128};
    for (uint32_t size : sh)
        add("irradiance SH9", "sh9:" + std::to_string(size), [&](ibl::IblQuality& q) {
            q.irradiance = ibl::IrradianceMode::Sh9;
            q.shSourceSize = size;
        });
    // The default is cube:256 (measured in the prefilter series).
    const std::vector<uint32_t> cube = quick ? std::vector<uint32_t>{64} : std::vector<uint32_t>{16, 64, 1024};
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

const ibl::CachedImage* findImage(const std::vector<ibl::CachedImage>& images, const std::string& prefix) {
    for (const ibl::CachedImage& image : images)
        if (image.name.rfind(prefix, 0) == 0) return &image;
    return nullptr;
}

// The ground truth and how far it converged: the same render at a quarter of the samples.
struct GroundTruth {
    CapturedFrame truth;
    reports::ErrorStats convergence;
    report::VisibleError visibleConvergence;
};

// Renders the ground truth of `frame` (written to the report folder as ground_truth.exr and .png)
// and the convergence check, and prints the line about them; `frame` is left at the default
// quality without reference samples.
GroundTruth groundTruth(Renderer& renderer, RenderSettings& frame, const assets::Environment& environment,
                        const IblReportOptions& options, Progress& progress) {
    const std::filesystem::path folder = options.out;
    GroundTruth out;
    progress.step(0, "ground truth (" + std::to_string(options.referenceSamples) + " samples per pixel)");
    renderer.setReferenceEnvironment(environment);
    renderer.precomputeIbl(environment, ibl::IblQuality{});
    frame.iblQuality = ibl::IblQuality{};
    frame.ibl.referenceSamples = options.referenceSamples;
    const auto truthStart = Clock::now();
    out.truth = renderer.capture(frame);
    const CapturedFrame& truth = out.truth;
    const double truthMs = msSince(truthStart);
    frame.ibl.referenceSamples = options.referenceSamples / 4;
    const CapturedFrame quarter = renderer.capture(frame);
    out.convergence = report::imageError(quarter.rgba32f, truth.rgba32f);
    out.visibleConvergence =
        report::visibleError(quarter.rgba32f, truth.rgba32f, truth.width, truth.height);
    frame.ibl.referenceSamples = 0;
    assets::writeExr(folder / "ground_truth.exr", truth.width, truth.height, truth.rgba32f);
    report::writePreview(folder / "ground_truth.png", truth);
    progress.clear();
    std::printf("ground truth: %u samples per lobe per pixel and %u texels summed, %.0f ms; a quarter of the samples "
                "differs by %.2e relative RMSE, %.2e mean relative error, FLIP max %.3f\n", options.referenceSamples,
                renderer.iblMaps().referenceTexelCount(), truthMs, out.convergence.rmse, out.convergence.meanRelative,
                out.visibleConvergence.flipMax);

    return out;
}

// What each setting's errors are measured against: the environment, its reference and the
// reference integrals' cache.
struct ErrorReference {
    const assets::Environment& environment;
    const assets::Environment& reference;
    reports::ReferenceCache& cache;
};

// Each setting's errors, one precompute per setting: its maps against the reference integrals, its
// image (`frame` at the setting's quality) against the ground truth `truth` and against the image
// with converged maps; the default setting's image and error map are written to `out`.
std::vector<Result> measureErrors(Renderer& renderer, RenderSettings frame, const std::vector<Setting>& settings,
                                  const ErrorReference& to, const CapturedFrame& truth, const CapturedFrame& converged,
                                  const std::filesystem::path& out, Progress& progress) {
    const assets::Environment& environment = to.environment;
    std::vector<Result> results;
    for (const Setting& setting : settings) {
        progress.step(results.size() + 1, setting.group + " " + setting.label + ": errors");
        Result r{.setting = setting};
        renderer.precomputeIbl(environment, setting.quality);
        const std::vector<ibl::CachedImage> maps = renderer.iblMaps().readBack();
        r.specular = reports::specularErrors(*findImage(maps, "specular"), environment, to.reference, 128, to.cache);
        r.irradiance = reports::irradianceErrors(*findImage(maps, "irradiance"), to.reference, 256, to.cache);
        r.lut = reports::lutErrors(*findImage(maps, "brdf_lut"), std::max(setting.quality.lutSize / 16, 1u));
        frame.iblQuality = setting.quality;
        const CapturedFrame image = renderer.capture(frame);
        r.image = report::imageError(image.rgba32f, truth.rgba32f);
        r.visible = report::visibleError(image.rgba32f, truth.rgba32f, image.width, image.height);
        r.visibleMaps = report::visibleError(image.rgba32f, converged.rgba32f, image.width, image.height);
        if (setting.quality == ibl::IblQuality{}) {
            assets::writeExr(out / "default.exr", image.width, image.height, image.rgba32f);
            report::writePreview(out / "default.png", image);
            report::writeErrorMap(out / "default_error.png", image, truth.rgba32f);
        }
        results.push_back(std::move(r));
    }
    return results;
}

}  // namespace

int runIblReport(const IblReportOptions& options) {
    const std::filesystem::path out = options.out;
    prepareReportFolder(out, {"report.csv", "report.md", "specular.png", "irradiance.png", "lut.png", "image.png",
                              "image_worst.png"});

    Session session(options.common, options.env);
    const assets::Environment& environment = *session.environment();  // the parser refuses --env none
    const assets::Environment reference = reports::referenceEnvironment(environment);
    reports::ReferenceCache cache;

    session.start();
    vk::Context& context = session.context();
    Renderer& renderer = session.renderer();
    const scene::Scene scene = assets::makeSphereGrid();
    RenderSettings frame{.width = options.width, .height = options.height, .floatOutput = true, .scene = &scene};
    frame.environment = &environment;
    frame.ibl.skybox = false;        // compare the lit scene only
    frame.ibl.multiscatter = false;  // the ground truth integrates the single-scattering BRDF
    frame.defaultLights = false;

    // Ground truth: the reflectance equation integrated per pixel against the environment itself
    // (its brightest texels summed, the rest sampled); its convergence is shown by the same render
    // at a quarter of the samples.
    const std::vector<Setting> settings = sweep(options.quick);
    // Steps: the ground truth, each setting's errors, each setting in each timing round, the files.
    Progress progress("ibl-report", 2 + settings.size() * (1 + options.repeats), options.common.quiet);
    const GroundTruth ground = groundTruth(renderer, frame, environment, options, progress);
    const CapturedFrame& truth = ground.truth;

    // The split sum with converged maps: what each setting's maps are compared with on screen.
    ibl::IblQuality convergedQuality;
    convergedQuality.prefilterSamples = 2048;
    convergedQuality.brightTexels = 4096;
    convergedQuality.irradiance = ibl::IrradianceMode::Cube;  // SH9 truncates a sun; the cube converges
    convergedQuality.irradianceSamples = 1024;
    renderer.precomputeIbl(environment, convergedQuality);
    const double convergedSpecularMax =
        Result{.specular = reports::specularErrors(*findImage(renderer.iblMaps().readBack(), "specular"), environment,
                                               reference, 128, cache)}
            .specularMax();
    frame.iblQuality = convergedQuality;
    const CapturedFrame converged = renderer.capture(frame);

    // Errors first, one precompute per setting (which also builds its pipelines before any is timed).
    std::vector<Result> results = measureErrors(renderer, frame, settings, {environment, reference, cache}, truth, converged, out, progress);
    // Times: rounds over every setting, alternately forwards and backwards, so that a drift of
    // the machine's speed reaches every setting alike, with a calibration run before each
    // precompute. A single calibration run right after a precompute varies far more than the
    // precompute does (18.6–41.8 ms against ±2% in one run), so a run's ratio to its neighbour is
    // noise: the ratio is the setting's median over the median of every calibration run.
    struct Times {
        std::vector<double> wall, gpu, setup;
    };
    std::vector<Times> times(settings.size());
    std::vector<double> calibrations;
    for (uint32_t round = 0; round < options.repeats; ++round)
        for (size_t k = 0; k < settings.size(); ++k) {
            const size_t i = round % 2 == 0 ? k : settings.size() - 1 - k;
            progress.step(1 + settings.size() * (1 + round) + k, settings[i].group + " " + settings[i].label + ": round " +
                                                   std::to_string(round + 1) + " of " + std::to_string(options.repeats));
            const double calibrationMs = renderer.renderCalibration(1280, 720).submitWaitMs;
            calibrations.push_back(calibrationMs);
            const auto start = Clock::now();
            const FrameTiming t = renderer.precomputeIbl(environment, settings[i].quality);
            const double total = msSince(start);
            Times& m = times[i];
            m.wall.push_back(t.submitWaitMs);
            m.setup.push_back(total - t.submitWaitMs);
            double sum = 0;
            for (double ms : t.timings.gpuMs) sum += std::max(ms, 0.0);
            m.gpu.push_back(sum);
        }
    progress.clear();
    const Spread calibration = spreadOf(calibrations);
    for (size_t i = 0; i < results.size(); ++i) {
        Result& r = results[i];
        const Spread wall = spreadOf(times[i].wall);
        r.wallMs = wall.median, r.wallLowMs = wall.low, r.wallHighMs = wall.high;
        r.gpuMs = median(times[i].gpu), r.setupMs = median(times[i].setup);
        r.ratio = wall.median / calibration.median;
        r.ratioLow = wall.low / calibration.median, r.ratioHigh = wall.high / calibration.median;
        std::printf("%-24s %-10s precompute %8.1f ms (%.1f–%.1f) = %5.2fx calibration (%.2f–%.2f; setup %6.1f ms); specular "
                    "RMSE %.2e mean %.2e; irradiance RMSE %.2e; LUT max %.1e; image RMSE %.2e mean %.2e; FLIP p99.9 %.3f max "
                    "%.3f, against converged maps %.3f %.3f\n",
                    r.setting.group.c_str(), r.setting.label.c_str(), r.wallMs, r.wallLowMs, r.wallHighMs, r.ratio,
                    r.ratioLow, r.ratioHigh, r.setupMs, r.specularRmse(), r.specularMeanRelative(), r.irradiance.rmse,
                    std::max(r.lut.maxA, r.lut.maxB), r.image.rmse, r.image.meanRelative, r.visible.flipP999,
                    r.visible.flipMax, r.visibleMaps.flipP999, r.visibleMaps.flipMax);
    }
    std::fflush(stdout);
    progress.step(1 + settings.size() * (1 + options.repeats), "writing the report");
    progress.finish();

    report::writeCsv(out, results);
    report::writeMarkdown(out,
                          {.environment = environment.source + " (" + std::to_string(environment.width) + "x" +
                                          std::to_string(environment.height) + ")",
                           .device = context.report().name,
                           .calibrationMs = calibration.median,
                           .calibrationLowMs = calibration.low,
                           .calibrationHighMs = calibration.high,
                           .repeats = options.repeats,
                           .width = options.width,
                           .height = options.height,
                           .referenceSamples = options.referenceSamples,
                           .convergence = ground.convergence,
                           .visibleConvergence = ground.visibleConvergence,
                           .converged = convergedQuality.canonical(),
                           .convergedSpecularMax = convergedSpecularMax},
                          results);
    report::writePlots(out, results);
    std::printf("wrote %s/report.csv, report.md, specular.png, irradiance.png, lut.png, image.png, image_worst.png\n",
                out.c_str());
    return session.exitCode(0);
}

}  // namespace candela::app
