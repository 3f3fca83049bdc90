// `candela scale-report`: how the frame's cost grows with the scene. The built-in sphere grid at
// N × N spheres (framed alike: the same screen area, each sphere smaller as N grows) under the
// procedural sky, with levels of detail on and off, on both shading paths (docs/shading-paths.md;
// the forward one alone where the device lacks the visibility path): frame time (and its ratio to
// the calibration pass of the same run), CPU time to build and record the frame, draws and
// triangles submitted.
// Writes report.csv, report.md and frame_vs_triangles.png (log-log). See docs/geometry.md.

#include "commands.h"
#include "session.h"
#include "frame_measurement.h"
#include "statistics.h"

#include "assets/builtin_scenes.h"
#include "assets/procedural_sky.h"
#include "core/errors.h"
#include "core/progress.h"
#include "graph/graph_export.h"
#include "reports/plot.h"
#include "vk/timestamps.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <list>

namespace candela::app {
namespace {

struct ScaleRow {
    uint32_t side = 0;
    float lodErrorPixels = 0.0f;
    options::ShadingPath path = options::ShadingPath::Forward;
    passes::DrawStats draws;
    double frameMs = 0.0, calibrationMs = 0.0, cpuMs = 0.0, forwardGpuMs = -1.0;
    double ratio() const { return frameMs / calibrationMs; }
};

// `gpuUnreliable`: the device's timestamps miss deferred work (graph::GraphTimings::gpuMsUnreliable).
void writeReport(const std::filesystem::path& out, const std::vector<ScaleRow>& rows, const ScaleReportOptions& options,
                 const std::string& device, bool gpuUnreliable) {
    TextFile csv(out / "report.csv");
    csv << "side,lod_error_px,scene_draws,submitted_draws,culled_draws,scene_triangles,submitted_triangles,frame_ms,"
           "calibration_ms,frame_ratio,cpu_ms,forward_gpu_ms,shading_path\n";
    for (const ScaleRow& r : rows)
        csv << r.side << "," << r.lodErrorPixels << "," << r.draws.sceneDraws << "," << r.draws.submittedDraws << ","
            << r.draws.culledDraws << "," << r.draws.sceneTriangles << "," << r.draws.submittedTriangles << "," << r.frameMs
            << "," << r.calibrationMs << "," << r.ratio() << "," << r.cpuMs << "," << r.forwardGpuMs << ","
            << options::shadingPathName(r.path) << "\n";
    csv.commit();
    TextFile md(out / "report.md");
    md << "# Scale report\n\nThe built-in sphere grid at N × N spheres, framed alike, under the procedural sky, "
       << options.width << "×" << options.height << " on " << device << ", median of " << options.frames
       << " frames; frame time as a ratio to the calibration pass of the same run."
       << (gpuUnreliable ? std::string(" report.csv's forward_gpu_ms: ") + graph::kUnreliableGpuTimes + "." : std::string())
       << "\n\n"
       << "| N | draws | levels of detail | shading path | triangles in the scene | submitted | frame / calibration | CPU build + record (ms) |\n"
       << "|---|---|---|---|---|---|---|---|\n";
    for (const ScaleRow& r : rows) {
        char line[256];
        std::snprintf(line, sizeof line, "| %u | %u | %s | %s | %llu | %llu | %.2f× | %.2f |\n", r.side, r.draws.sceneDraws,
                      r.lodErrorPixels > 0.0f ? "on" : "off", options::shadingPathName(r.path), (unsigned long long)r.draws.sceneTriangles,
                      (unsigned long long)r.draws.submittedTriangles, r.ratio(), r.cpuMs);
        md << line;
    }
    md.commit();
    reports::PlotSpec plot{.title = "Frame time against scene triangles (N x N sphere grid)",
                      .xLabel = "triangles in the scene",
                      .yLabel = "frame time / calibration",
                      .series = {"levels of detail on, forward", "levels of detail off, forward", "levels of detail on, visibility",
                                 "levels of detail off, visibility"},
                      .paretoLine = false};
    for (const ScaleRow& r : rows)
        plot.points.push_back({double(r.draws.sceneTriangles), r.ratio(), "N=" + std::to_string(r.side),
                               (r.lodErrorPixels > 0.0f ? 0u : 1u) + (r.path == options::ShadingPath::Visibility ? 2u : 0u)});
    reports::writeLogLogPlot(out / "frame_vs_triangles.png", plot);
}

}  // namespace

int runScaleReport(const ScaleReportOptions& options) {
    prepareReportFolder(options.out, {"report.csv", "report.md", "frame_vs_triangles.png"});
    Session session(options.common, EnvironmentChoice{});  // the procedural sky
    const assets::Environment& sky = *session.environment();
    session.start();
    vk::Context& context = session.context();
    Renderer& renderer = session.renderer();
    // The renderer keeps pointing at the last scene it drew: every scene lives until the end.
    std::list<scene::Scene> scenes;
    std::vector<ScaleRow> rows;
    std::vector<options::ShadingPath> paths = {options::ShadingPath::Forward};
    if (context.choices().visibilityUnsupported.empty()) paths.push_back(options::ShadingPath::Visibility);
    Progress progress("scale-report", options.sizes.size() * 2 * paths.size(), options.common.quiet);
    for (uint32_t side : options.sizes) {
        const scene::Scene& grid = scenes.emplace_back(assets::makeSphereGrid(side));
        for (const float lodError : {options.lodErrorPixels, 0.0f})
        for (const options::ShadingPath path : paths) {
            RenderSettings settings{.width = options.width, .height = options.height, .scene = &grid, .environment = &sky};
            settings.drawSelection.lodErrorPixels = lodError;
            settings.shadingPath = path;
            renderer.validateSettings(settings);
            const FrameMeasurement m = measureFrames(renderer, settings, options.frames);
            ScaleRow row{.side = side, .lodErrorPixels = lodError, .path = path, .draws = m.drawStats, .frameMs = median(m.frameMs),
                    .calibrationMs = median(m.calibrationMs), .cpuMs = median(m.cpuMs)};
            if (auto forward = m.passGpuMs.find("forward"); forward != m.passGpuMs.end()) row.forwardGpuMs = median(forward->second);
            rows.push_back(row);
            char detail[200];
            std::snprintf(detail, sizeof detail, "N=%u, levels of detail %s, %s: %.2fx calibration, %llu of %llu triangles", side,
                          lodError > 0.0f ? "on" : "off", options::shadingPathName(path), row.ratio(), (unsigned long long)row.draws.submittedTriangles,
                          (unsigned long long)row.draws.sceneTriangles);
            progress.step(rows.size(), detail);
        }
    }
    progress.finish();
    writeReport(options.out, rows, options, context.report().name,
                !vk::timestampsMeasurePasses(context.caps().driver));
    std::printf("wrote %s/report.csv, report.md, frame_vs_triangles.png\n", options.out.c_str());
    return 0;
}

}  // namespace candela::app
