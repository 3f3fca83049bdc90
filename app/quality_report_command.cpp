// `candela quality-report`: image error against run time for the anti-aliasing and geometry
// settings — MSAA × specular anti-aliasing × level-of-detail error, on each shading path the device
// has (docs/shading-paths.md) — on a set of scenes. Per
// setting: the frame time as a ratio to the calibration pass of the same run (the median of
// --repeats rounds over every setting, with the quartiles of the rounds), the error against a
// reference (full detail, no specular AA, 4× the width and height, i.e. 16 samples per pixel,
// box-downsampled in linear radiance; both display-encoded as the tonemap pass does: mean and 99th
// percentile in levels of 255) over a slow orbit of the camera (1° per frame), and the orbit's
// mean frame-to-frame difference (motion plus shimmer; the reference's own is the motion alone)
// and its temporal error (the flicker the reference does not have). Settings that differ only in
// their LOD error and draw the same work and the same images are one point (sameWork).
// Writes report.csv, report.md and, per scene, SCENE_error.png and SCENE_temporal.png (log-log,
// Pareto front, the device's defaults ringed). See docs/anti-aliasing.md.

#include "commands.h"
#include "session.h"
#include "stopwatch.h"
#include "frame_measurement.h"
#include "statistics.h"

#include "core/errors.h"
#include "core/log.h"
#include "core/progress.h"
#include "assets/image_file.h"
#include "reports/image_error.h"
#include "reports/plot.h"
#include "render/visibility_path.h"
#include "assets/builtin_scenes.h"
#include "assets/gltf_loader.h"
#include "assets/procedural_sky.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <list>
#include <set>
#include <tuple>

