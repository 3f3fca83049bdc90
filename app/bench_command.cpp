// `candela bench`: frame time and per-pass GPU time of a scene, each also as a ratio to the
// calibration pass (passes/diagnostics/calibration_pass.h) run in the same process, because
// absolute times on a shared CPU vary by up to 2× between runs. Frames and calibration runs are
// interleaved so that drift affects both alike. Then each pass's wall time submitted alone
// (serialized), which on CPU devices is the only per-pass cost to trust: their timestamps miss
// deferred work, and the output says so (graph::kUnreliableGpuTimes).

#include "commands.h"
#include "frame_measurement.h"
#include "session.h"
#include "stopwatch.h"

#include "graph/graph_export.h"
#include "render/camera_framing.h"
#include "vk/pipeline_cache_file.h"
#include "vk/timestamps.h"

#include "core/errors.h"
#include "core/log.h"
#include "bench_cold.h"
#include "statistics.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>

namespace candela::app {
namespace {

double minimum(const std::vector<double>& values) {
    return values.empty() ? -1.0 : *std::min_element(values.begin(), values.end());
}

// A switch of the debug view after the measured frames: the first frame in the new view (its
// pipelines compiled then, or ahead of it by --precompile debug-views) and the one after it.
struct DebugViewSwitch {
    options::DebugView to = options::DebugView::None;
    double firstMs = 0.0, nextMs = 0.0;  // wall time of each call
};

DebugViewSwitch switchDebugView(Renderer& renderer, const RenderSettings& settings) {
    // Background builds (--precompile debug-views) are done long before a user's first switch:
    // finished here, so that the two modes compare what the switch itself costs.
    renderer.finishPipelineBuilds();
    DebugViewSwitch out;
    for (options::DebugView view : options::allDebugViews())
        if (view != settings.debugView) {
            out.to = view;
            break;
        }
    RenderSettings switched = settings;
    switched.debugView = out.to;
    // The measured frames have checked the --disable-pass names; a debug view need not declare
    // them all (it draws no skybox).
    renderer.setUnknownPassIsError(false);
    for (double* ms : {&out.firstMs, &out.nextMs}) {
        const auto start = Clock::now();
        renderer.renderFrame(switched);
        *ms = msSince(start);
    }
    renderer.setUnknownPassIsError(true);
    return out;
}

// The --explain line saying which shading path the frame took ("shading path: ...").
std::string shadingPathLine(const std::vector<std::string>& explain) {
    for (const std::string& line : explain)
        if (line.starts_with("shading path: ")) return line.substr(14);
    return "forward";
}

// Each shading path measured on its own (as the main measurement: frames interleaved with
// calibration runs, as ratios to them), when the path was not chosen on the command line.
struct PathMeasurement {
    options::ShadingPath path;
    FrameMeasurement m;
};

// Frames run with serialized passes after the measured ones, for the per-pass wall times.
constexpr uint32_t kSerialFrames = 5;

// Per pass: the median GPU time (timestamps) and the median wall time of the pass run alone
// (serialized) with its quartiles, each also as a ratio to the calibration's.
nlohmann::ordered_json passesJson(const FrameMeasurement& m) {
    const double calibration = median(m.calibrationMs), calibrationGpu = median(m.calibrationGpuMs);
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    for (const std::string& name : m.passOrder) {
        const auto times = m.passGpuMs.find(name);
        const double gpu = times == m.passGpuMs.end() ? -1.0 : median(times->second);
        const auto serialTimes = m.passSerialMs.find(name);
        const Spread serial = serialTimes == m.passSerialMs.end() ? Spread{} : spreadOf(serialTimes->second);
        passes.push_back({{"name", name},
                          {"gpuMedianMs", gpu},
                          {"ratioToCalibrationGpu", gpu >= 0.0 && calibrationGpu > 0.0 ? gpu / calibrationGpu : -1.0},
                          {"serialMedianMs", serial.median},
                          {"serialP25Ms", serial.low},
                          {"serialP75Ms", serial.high},
                          {"serialRatio", serial.median >= 0.0 ? serial.median / calibration : -1.0}});
    }
    return passes;
}

// `mark`: "*" after GPU times that are unreliable (the note is printed once, by the caller).
void printPasses(const nlohmann::ordered_json& passes, const char* indent, const char* mark) {
    for (const auto& p : passes)
        std::printf("%spass %-20s GPU median %6.2f ms%s (%.2fx calibration GPU); alone %6.2f ms (interquartile %.2f–%.2f; %.2fx calibration)\n",
                    indent, p["name"].get<std::string>().c_str(), p["gpuMedianMs"].get<double>(), mark,
                    p["ratioToCalibrationGpu"].get<double>(), p["serialMedianMs"].get<double>(),
                    p["serialP25Ms"].get<double>(), p["serialP75Ms"].get<double>(), p["serialRatio"].get<double>());
}

// What bench measured of the scene, besides the scene itself and its settings.
struct BenchResult {
    double loadMs = 0.0;     // reading and decoding the file
    double startupMs = 0.0;  // the device, the pipeline cache file, the renderer
    FrameMeasurement m;
    DebugViewSwitch viewSwitch;
    std::vector<PathMeasurement> paths;  // each shading path, when --shading-path is auto
    std::vector<double> animationMs;     // evaluating the pose, per frame
    std::optional<InFlightMeasurement> inFlight;
};

// The frame time from each frame's start to the next (Renderer::renderToTarget), as the viewer
// runs frames, as "inFlight" of the JSON.
nlohmann::ordered_json inFlightJson(const InFlightMeasurement& inFlight, double calibration, uint32_t frames) {
    const vk::FrameRingStats& ring = inFlight.ring;
    return {{"medianMs", median(inFlight.frameMs)},
            {"medianRatio", median(inFlight.frameMs) / calibration},
            {"wallMsPerFrame", inFlight.wallMsPerFrame},
            {"wallRatio", inFlight.wallMsPerFrame / calibration},
            {"submits", ring.submits},
            {"overlappedSubmits", ring.overlappedSubmits},
            {"blockingWaits", ring.blockingWaits},
            {"blockedMsPerFrame", ring.blockedMs / frames},
            {"completionWaits", inFlight.completionWaits}};
}

// The measurement as JSON (--json; the text reads some of its figures from it), but "inFlight".
nlohmann::ordered_json benchJson(const BenchOptions& options, const scene::Scene& scene, const pose::ScenePose& pose,
                                 const RenderSettings& settings, Session& session, const BenchResult& b) {
    const FrameMeasurement& m = b.m;
    const vk::Context& context = session.context();
    Renderer& renderer = session.renderer();
    const double loadMs = b.loadMs, startupMs = b.startupMs;
    const DebugViewSwitch& viewSwitch = b.viewSwitch;
    const std::vector<PathMeasurement>& paths = b.paths;
    const std::vector<double>& animationMs = b.animationMs;
    const std::vector<double>&frameMs = m.frameMs, &calibrationMs = m.calibrationMs, &calibrationGpuMs = m.calibrationGpuMs;
    const passes::DrawStats& drawStats = m.drawStats;
    const double calibration = median(calibrationMs), calibrationGpu = median(calibrationGpuMs);
    nlohmann::ordered_json out;
    out["scene"] = scene.source;
    out["device"] = context.report().name;
    out["width"] = settings.width;
    out["height"] = settings.height;
    out["frames"] = options.frames;
    out["sceneLoadMs"] = loadMs;  // reading and decoding the file, CPU
    out["geometryDecompressionMs"] = scene.report.decompression.milliseconds;  // part of it: Draco and meshopt
    const scene::SceneLoadReport::TextureDecoding& textures = scene.report.textureDecoding;
    out["textures"] = {{"decodeMs", textures.milliseconds},  // part of it: PNG, JPEG, WebP, KTX2 to RGBA8
                       {"formats", textures.formats},
                       {"encodedBytes", textures.encodedBytes},
                       {"decodedBytes", textures.decodedBytes},
                       {"deviceBytes", renderer.sceneTextureBytes()}};
    const Spread calibrationSpread = spreadOf(calibrationMs), frameSpread = spreadOf(frameMs);
    out["calibration"] = {{"medianMs", calibration},
                          {"minMs", minimum(calibrationMs)},
                          {"p25Ms", calibrationSpread.low},
                          {"p75Ms", calibrationSpread.high},
                          {"gpuMedianMs", calibrationGpu}};
    out["frame"] = {{"medianMs", median(frameMs)},
                    {"cpuMedianMs", median(m.cpuMs)},
                    {"minMs", minimum(frameMs)},
                    {"p25Ms", frameSpread.low},
                    {"p75Ms", frameSpread.high},
                    {"medianRatio", median(frameMs) / calibration},
                    {"minRatio", minimum(frameMs) / minimum(calibrationMs)}};
    const nlohmann::ordered_json passes = passesJson(m);
    out["passes"] = passes;
    const bool gpuUnreliable = !vk::timestampsMeasurePasses(context.caps().driver);
    if (gpuUnreliable) out["gpuMsUnreliable"] = graph::kUnreliableGpuTimes;
        out["shadingPath"] = shadingPathLine(m.explain);
    nlohmann::ordered_json pathsOut = nlohmann::ordered_json::array();
    for (const PathMeasurement& p : paths) {
        const double pathCalibration = median(p.m.calibrationMs);
        pathsOut.push_back({{"path", options::shadingPathName(p.path)},
                            {"took", shadingPathLine(p.m.explain)},
                            {"medianMs", median(p.m.frameMs)},
                            {"medianRatio", median(p.m.frameMs) / pathCalibration},
                            {"minRatio", minimum(p.m.frameMs) / minimum(p.m.calibrationMs)},
                            {"passes", passesJson(p.m)}});
    }
    if (!paths.empty()) out["shadingPaths"] = pathsOut;
    out["startupMs"] = startupMs;
    out["firstFrame"] = {{"ms", m.firstFrameMs}, {"ratio", m.firstFrameMs / calibration}};
    out["debugViewSwitch"] = {{"to", options::debugViewName(viewSwitch.to)},
                              {"firstMs", viewSwitch.firstMs},
                              {"firstRatio", viewSwitch.firstMs / calibration},
                              {"nextMs", viewSwitch.nextMs},
                              {"nextRatio", viewSwitch.nextMs / calibration}};
    out["pipelines"] = {{"precompile", options::precompileName(settings.precompile)},
                        {"cache", context.pipelineCacheFile().status()}};
    const vk::MsaaChoice msaa = renderer.msaa(settings.msaa);
    out["msaa"] = {{"samples", msaa.samples}, {"reason", msaa.reason}};
    out["draws"] = {{"scene", drawStats.sceneDraws},
                    {"submitted", drawStats.submittedDraws},
                    {"culled", drawStats.culledDraws},
                    {"coarserLevel", drawStats.coarserDraws},
                    {"sceneTriangles", drawStats.sceneTriangles},
                    {"submittedTriangles", drawStats.submittedTriangles},
                    {"stateChanges", drawStats.stateChanges()},
                    {"pipelineBinds", drawStats.pipelineBinds},
                    {"descriptorBinds", drawStats.descriptorBinds}};
    out["geometry"] = {{"meshes", scene.report.geometry.meshes},
                       {"simplifiedMeshes", scene.report.geometry.simplifiedMeshes},
                       {"indexBytes", scene.report.geometry.indexBytes},
                       {"lodIndexBytes", scene.report.geometry.lodIndexBytes},
                       {"prepareMs", scene.report.geometry.milliseconds}};
    if (pose.animated())
        out["animation"] = {{"playing", pose.playing().size()}, {"evaluateMedianMs", median(animationMs)},
                            {"evaluateMaxMs", *std::max_element(animationMs.begin(), animationMs.end())}};
    if (options.explain) out["explain"] = m.explain;
    return out;
}

// The measurement as text.
void printBench(const BenchOptions& options, const scene::Scene& scene, const pose::ScenePose& pose,
                const RenderSettings& settings, Session& session, const BenchResult& b, const nlohmann::ordered_json& out) {
    const FrameMeasurement& m = b.m;
    const vk::Context& context = session.context();
    Renderer& renderer = session.renderer();
    const double loadMs = b.loadMs, startupMs = b.startupMs;
    const DebugViewSwitch& viewSwitch = b.viewSwitch;
    const std::vector<double>&frameMs = m.frameMs, &calibrationMs = m.calibrationMs;
    const passes::DrawStats& drawStats = m.drawStats;
    const double calibration = median(calibrationMs), calibrationGpu = median(m.calibrationGpuMs);
    const Spread calibrationSpread = spreadOf(calibrationMs), frameSpread = spreadOf(frameMs);
    const scene::SceneLoadReport::TextureDecoding& textures = scene.report.textureDecoding;
    const vk::MsaaChoice msaa = renderer.msaa(settings.msaa);
    const bool gpuUnreliable = out.contains("gpuMsUnreliable");
    const char* mark = gpuUnreliable ? "*" : "";
    const nlohmann::ordered_json& passes = out["passes"];
    const nlohmann::ordered_json pathsOut = out.contains("shadingPaths") ? out["shadingPaths"] : nlohmann::ordered_json::array();
    const std::optional<InFlightMeasurement>& inFlight = b.inFlight;
    std::printf("%s at %ux%u on %s, %u frames (CPU wall time around submit+wait)\n", scene.source.c_str(),
                settings.width, settings.height, context.report().name.c_str(), options.frames);
    std::printf("  scene load:  %.2f ms (reading and decoding the file)\n", loadMs);
    std::printf("  msaa:        %s\n", msaa.reason.c_str());
    if (!textures.formats.empty()) {
        std::string formats;
        for (const auto& [format, count] : textures.formats) formats += (formats.empty() ? "" : ", ") + std::to_string(count) + " " + format;
        std::printf("  textures:    %s decoded in %.1f ms (%s in files, %s of RGBA8); %s on the device\n", formats.c_str(),
                    textures.milliseconds, formatBytes(textures.encodedBytes).c_str(), formatBytes(textures.decodedBytes).c_str(),
                    formatBytes(renderer.sceneTextureBytes()).c_str());
    }
    if (const auto& d = scene.report.decompression; d.dracoPrimitives + d.meshoptViews > 0)
        std::printf("  geometry decompression: %.2f ms (%zu Draco primitives, %zu meshopt bufferViews)\n",
                    d.milliseconds, d.dracoPrimitives, d.meshoptViews);
    const auto& g = scene.report.geometry;
    std::printf("  geometry:    %zu meshes, %zu with levels of detail: +%.1f%% index memory (%s full, %s levels), "
                "prepared in %.1f ms\n",
                g.meshes, g.simplifiedMeshes, g.indexBytes ? 100.0 * double(g.lodIndexBytes) / double(g.indexBytes) : 0.0,
                formatBytes(g.indexBytes).c_str(), formatBytes(g.lodIndexBytes).c_str(), g.milliseconds);
    std::printf("  draws:       %u of %u submitted (%u culled, %u at a coarser level), %llu of %llu triangles, "
                "%u state changes (%u pipeline, %u descriptor-set binds)\n",
                drawStats.submittedDraws, drawStats.sceneDraws, drawStats.culledDraws, drawStats.coarserDraws,
                (unsigned long long)drawStats.submittedTriangles, (unsigned long long)drawStats.sceneTriangles,
                drawStats.stateChanges(), drawStats.pipelineBinds, drawStats.descriptorBinds);
    std::printf("  calibration: median %.2f ms (interquartile %.2f–%.2f), min %.2f ms (GPU %.2f ms)\n", calibration,
                calibrationSpread.low, calibrationSpread.high, minimum(calibrationMs), calibrationGpu);
    std::printf("  frame:       median %.2f ms (interquartile %.2f–%.2f; %.2fx calibration), min %.2f ms (%.2fx); CPU "
                "building and recording %.2f ms\n",
                median(frameMs), frameSpread.low, frameSpread.high, median(frameMs) / calibration, minimum(frameMs),
                minimum(frameMs) / minimum(calibrationMs), median(m.cpuMs));
    std::printf("  first frame: %.1f ms (%.1fx calibration) after a start-up of %.1f ms; pipelines: --precompile %s, "
                "cache %s\n",
                m.firstFrameMs, m.firstFrameMs / calibration, startupMs, options::precompileName(settings.precompile),
                context.pipelineCacheFile().status().c_str());
    std::printf("  debug-view switch to %s: first frame %.1f ms (%.1fx calibration), next %.1f ms (%.1fx)\n",
                options::debugViewName(viewSwitch.to), viewSwitch.firstMs, viewSwitch.firstMs / calibration,
                viewSwitch.nextMs, viewSwitch.nextMs / calibration);
    if (pose.animated())
        std::printf("  animation:   %zu playing, CPU evaluation median %.4f ms, max %.4f ms per frame\n",
                    pose.playing().size(), out["animation"]["evaluateMedianMs"].get<double>(),
                    out["animation"]["evaluateMaxMs"].get<double>());
    std::printf("  shading:     %s\n", out["shadingPath"].get<std::string>().c_str());
    if (gpuUnreliable) std::printf("  * %s\n", graph::kUnreliableGpuTimes);
    printPasses(passes, "  ", mark);
    for (const auto& p : pathsOut) {
        std::printf("  path %-10s frame median %.2f ms (%.2fx calibration of its own run), min %.2fx: %s\n",
                    p["path"].get<std::string>().c_str(), p["medianMs"].get<double>(), p["medianRatio"].get<double>(),
                    p["minRatio"].get<double>(), p["took"].get<std::string>().substr(0, 60).c_str());
        printPasses(p["passes"], "    ", mark);
    }
    if (inFlight) {
        const vk::FrameRingStats& ring = inFlight->ring;
        std::printf("  in flight:   median frame %.2f ms (%.2fx calibration), %.2f ms per frame to the last one's end "
                    "(%.2fx), rendered offscreen as the viewer does; %llu of %llu submitted while an earlier frame still "
                    "ran, CPU blocked on fences %.2f ms per frame, %llu waits for the frame just submitted\n",
                    median(inFlight->frameMs), median(inFlight->frameMs) / calibration, inFlight->wallMsPerFrame,
                    inFlight->wallMsPerFrame / calibration, (unsigned long long)ring.overlappedSubmits,
                    (unsigned long long)ring.submits, ring.blockedMs / options.frames,
                    (unsigned long long)inFlight->completionWaits);
    }
    if (options.explain)
        for (const std::string& line : m.explain) std::printf("%s\n", line.c_str());
}

}  // namespace

int runBench(const BenchOptions& options, const std::vector<std::string>& arguments) {
    if (options.cold > 0) return runColdBench(options, arguments);
    const auto loadStart = Clock::now();
    const scene::Scene scene = loadScene(options);
    BenchResult b;
    b.loadMs = msSince(loadStart);
    Session session(options.common, options.env);
    RenderSettings settings = renderSettings(options, scene, session.environment());
    settings.tonemap.dither = options.dither;
    settings.outputs = options.outputs;
    // Frame i shows the animations at --time + i/60 s: each frame pays for evaluating its pose.
    pose::ScenePose pose = loadPose(options, scene);
    warnAnimationConflicts(options, scene);
    settings.pose = &pose;
    {
        // Framed once over the frames' poses, as render frames a sequence: the camera holds still.
        std::vector<double> times;
        for (uint32_t i = 0; i < std::max(options.frames, 1u); ++i) times.push_back(options.time + i / 60.0);
        settings.camera = resolveFraming(scene, settings.camera, float(settings.width) / float(settings.height), &pose, times);
    }
    log::info("camera: " + Renderer::cameraFlags(scene, settings.camera, float(settings.width) / float(settings.height), &pose));
    const auto advance = [&](uint32_t frame) {
        const auto start = Clock::now();
        pose.evaluate(options.time + frame / 60.0);
        b.animationMs.push_back(msSince(start));
    };
    const auto startup = Clock::now();
    session.start();
    b.startupMs = msSince(startup);
    Renderer& renderer = session.renderer();
    const uint32_t serialFrames = std::min(options.frames, kSerialFrames);
    b.m = measureFrames(renderer, settings, options.frames, advance, serialFrames);
    b.viewSwitch = switchDebugView(renderer, settings);
    if (settings.shadingPath == options::ShadingPath::Auto)
        for (const options::ShadingPath path : {options::ShadingPath::Forward, options::ShadingPath::Visibility}) {
            RenderSettings s = settings;
            s.shadingPath = path;
            b.paths.push_back({path, measureFrames(renderer, s, options.frames, advance, serialFrames)});
        }
    nlohmann::ordered_json out = benchJson(options, scene, pose, settings, session, b);
    if (options.inFlight) {
        b.inFlight = measureFramesInFlight(renderer, session.context(), settings, options.frames);
        out["inFlight"] = inFlightJson(*b.inFlight, median(b.m.calibrationMs), options.frames);
    }
    if (options.json)
        std::printf("%s\n", out.dump(2).c_str());
    else
        printBench(options, scene, pose, settings, session, b, out);
    return session.exitCode(0);
}

}  // namespace candela::app
