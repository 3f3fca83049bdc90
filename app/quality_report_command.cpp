// `candela quality-report`: image error against run time for the anti-aliasing and geometry
// settings — MSAA × specular anti-aliasing × level-of-detail error, on each shading path the device
// has (docs/shading-paths.md) — on a set of scenes. Per
// setting: the frame time as a ratio to the calibration pass of the same run, the error against a
// reference (full detail, no specular AA, 4× the width and height, i.e. 16 samples per pixel,
// box-downsampled in linear radiance; both display-encoded as the tonemap pass does: mean and 99th
// percentile in levels of 255) over a slow orbit of the camera (1° per frame), and the orbit's
// mean frame-to-frame difference (motion plus shimmer; the reference's own is the motion alone)
// and its temporal error (the flicker the reference does not have).
// Writes report.csv, report.md and, per scene, SCENE_error.png and SCENE_temporal.png (log-log,
// Pareto front, the device's defaults ringed). See docs/anti-aliasing.md.

#include "commands.h"
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

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <list>
#include <set>
#include <tuple>

namespace candela::app {
namespace {

constexpr uint32_t kReferenceScale = 4;  // per axis: 16 samples per pixel

struct Row {
    std::string scene;
    uint32_t msaa = 1;
    bool specularAa = false;
    float lodError = 0.0f;
    passes::ShadingPath path = passes::ShadingPath::Forward;
    double frameRatio = 0.0, frameMs = 0.0;
    io::DisplayError error;
    double temporal = 0.0;       // mean frame-to-frame difference over the orbit
    double temporalError = 0.0;  // its difference from the reference's frame-to-frame changes (flicker)
    uint64_t triangles = 0;
    bool pareto = false;  // on the (frame ratio, mean error) front of its scene
    bool isDefault = false;
};

struct SceneResult {
    std::string name;
    double referenceTemporal = 0.0;
    double referenceSeconds = 0.0;
    std::vector<Row> rows;
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
        io::FloatImage image{frame.width, frame.height, frame.rgba32f};
        out.push_back(io::displayEncode(scale > 1 ? io::boxDownsample(image, scale) : image));
    }
    return out;
}

std::string settingName(const Row& r) {
    char text[128];
    std::snprintf(text, sizeof text, "MSAA %u, specular AA %s, LOD %g px, %s path", r.msaa, r.specularAa ? "on" : "off",
                  double(r.lodError), passes::shadingPathName(r.path));
    return text;
}

void writeReport(const std::filesystem::path& out, const std::vector<SceneResult>& results, const QualityReportOptions& o,
                 const std::string& device, const vk::MsaaChoice& defaultMsaa, const std::vector<std::string>& notes) {
    std::ofstream csv(out / "report.csv");
    csv << "scene,msaa,specular_aa,lod_error_px,shading_path,frame_ratio,frame_ms,mean_error,p99_error,temporal,temporal_error,"
           "reference_temporal,submitted_triangles,pareto,default\n";
    for (const SceneResult& s : results)
        for (const Row& r : s.rows)
            csv << r.scene << "," << r.msaa << "," << (r.specularAa ? "on" : "off") << "," << r.lodError << ","
                << passes::shadingPathName(r.path) << "," << r.frameRatio
                << "," << r.frameMs << "," << r.error.mean << "," << r.error.p99 << "," << r.temporal << "," << r.temporalError << ","
                << s.referenceTemporal << "," << r.triangles << "," << r.pareto << "," << r.isDefault << "\n";

    std::ofstream md(out / "report.md");
    md << "# Quality report: anti-aliasing and levels of detail\n\n"
       << o.width << "×" << o.height << " on " << device << ". Frame time: median of " << o.frames
       << " frames as a ratio to the calibration pass of the same run. Error: against a reference with full detail and "
          "no specular AA at "
       << kReferenceScale << "× the width and height (" << kReferenceScale * kReferenceScale
       << " samples per pixel), box-downsampled in linear radiance; both tonemapped (PBR Neutral) and sRGB-encoded to 8 "
          "bits; mean absolute difference and 99th percentile of each pixel's largest channel difference, in levels of "
          "255, over "
       << o.orbitFrames << " frames of an orbit at 1° per frame. Temporal: the mean absolute frame-to-frame difference "
          "over that orbit (motion plus shimmer; the reference's own is the motion), and its error: the mean absolute "
          "difference between the setting's frame-to-frame changes and the reference's (the flicker the reference does "
          "not have). ★: on the Pareto front of frame "
          "time against mean error. Default on this device: MSAA "
       << defaultMsaa.samples << ", specular AA " << (passes::ShadingOptions{}.specularAntiAliasing ? "on" : "off") << ", LOD "
       << passes::DrawSelection::kDefaultLodErrorPixels << " px.\n\n";
    for (const std::string& note : notes) md << "- " << note << "\n";
    if (!notes.empty()) md << "\n";
    for (const SceneResult& s : results) {
        char line[320];
        std::snprintf(line, sizeof line, "## %s\n\nReference orbit (%.1f s to render): frame-to-frame difference %.3f/255.\n\n",
                      s.name.c_str(), s.referenceSeconds, s.referenceTemporal);
        md << line
           << "| MSAA | specular AA | LOD error (px) | shading path | frame / calibration | mean error | p99 error | temporal | temporal error | triangles | |\n"
           << "|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const Row& r : s.rows) {
            std::snprintf(line, sizeof line, "| %u | %s | %g | %s | %.2f× | %.3f | %.0f | %.3f | %.3f | %llu | %s%s |\n", r.msaa,
                          r.specularAa ? "on" : "off", double(r.lodError), passes::shadingPathName(r.path), r.frameRatio, r.error.mean, r.error.p99,
                          r.temporal, r.temporalError, (unsigned long long)r.triangles, r.pareto ? "★" : "", r.isDefault ? " default" : "");
            md << line;
        }
        md << "\n![" << s.name << ": error against frame time](" << s.name << "_error.png)\n![" << s.name
           << ": temporal error against frame time](" << s.name << "_temporal.png)\n\n";

        for (const bool temporal : {false, true}) {
            io::PlotSpec plot{.title = s.name + (temporal ? ": temporal error against frame time"
                                                           : ": image error against frame time"),
                              .xLabel = "frame time / calibration",
                              .yLabel = temporal ? "temporal error: flicker vs the reference (of 255)" : "mean error (of 255)"};
            // One series per (MSAA, specular AA, shading path), in that order in every scene's plots.
            std::set<std::tuple<uint32_t, bool, passes::ShadingPath>> keys;
            for (const Row& r : s.rows) keys.insert({r.msaa, r.specularAa, r.path});
            const std::vector<std::tuple<uint32_t, bool, passes::ShadingPath>> series(keys.begin(), keys.end());
            for (const auto& [msaa, specularAa, path] : series)
                plot.series.push_back("MSAA " + std::to_string(msaa) + ", specular AA " + (specularAa ? "on" : "off") + ", " +
                                      passes::shadingPathName(path));
            for (const Row& r : s.rows) {
                const auto it = std::find(series.begin(), series.end(), std::tuple{r.msaa, r.specularAa, r.path});
                char label[32];
                std::snprintf(label, sizeof label, "%g px", double(r.lodError));
                if (r.isDefault) plot.highlight = plot.points.size();
                plot.points.push_back({r.frameRatio, temporal ? r.temporalError : r.error.mean, label, uint32_t(it - series.begin())});
            }
            io::writeLogLogPlot(out / (s.name + (temporal ? "_temporal.png" : "_error.png")), plot);
        }
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
    for (const std::string& file : files) io::checkWritable(std::filesystem::path(options.out) / file);

    // Everything the sweep needs is loaded first, so that a bad file fails before minutes of work.
    const scene::Environment sky = scene::makeProceduralSky();
    std::optional<scene::Environment> fileEnvironment;
    if (options.env.kind == EnvironmentChoice::Kind::File) fileEnvironment = loadEnvironment(options.env);
    std::list<scene::Scene> loaded;  // the renderer keeps pointing at the last scene it drew
    for (const std::string& entry : options.scenes) {
        scene::Scene& scene = loaded.emplace_back(entry == "default" ? scene::makeSphereGrid() : scene::loadGltf(entry));
        for (const std::string& warning : scene.warnings) log::warn(entry + ": " + warning);
        for (const std::string& note : scene.notes) log::info(entry + ": " + note);
    }

    vk::Context context(contextDesc(options.common));
    Renderer renderer(context);
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
    std::vector<passes::ShadingPath> paths = {passes::ShadingPath::Forward};
    if (context.choices().visibilityUnsupported.empty()) paths.push_back(passes::ShadingPath::Visibility);
    const size_t perScene = sampleCounts.size() * 2 * options.lodErrors.size() * paths.size();
    // Steps: per scene its reference, then its settings.
    Progress progress("quality-report", options.scenes.size() * (perScene + 1), options.common.quiet);
    size_t done = 0;

    std::vector<SceneResult> results;
    auto scene = loaded.begin();
    for (size_t s = 0; s < options.scenes.size(); ++s, ++scene) {
        const bool builtin = options.scenes[s] == "default";
        const scene::Environment* environment = builtin || !fileEnvironment ? &sky : &*fileEnvironment;
        SceneResult result{.name = scenes[s]};
        RenderSettings base{.width = options.width, .height = options.height, .scene = &*scene, .environment = environment};
        base.ibl.skybox = true;
        base.drawSelection.lodErrorPixels = 0.0f;
        base.msaa = 1;
        renderer.validateSettings(base);
        progress.step(done, result.name + ": reference (" + std::to_string(options.width * kReferenceScale) + "x" +
                                std::to_string(options.height * kReferenceScale) + ", " + std::to_string(options.orbitFrames) +
                                " frames)");
        const auto referenceStart = std::chrono::steady_clock::now();
        const std::vector<std::vector<uint8_t>> reference = orbitFrames(renderer, base, options.orbitFrames, kReferenceScale);
        result.referenceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - referenceStart).count();
        ++done;
        result.referenceTemporal = io::meanFrameToFrameDifference(reference);
        for (uint32_t samples : sampleCounts)
            for (bool specularAa : {false, true})
                for (float lodError : options.lodErrors)
                for (passes::ShadingPath path : paths) {
                    RenderSettings settings = base;
                    settings.shadingPath = path;
                    settings.msaa = samples;
                    settings.shadingOptions.specularAntiAliasing = specularAa;
                    settings.drawSelection.lodErrorPixels = lodError;
                    settings.camera.orbit = glm::vec3(0.0f, 90.0f, 0.0f);
                    const FrameMeasurement m = measureFrames(renderer, settings, options.frames);
                    const std::vector<std::vector<uint8_t>> frames = orbitFrames(renderer, settings, options.orbitFrames, 1);
                    Row row{.scene = result.name, .msaa = samples, .specularAa = specularAa, .lodError = lodError, .path = path,
                            .frameRatio = median(m.frameMs) / median(m.calibrationMs), .frameMs = median(m.frameMs),
                            .error = io::displayError(frames, reference), .temporal = io::meanFrameToFrameDifference(frames),
                            .temporalError = io::meanTemporalError(frames, reference),
                            .triangles = m.drawStats.submittedTriangles};
                    row.isDefault = samples == defaultMsaa.samples && specularAa == passes::ShadingOptions{}.specularAntiAliasing &&
                                    lodError == passes::DrawSelection::kDefaultLodErrorPixels &&
                                    path == defaultShadingPath(context).first;
                    result.rows.push_back(row);
                    char detail[200];
                    std::snprintf(detail, sizeof detail, "%s %s: %.2fx calibration, error %.3f (p99 %.0f), temporal error %.3f",
                                  result.name.c_str(), settingName(row).c_str(), row.frameRatio, row.error.mean, row.error.p99,
                                  row.temporalError);
                    progress.step(++done, detail);
                }
        std::vector<io::PlotPoint> points;
        for (const Row& r : result.rows) points.push_back({r.frameRatio, r.error.mean});
        for (size_t i : io::paretoFront(points)) result.rows[i].pareto = true;
        std::sort(result.rows.begin(), result.rows.end(), [](const Row& a, const Row& b) { return a.frameRatio < b.frameRatio; });
        results.push_back(std::move(result));
    }
    progress.finish();
    writeReport(options.out, results, options, context.report().name, defaultMsaa, notes);
    std::printf("wrote %s/report.csv, report.md and 2 plots per scene\n", options.out.c_str());
    if (context.validationMessageCount() > 0) {
        log::error(std::to_string(context.validationMessageCount()) + " validation messages");
        return 3;
    }
    return 0;
}

}  // namespace candela::app