namespace candela::app {
namespace {

constexpr uint32_t kReferenceScale = 4;  // per axis: 16 samples per pixel

struct QualityRow {
    std::string scene;
    uint32_t msaa = 1;
    bool specularAa = false;
    std::vector<float> lodErrors;  // one, or those that drew the same work and images (sameWork)
    options::ShadingPath path = options::ShadingPath::Forward;
    Spread frameRatio;             // over the rounds: median and quartiles
    double frameMs = 0.0;          // median over the rounds of each round's median frame
    std::vector<double> roundRatios, roundMs;
    reports::DisplayError error;
    double temporal = 0.0;       // mean frame-to-frame difference over the orbit
    double temporalError = 0.0;  // its difference from the reference's frame-to-frame changes (flicker)
    uint64_t triangles = 0;
    uint32_t draws = 0;
    bool pareto = false;  // on the (frame ratio, mean error) front of its scene, spreads considered
    bool isDefault = false;
    RenderSettings settings;  // of the first setting, timed for all (valid while its scene is measured)
};

struct SceneResult {
    std::string name;
    double referenceTemporal = 0.0;
    double referenceSeconds = 0.0;
    std::vector<QualityRow> rows;
};

std::string sceneName(const std::string& entry) {
    return entry == "default" ? "default" : std::filesystem::path(entry).stem().string();
}

// The frames of the orbit at `settings` (floatOutput), display-encoded; `scale` > 1 renders that
// many times larger and box-downsamples.
std::vector<std::vector<uint8_t>> orbitFrames(Renderer& renderer, RenderSettings settings, uint32_t frames, uint32_t scale) {
    settings.floatOutput = true;
    settings.width *= scale;
    settings.height *= scale;
    std::vector<std::vector<uint8_t>> out;
    // 1° per frame around the scene, at the distance framing chooses for the first frame (framing
    // each direction would move the camera in and out).
    settings.camera.orbit = glm::vec3(0.0f, 90.0f, 0.0f);
    const float distance =
        Renderer::orbitCamera(*settings.scene, settings.camera, float(settings.width) / float(settings.height), settings.pose).radius;
    for (uint32_t k = 0; k < frames; ++k) {
        settings.camera.orbit = glm::vec3(float(k), 90.0f, distance);
        const CapturedFrame frame = renderer.capture(settings);
        reports::FloatImage image{frame.width, frame.height, frame.rgba32f};
        out.push_back(reports::displayEncode(scale > 1 ? reports::boxDownsample(image, scale) : image));
    }
    return out;
}

// A row as a point of error against frame time for the Pareto front and the plots: the frame
// ratio's spread over the rounds, and the error compared at the table's precision (3 decimals:
// values within half its last digit count as equal).
reports::PlotPoint paretoPoint(const QualityRow& r, double error) {
    constexpr double kHalfDigit = 0.0005;
    return {.x = r.frameRatio.median, .y = error, .xLow = r.frameRatio.low, .xHigh = r.frameRatio.high,
            .yLow = std::max(error - kHalfDigit, 0.0), .yHigh = error + kHalfDigit};
}

// The row's LOD errors, "0/0.5/2" for merged settings.
std::string lodList(const QualityRow& r) {
    std::string out;
    for (float lod : r.lodErrors) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", double(lod));
        out += (out.empty() ? "" : "/") + std::string(text);
    }
    return out;
}

std::string settingName(const QualityRow& r) {
    char text[160];
    std::snprintf(text, sizeof text, "MSAA %u, specular AA %s, LOD %s px, %s path", r.msaa, r.specularAa ? "on" : "off",
                  lodList(r).c_str(), options::shadingPathName(r.path));
    return text;
}

// Whether a setting that differs from `row` only in its LOD error did the same work and drew the
// same: the same submitted draws and triangles in the timed view, and byte-identical display
// frames over the whole orbit. Such settings are one point of the report.
bool sameWork(const QualityRow& row, const std::vector<std::vector<uint8_t>>& rowFrames, const passes::DrawStats& stats,
              const std::vector<std::vector<uint8_t>>& frames) {
    return row.draws == stats.submittedDraws && row.triangles == stats.submittedTriangles && rowFrames == frames;
}

void writeReport(const std::filesystem::path& out, const std::vector<SceneResult>& results, const QualityReportOptions& o,
                 const std::string& device, const vk::MsaaChoice& defaultMsaa, const std::vector<std::string>& notes) {
    TextFile csv(out / "report.csv");
    csv << "scene,msaa,specular_aa,lod_error_px,shading_path,frame_ratio,frame_ratio_min,frame_ratio_max,frame_ms,mean_error,"
           "p99_error,temporal,temporal_error,reference_temporal,submitted_triangles,pareto,default\n";
    for (const SceneResult& s : results)
        for (const QualityRow& r : s.rows)
            csv << r.scene << "," << r.msaa << "," << (r.specularAa ? "on" : "off") << "," << lodList(r) << ","
                << options::shadingPathName(r.path) << "," << r.frameRatio.median << "," << r.frameRatio.low << ","
                << r.frameRatio.high << "," << r.frameMs << "," << r.error.mean << "," << r.error.p99 << "," << r.temporal << "," << r.temporalError << ","
                << s.referenceTemporal << "," << r.triangles << "," << r.pareto << "," << r.isDefault << "\n";

    csv.commit();
    TextFile md(out / "report.md");
    md << "# Quality report: anti-aliasing and levels of detail\n\n"
       << o.width << "×" << o.height << " on " << device << ". Frame time: in each of " << o.repeats
       << " rounds over every setting (alternately forwards and backwards), the median of " << o.frames
       << " frames over the median of the calibration passes run between them; the median of the rounds, their "
          "quartiles in brackets (nearest rank: for 3 rounds the lowest and highest, for 5 the second and fourth). Settings that differ only in their LOD error and submitted the same draws and "
          "triangles and drew byte-identical frames over the orbit are one row (LOD errors joined by /). Error: against a reference with full detail and "
          "no specular AA at "
       << kReferenceScale << "× the width and height (" << kReferenceScale * kReferenceScale
       << " samples per pixel), box-downsampled in linear radiance; both tonemapped (PBR Neutral) and sRGB-encoded to 8 "
          "bits; mean absolute difference and 99th percentile of each pixel's largest channel difference, in levels of "
          "255, over "
       << o.orbitFrames << " frames of an orbit at 1° per frame. Temporal: the mean absolute frame-to-frame difference "
          "over that orbit (motion plus shimmer; the reference's own is the motion), and its error: the mean absolute "
          "difference between the setting's frame-to-frame changes and the reference's (the flicker the reference does "
          "not have). ★: on the Pareto front of frame "
          "time against mean error, where a row is dominated only by one that is better beyond the spread on one axis "
          "(frame time: the brackets do not overlap; error: lower at the table's 3 decimals) and not worse beyond it "
          "on the other. Default on this device: MSAA "
       << defaultMsaa.samples << ", specular AA " << (options::ShadingOptions{}.specularAntiAliasing ? "on" : "off") << ", LOD "
       << options::DrawSelection::kDefaultLodErrorPixels << " px.\n\n";
    for (const std::string& note : notes) md << "- " << note << "\n";
    if (!notes.empty()) md << "\n";
    for (const SceneResult& s : results) {
        char line[320];
        std::snprintf(line, sizeof line, "## %s\n\nReference orbit (%.1f s to render): frame-to-frame difference %.3f/255.\n\n",
                      s.name.c_str(), s.referenceSeconds, s.referenceTemporal);
        md << line
           << "| MSAA | specular AA | LOD error (px) | shading path | frame / calibration | mean error | p99 error | temporal | temporal error | triangles | |\n"
           << "|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const QualityRow& r : s.rows) {
            std::snprintf(line, sizeof line, "| %u | %s | %s | %s | %.2f× (%.2f–%.2f) | %.3f | %.0f | %.3f | %.3f | %llu | %s%s |\n",
                          r.msaa, r.specularAa ? "on" : "off", lodList(r).c_str(), options::shadingPathName(r.path),
                          r.frameRatio.median, r.frameRatio.low, r.frameRatio.high, r.error.mean, r.error.p99, r.temporal,
                          r.temporalError, (unsigned long long)r.triangles, r.pareto ? "★" : "", r.isDefault ? " default" : "");
            md << line;
        }
        md << "\n![" << s.name << ": error against frame time](" << s.name << "_error.png)\n![" << s.name
           << ": temporal error against frame time](" << s.name << "_temporal.png)\n\n";

        for (const bool temporal : {false, true}) {
            reports::PlotSpec plot{.title = s.name + (temporal ? ": temporal error against frame time"
                                                           : ": image error against frame time"),
                              .xLabel = "frame time / calibration",
                              .yLabel = temporal ? "temporal error: flicker vs the reference (of 255)" : "mean error (of 255)"};
            // One series per (MSAA, specular AA, shading path), in that order in every scene's plots.
            std::set<std::tuple<uint32_t, bool, options::ShadingPath>> keys;
            for (const QualityRow& r : s.rows) keys.insert({r.msaa, r.specularAa, r.path});
            const std::vector<std::tuple<uint32_t, bool, options::ShadingPath>> series(keys.begin(), keys.end());
            for (const auto& [msaa, specularAa, path] : series)
                plot.series.push_back("MSAA " + std::to_string(msaa) + ", specular AA " + (specularAa ? "on" : "off") + ", " +
                                      options::shadingPathName(path));
            for (const QualityRow& r : s.rows) {
                const auto it = std::find(series.begin(), series.end(), std::tuple{r.msaa, r.specularAa, r.path});
                if (r.isDefault) plot.highlight = plot.points.size();
                reports::PlotPoint point = paretoPoint(r, temporal ? r.temporalError : r.error.mean);
                point.label = lodList(r) + " px";
                point.series = uint32_t(it - series.begin());
                plot.points.push_back(point);
            }
            reports::writeLogLogPlot(out / (s.name + (temporal ? "_temporal.png" : "_error.png")), plot);
        }
    }
    md.commit();
}

// What the settings of one scene are measured with, and the progress over all of them.
struct Sweep {
    const QualityReportOptions& options;
    Renderer& renderer;
    vk::MsaaChoice defaultMsaa;
    options::ShadingPath defaultPath;
    Progress& progress;
    size_t& done;  // progress steps taken
};

// One series of settings: an MSAA sample count, specular AA on or off and a shading path.
struct Series {
    uint32_t samples = 1;
    bool specularAa = false;
    options::ShadingPath path = options::ShadingPath::Forward;
};

// The errors of `series` at each LOD error of --lod-errors (in a row, so that a setting that
// repeats the previous ones' work joins their row: sameWork), added to `result`'s rows.
void measureSeries(Sweep& sweep, const RenderSettings& base, const Series& series,
                   const std::vector<std::vector<uint8_t>>& reference, SceneResult& result) {
    const auto [samples, specularAa, path] = series;
    Renderer& renderer = sweep.renderer;
    const QualityReportOptions& options = sweep.options;
    std::vector<std::vector<std::vector<uint8_t>>> seriesFrames;  // per row of this series
    const size_t seriesStart = result.rows.size();
    for (float lodError : options.lodErrors) {
        RenderSettings settings = base;
        settings.shadingPath = path;
        settings.msaa = samples;
        settings.shadingOptions.specularAntiAliasing = specularAa;
        settings.drawSelection.lodErrorPixels = lodError;
        settings.camera.orbit = glm::vec3(0.0f, 90.0f, 0.0f);
        renderer.renderFrame(settings);  // the timed view: what it submits
        const passes::DrawStats stats = renderer.drawStats();
        std::vector<std::vector<uint8_t>> frames = orbitFrames(renderer, settings, options.orbitFrames, 1);
        const bool isDefault = samples == sweep.defaultMsaa.samples &&
                               specularAa == options::ShadingOptions{}.specularAntiAliasing &&
                               lodError == options::DrawSelection::kDefaultLodErrorPixels &&
                               path == sweep.defaultPath;
        QualityRow* same = nullptr;
        for (size_t k = 0; k < seriesFrames.size() && !same; ++k)
            if (sameWork(result.rows[seriesStart + k], seriesFrames[k], stats, frames)) same = &result.rows[seriesStart + k];
        if (same) {
            same->lodErrors.push_back(lodError);
            same->isDefault = same->isDefault || isDefault;
        } else {
            result.rows.push_back({.scene = result.name, .msaa = samples, .specularAa = specularAa,
                                   .lodErrors = {lodError}, .path = path,
                                   .error = reports::displayError(frames, reference),
                                   .temporal = reports::meanFrameToFrameDifference(frames),
                                   .temporalError = reports::meanTemporalError(frames, reference),
                                   .triangles = stats.submittedTriangles, .draws = stats.submittedDraws,
                                   .isDefault = isDefault, .settings = settings});
            seriesFrames.push_back(std::move(frames));
        }
        const QualityRow& row = same ? *same : result.rows.back();
        char detail[240];
        std::snprintf(detail, sizeof detail, "%s %s: error %.3f (p99 %.0f), temporal error %.3f%s", result.name.c_str(),
                      settingName(row).c_str(), row.error.mean, row.error.p99, row.temporalError,
                      same ? " (the same work and images: one point)" : "");
        sweep.progress.step(++sweep.done, detail);
    }
}

}  // namespace

int runQualityReport(const QualityReportOptions& options) {
    std::vector<std::string> scenes;
    for (const std::string& entry : options.scenes) {
        const std::string name = sceneName(entry);
        if (std::find(scenes.begin(), scenes.end(), name) != scenes.end())
            throw UserError("--scenes: two scenes named '" + name + "'");
        scenes.push_back(name);
    }
    std::vector<std::string> files = {"report.csv", "report.md"};
    for (const std::string& name : scenes) files.insert(files.end(), {name + "_error.png", name + "_temporal.png"});
    prepareReportFolder(options.out, {});
    for (const std::string& file : files) assets::checkWritable(std::filesystem::path(options.out) / file);

    // Everything the sweep needs is loaded first, so that a bad file fails before minutes of work.
    const assets::Environment sky = assets::makeProceduralSky();
    // The session's environment: the --env file of the glTF scenes; none with --env sky.
    const bool fileEnvironment = options.env.kind == EnvironmentChoice::Kind::File;
    Session session(options.common, fileEnvironment ? options.env : EnvironmentChoice{EnvironmentChoice::Kind::None});
    std::list<scene::Scene> loaded;  // the renderer keeps pointing at the last scene it drew
    for (const std::string& entry : options.scenes) {
        scene::Scene& scene = loaded.emplace_back(entry == "default" ? assets::makeSphereGrid() : assets::loadGltf(entry));
        for (const std::string& warning : scene.report.warnings) log::warn(entry + ": " + warning);
        for (const std::string& note : scene.report.notes) log::info(entry + ": " + note);
    }

    session.start();
    vk::Context& context = session.context();
    Renderer& renderer = session.renderer();
    const vk::MsaaChoice defaultMsaa = renderer.msaa(std::nullopt);
    std::vector<uint32_t> sampleCounts;
    std::vector<std::string> notes;
    for (uint32_t asked : options.msaa) {
        const vk::MsaaChoice choice = renderer.msaa(asked);
        if (choice.clamped)
            notes.push_back("MSAA " + std::to_string(asked) + ": not supported here (" + choice.reason + "), not measured apart");
        if (std::find(sampleCounts.begin(), sampleCounts.end(), choice.samples) == sampleCounts.end())
            sampleCounts.push_back(choice.samples);
    }
    // Both shading paths where the device has the visibility path (docs/shading-paths.md).
    std::vector<options::ShadingPath> paths = {options::ShadingPath::Forward};
    if (context.choices().visibilityUnsupported.empty()) paths.push_back(options::ShadingPath::Visibility);
    const size_t perScene = sampleCounts.size() * 2 * options.lodErrors.size() * paths.size();
    // Steps: per scene its reference, then each setting's orbit, then each setting in each timing
    // round (a merged setting's steps are taken together).
    Progress progress("quality-report", options.scenes.size() * (1 + perScene * (1 + options.repeats)), options.common.quiet);
    size_t done = 0;

    Sweep sweep{options, renderer, defaultMsaa, defaultShadingPath(context).first, progress, done};
    std::vector<SceneResult> results;
    auto scene = loaded.begin();
    for (size_t s = 0; s < options.scenes.size(); ++s, ++scene) {
        const bool builtin = options.scenes[s] == "default";
        const assets::Environment* environment = builtin || !fileEnvironment ? &sky : session.environment();
        SceneResult result{.name = scenes[s]};
        RenderSettings base{.width = options.width, .height = options.height, .scene = &*scene, .environment = environment};
        base.ibl.skybox = true;
        base.drawSelection.lodErrorPixels = 0.0f;
        base.msaa = 1;
        renderer.validateSettings(base);
        progress.step(done, result.name + ": reference (" + std::to_string(options.width * kReferenceScale) + "x" +
                                std::to_string(options.height * kReferenceScale) + ", " + std::to_string(options.orbitFrames) +
                                " frames)");
        const auto referenceStart = Clock::now();
        const std::vector<std::vector<uint8_t>> reference = orbitFrames(renderer, base, options.orbitFrames, kReferenceScale);
        result.referenceSeconds = msSince(referenceStart) / 1000.0;
        ++done;
        result.referenceTemporal = reports::meanFrameToFrameDifference(reference);
        // Errors first, the LOD errors of one (MSAA, specular AA, path) in a row so that a setting
        // that repeats the previous ones' work joins their row (sameWork).
        for (uint32_t samples : sampleCounts)
            for (bool specularAa : {false, true})
                for (options::ShadingPath path : paths) measureSeries(sweep, base, {samples, specularAa, path}, reference, result);
        // Timing: rounds over every point, alternately forwards and backwards, so that a drift of
        // the machine's speed reaches every setting alike; each round's ratio is the median frame
        // over the median of the calibration passes interleaved with the frames.
        for (uint32_t round = 0; round < options.repeats; ++round)
            for (size_t k = 0; k < result.rows.size(); ++k) {
                QualityRow& row = result.rows[round % 2 == 0 ? k : result.rows.size() - 1 - k];
                const FrameMeasurement m = measureFrames(renderer, row.settings, options.frames);
                row.roundMs.push_back(median(m.frameMs));
                row.roundRatios.push_back(median(m.frameMs) / median(m.calibrationMs));
                done += row.lodErrors.size();
                char detail[240];
                std::snprintf(detail, sizeof detail, "%s %s: round %u of %u, %.2fx calibration", result.name.c_str(),
                              settingName(row).c_str(), round + 1, options.repeats, row.roundRatios.back());
                progress.step(done, detail);
            }
        std::vector<reports::PlotPoint> points;
        for (QualityRow& r : result.rows) {
            r.frameRatio = spreadOf(r.roundRatios);
            r.frameMs = median(r.roundMs);
            points.push_back(paretoPoint(r, r.error.mean));
        }
        for (size_t i : reports::paretoFront(points)) result.rows[i].pareto = true;
        std::sort(result.rows.begin(), result.rows.end(),
                  [](const QualityRow& a, const QualityRow& b) { return a.frameRatio.median < b.frameRatio.median; });
        results.push_back(std::move(result));
    }
    progress.finish();
    writeReport(options.out, results, options, context.report().name, defaultMsaa, notes);
    std::printf("wrote %s/report.csv, report.md and 2 plots per scene\n", options.out.c_str());
    return session.exitCode(0);
}

}  // namespace candela::app
