// `candela render`: one scene, or many in one run (scene_batch.h) on one device with one
// environment precompute. The next scene is read on a second thread while the current one
// renders; each scene's device memory is freed before the next is uploaded.

#include "commands.h"
#include "api/access.h"
#include "api/cameras.h"
#include "candela/dataset.h"
#include "candela/device.h"
#include "failures.h"
#include "image_writer.h"
#include "render_outputs.h"
#include "render_page.h"
#include "render_report.h"
#include "scene_batch.h"
#include "session.h"
#include "stopwatch.h"
#include "assets/image_file.h"
#include "core/log.h"
#include "core/process_memory.h"
#include "core/progress.h"
#include "graph/graph_export.h"
#include "scene/material_variants.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/timestamps.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <future>
#include <map>

#include <nlohmann/json.hpp>

namespace candela::app {
namespace {

namespace fs = std::filesystem;

// Creates the folder `file` goes in.
void createFolderOf(const std::filesystem::path& file) {
    std::error_code ec;
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
    if (ec) throw UserError(file.string() + ": cannot write: cannot create the folder " + file.parent_path().string() + ": " + ec.message());
}

// A scene read on the loading thread, or why it could not be.
struct LoadedScene {
    std::optional<scene::Scene> scene;
    std::exception_ptr error;
    double ms = 0.0;
};

LoadedScene load(const SceneInput& input, const RenderOptions& options) {
    LoadedScene out;
    const auto start = Clock::now();
    try {
        out.scene = readScene(options, input.file.string(), true);  // the API builds the levels of detail if they pay
    } catch (...) {
        out.error = std::current_exception();
    }
    out.ms = msSince(start);
    return out;
}

// What stays the same over a run: the options, the device, the environment, the output format.
struct Run {
    const RenderOptions& options;
    Session& session;
    assets::ImageFileFormat format;
    bool batch;     // several scenes: shorter lines, one precompute for all (sheen included)
    bool sequence;  // --frames N > 1 or --views N
    bool anyFrame = false;
    bool gpuNoteShown = false;  // graph::kUnreliableGpuTimes, said once after the first marked line
    // A single scene's failure, rethrown after the report is written.
    std::exception_ptr singleFailure;
    // Encodes and writes each image while the next one is drawn (finished before the report).
    ImageWriter writer;
    // The report of the scene being drawn (null between scenes): an image of it that fails to be
    // written stops it.
    const SceneReport* rendering = nullptr;
    // The pipelines created before the first scene's environment maps were prepared ahead of it:
    // those the maps created count with that scene (unset: from the scene's start).
    std::optional<vk::Context::PipelineCreation> firstScenePipelinesFrom;
};

// printf into a std::string.
template <typename... Args>
std::string printed(const char* pattern, Args... args) {
    std::string out(size_t(std::snprintf(nullptr, 0, pattern, args...)), '\0');
    std::snprintf(out.data(), out.size() + 1, pattern, args...);
    return out;
}

// The lines printed once an image is written (with the footnote on lavapipe's GPU times after the
// first that needs it), made while its frame's figures are at hand.
std::string writtenLines(Run& run, const std::string& out, const CapturedFrame& frame, double time, const SceneReport& r) {
    std::string text = printed("wrote %s (%ux%u", out.c_str(), frame.width, frame.height);
    if (run.sequence) text += printed(", t = %.4f s", time);
    if (run.batch) return text + printed("): load %.1f ms, upload %.1f ms, frame %.1f ms\n", r.loadMs, r.uploadMs, r.frameMs.back());
    text += printed("): submit+wait %.2f ms, readback %.2f ms", frame.submitWaitMs, frame.readbackMs);
    const graph::GraphDecl& decl = run.session.renderer().lastGraph().declaration();
    const char* mark = frame.timings.gpuMsUnreliable ? "*" : "";
    bool marked = false;
    for (uint32_t pass : run.session.renderer().lastGraph().compiled().order)
        if (frame.timings.gpuMs.size() > pass && frame.timings.gpuMs[pass] >= 0.0) {
            text += printed("; %s %.2f ms GPU%s", decl.passes[pass].name.c_str(), frame.timings.gpuMs[pass], mark);
            marked = *mark != '\0';
        }
    text += "\n";
    if (marked && !run.gpuNoteShown) {
        text += printed("* %s\n", graph::kUnreliableGpuTimes);
        run.gpuNoteShown = true;
    }
    return text;
}

// Records `error` as scene `r`'s failure (and a single scene's, to be rethrown after the report);
// a batch logs it and goes on.
void failScene(Run& run, SceneReport& r, const std::exception_ptr& error, Progress& progress) {
    if (!run.batch) run.singleFailure = error;
    const Failure failure = describeFailure(error);
    r.ok = false;
    r.error = failure.message;
    r.exitCode = failure.exitCode;
    // Loader messages name their file already; the renderer's do not.
    if (!r.input.file.empty() && r.error.rfind(r.input.file.string(), 0) != 0) r.error = r.input.file.string() + ": " + r.error;
    progress.clear();
    if (run.batch) log::error(r.error);
}

// What an output shows, in the report and the page: "render", the variant, "frame 3", "blue, frame 3".
std::string outputLabel(const std::string& variant, std::optional<uint32_t> frame) {
    std::string label = variant;
    if (frame) label += (label.empty() ? "" : ", ") + ("frame " + std::to_string(*frame));
    return label.empty() ? "render" : label;
}

// Records in `r` the outputs of a scene (or variant) that --resume left as they were.
void recordResumed(SceneReport& r, const RenderOptions& options, const std::string& variant) {
    const std::vector<std::string> outputs = outputsOf(options, r.input, variantNameOf(variant));
    for (size_t i = 0; i < outputs.size(); ++i)
        for (const std::string& file : filesOf(options, outputs[i]))
            r.outputs.push_back({file, outputLabel(variant, options.sequence() ? std::optional(uint32_t(i)) : std::nullopt)});
}

// The API's sequence of `options`: frames, a turntable, or views; jittered lighting.
candela::SequenceOptions sequenceOptions(const RenderOptions& options) {
    candela::SequenceOptions sequence{.frames = std::max(options.frames, 1u), .fps = options.fps > 0.0 ? options.fps : 30.0,
                                      .turntableDegrees = options.turntableDegrees, .lightingSeed = options.lightSeed};
    if (options.views > 0)
        sequence.views = options.viewRing ? candela::ringViews(options.views, *options.viewRing) : candela::sphereViews(options.views);
    return sequence;
}

// Writes the cameras of a sequence's frames to `file` (transformsFileOf), the frames' paths
// relative to its folder.
void writeTransforms(const fs::path& file, std::vector<candela::DatasetFrame> frames) {
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    for (candela::DatasetFrame& frame : frames) frame.file = fs::path(frame.file).lexically_relative(folder).generic_string();
    writeText(file.string(), candela::transformsJson(frames));
}

// The public API's render options for images in files of `format`.
candela::RenderOptions apiOptionsOf(const RenderOptions& options, assets::ImageFileFormat format) {
    candela::RenderOptions api = apiRenderOptions(options);
    api.dither = options.dither;
    api.format = assets::isFloatFormat(format) ? candela::PixelFormat::Rgba32Float : candela::PixelFormat::Rgba8Srgb;
    api.outputs = apiOutputs(options);
    return api;
}

// Renders every image of one scene (each variant asked for, each frame of a sequence) through the
// public API (candela::Device::renderSequence, with the flags the API does not have applied to
// each frame's settings: engine/api/access.h) and fills `r` with what it took. Throws what the
// API or the writers throw.
void renderScene(Run& run, candela::Scene& held, SceneReport& r, Progress& progress) {
    const RenderOptions& options = run.options;
    scene::Scene& scene = Access::impl(held).scene;
    r.extensions = scene.report.extensionsUsed;
    r.imageDecodeMs = scene.report.textureDecoding.milliseconds;
    r.imageDecodeWaitMs = scene.report.textureDecoding.waitMilliseconds;
    r.decompressionMs = scene.report.decompression.milliseconds;
    for (const std::string& warning : scene.report.warnings) log::warn(scene.source + ": " + warning);
    for (const std::string& note : scene.report.notes) log::info(scene.source + ": " + note);
    r.warnings = scene.report.warnings;
    r.notes = scene.report.notes;
    log::Capture capture;  // what the renderer logs from here on belongs to this scene
    const uint32_t precomputesBefore = run.session.renderer().precomputeCount();
    const double lodBefore = scene.report.geometry.lodMilliseconds;
    const vk::Context::PipelineCreation pipelinesBefore = run.firstScenePipelinesFrom.value_or(run.session.context().pipelineCreation());
    run.firstScenePipelinesFrom.reset();
    warnAnimationConflicts(options, scene);  // once per scene, whatever the variants

    std::vector<std::string> variants;  // "": the default materials
    if (options.variant == "all") variants = scene.variants;
    if (variants.empty()) variants.push_back(options.variant == "all" ? "" : options.variant);
    candela::RenderOptions api = apiOptionsOf(options, run.format);
    const float aspect = float(options.width) / float(options.height);
    const candela::SequenceOptions sequence = sequenceOptions(options);
    std::string cameraLine;  // the last camera printed (--verbose)
    double time = 0.0;       // the pose's, of the frame being drawn

    // What the flags ask beyond the API's options, for each frame; --verbose prints the camera.
    const SettingsHook flags = [&](RenderSettings& settings) {
        applyRenderFlags(options, settings);
        // One precompute serves the whole run: with the sheen cube, for scenes with or without a sheen.
        if (run.batch) settings.iblQuality.sheen = true;
        time = settings.pose->time();
        if (log::verbose()) {
            const std::string line = "camera: " + Renderer::cameraFlags(scene, settings.camera, aspect, settings.pose);
            if (line != cameraLine) log::info(cameraLine = line);
        }
    };
    for (const std::string& variant : variants) {
        api.variant = variant;
        const std::string variantName = variantNameOf(variant);
        r.variants.push_back(variant);
        // --variant all: each variant's files are known once the file is read.
        if (options.resume && options.variant == "all" && outputsComplete(options, r.input, variantName, !run.batch)) {
            recordResumed(r, options, variant);
            continue;
        }
        Clock::time_point stageStart = Clock::now();
        const candela::ProgressCallback stages = [&](const candela::RenderProgress& stage) {
            // The upload runs between the first two stages.
            if (stage.stage == candela::RenderProgress::Stage::Frame && stage.frame == 0) r.uploadMs += msSince(stageStart);
            stageStart = Clock::now();
            return true;
        };
        std::vector<candela::DatasetFrame> cameras;  // of a sequence: its transforms.json
        const candela::FrameCallback write = [&](uint32_t i, const candela::Image& image) {
            r.frameMs.push_back(msSince(stageStart));
            const CapturedFrame& frame = Access::impl(run.session.device()).lastFrame;
            run.anyFrame = true;
            double gpu = 0.0;
            for (double ms : frame.timings.gpuMs) gpu += std::max(ms, 0.0);
            r.gpuMs.push_back(gpu);
            r.readbackMs.push_back(frame.readbackMs);
            const std::optional<uint32_t> frameNumber = run.sequence ? std::optional(i) : std::nullopt;
            const std::string out = expandOutPattern(options.out, {r.input.name, r.input.path, variantName, frameNumber});
            createFolderOf(out);
            for (const std::string& file : filesOf(options, out)) r.outputs.push_back({file, outputLabel(variant, frameNumber)});
            if (run.sequence)
                cameras.push_back({.file = out, .camera = image.camera,
                                   .environmentRotationDegrees = frameEnvironmentRotation(api, sequence, i)});
            // Written while the next image is drawn: what became of it is known at the next write
            // (or the run's end). A failed write stops this scene; one of a scene drawn before is
            // recorded as that scene's failure.
            SceneReport* written = &r;
            run.writer.write(out, image, candela::OutputFileFormat(uint32_t(options.outputsFormat)),
                             [&run, &progress, written, lines = writtenLines(run, out, frame, time, r), i](
                                 double encodeMs, std::exception_ptr error) {
                                 if (error && run.rendering == written) std::rethrow_exception(error);
                                 if (error) return failScene(run, *written, error, progress);
                                 written->encodeMs.push_back(encodeMs);
                                 progress.clear();
                                 std::fputs(lines.c_str(), stdout);
                                 std::fflush(stdout);
                                 if (!run.batch) progress.step(i + 1, "frames written");
                             });
        };
        Access::renderSequence(run.session.device(), held, api, sequence, write, run.session.apiEnvironment(), stages, flags);
        if (run.sequence) writeTransforms(transformsFileOf(options, r.input, variantName, !run.batch), cameras);
    }
    r.geometryMs = scene.report.geometry.milliseconds;  // with the levels of detail, if they were built
    r.lodMs = scene.report.geometry.lodMilliseconds - lodBefore;
    r.parseMs = std::max(0.0, r.loadMs - r.imageDecodeWaitMs - r.decompressionMs - (r.geometryMs - r.lodMs));
    const vk::Context::PipelineCreation pipelines = run.session.context().pipelineCreation();
    r.pipelines = pipelines.count - pipelinesBefore.count;
    r.pipelineMs = pipelines.milliseconds - pipelinesBefore.milliseconds;
    const passes::DrawStats& stats = run.session.renderer().drawStats();
    r.triangles = stats.sceneTriangles;
    r.draws = stats.sceneDraws;
    r.work = {.drawsSubmitted = stats.submittedDraws, .culledDraws = stats.culledDraws, .coarserDraws = stats.coarserDraws,
              .trianglesSubmitted = stats.submittedTriangles, .pipelineBinds = stats.pipelineBinds,
              .descriptorBinds = stats.descriptorBinds, .texelsDecoded = scene.report.textureDecoding.decodedBytes / 4,
              .simplifiedMeshes = scene.report.geometry.simplifiedMeshes,
              .iblPrecomputes = run.session.renderer().precomputeCount() - precomputesBefore,
              .pipelinesCreated = r.pipelines};
    const graph::GraphDecl& graph = run.session.renderer().lastGraph().declaration();
    for (uint32_t pass : run.session.renderer().lastGraph().compiled().order) r.work.passes.push_back(graph.passes[pass].name);
    if (const gpu_scene::GpuScene* uploaded = run.session.renderer().uploadedScene())
        for (size_t i = 0; i < scene.images.size(); ++i) {
            const scene::Image& image = scene.images[i];
            r.textures.push_back({image.name, image.format, image.width, image.height, image.encodedBytes, uploaded->imageBytes(i)});
        }
    r.warnings.insert(r.warnings.end(), capture.warnings.begin(), capture.warnings.end());
    r.notes.insert(r.notes.end(), capture.infos.begin(), capture.infos.end());
}

// Checks the --out pattern against the scenes before anything renders: known fields, a valid
// image format, and a different file for every scene. Returns the format.
assets::ImageFileFormat checkOutputs(const RenderOptions& options, const std::vector<SceneInput>& scenes, bool sequence) {
    checkOutPattern(options.out);
    if (!options.out.empty() && options.out.back() == '/')
        throw UserError("--out " + options.out + ": names a folder; give a file in it, e.g. --out " + options.out + "candela.png");
    if (!sequence) {
        bool frameField = usesField(options.out, "frame");
        try {
            sequenceFileName(options.out, 0);
            frameField = true;
        } catch (const UserError&) {
        }
        if (frameField)
            throw UserError("--out " + options.out + ": a frame number field without --frames N or --views N (an image "
                            "sequence); give one, or write %% for a literal %");
    }
    if (options.variant == "all" && !usesField(options.out, "variant"))
        throw UserError("--variant all: --out needs {variant} in its pattern (one image per variant), e.g. --out '{name}-{variant}.png'");
    std::map<std::string, std::string> writer;  // output → the scene that writes it
    std::optional<assets::ImageFileFormat> format;
    for (const SceneInput& s : scenes) {
        const std::string out = expandOutPattern(options.out, {s.name, s.path, "default", sequence ? std::optional(0u) : std::nullopt});
        if (!format) format = assets::imageFileFormat(out);
        if (const auto [it, inserted] = writer.emplace(out, s.file.string()); !inserted)
            throw UserError("--out " + options.out + ": " + it->second + " and " + s.file.string() + " would both write " + out +
                            (usesField(options.out, "name") || usesField(options.out, "path")
                                 ? " (use {path}: it keeps their folders apart)"
                                 : " (give a pattern with {name} or {path}, e.g. --out 'renders/{name}.png')"));
    }
    return format.value_or(assets::ImageFileFormat::Png);
}

// The scenes listed: --scene's file, then the SCENE arguments; neither: the built-in scene.
std::vector<SceneInput> listScenes(const RenderOptions& options) {
    std::vector<SceneInput> listed;
    if (!options.scene.empty()) listed.push_back(fileInput(options.scene));
    if (!options.inputs.empty())
        for (SceneInput& scene : expandSceneInputs(options.inputs)) listed.push_back(std::move(scene));
    if (listed.empty()) listed.push_back({"", "default", "default"});
    return listed;
}

// Checks, before anything loads, that every file the run writes can be written (a single scene's
// image included); returns the image format.
assets::ImageFileFormat prepareOutputs(const RenderOptions& options, const std::vector<SceneInput>& listed,
                                   const std::vector<SceneInput>& scenes, bool sequence) {
    const assets::ImageFileFormat format = checkOutputs(options, scenes, sequence);
    if (listed.size() == 1) {
        const std::string first = expandOutPattern(options.out, {listed[0].name, listed[0].path, "default", sequence ? std::optional(0u) : std::nullopt});
        createFolderOf(first);
        assets::checkWritable(first);
    }
    for (const std::string& path : {options.graphDot, options.graphJson, options.report, options.html})
        if (!path.empty()) {
            createFolderOf(path);
            assets::checkWritable(path);
        }
    return format;
}

// Renders one scene of the run into `r`; a failure is recorded in `r` (and logged in a batch),
// and for a single scene also kept in run.singleFailure to be rethrown after the report is written.
void runScene(Run& run, LoadedScene loaded, SceneReport& r, RunReport& report, Progress& progress) {
    vk::Context& context = run.session.context();
    const uint32_t validationBefore = context.validationMessageCount();
    std::optional<candela::Scene> scene;  // kept until the device has let go of it
    try {
        if (loaded.error) std::rethrow_exception(loaded.error);
        scene.emplace(Access::scene(std::move(*loaded.scene)));
        run.rendering = &r;
        renderScene(run, *scene, r, progress);
        r.ok = true;
    } catch (...) {
        failScene(run, r, std::current_exception(), progress);
    }
    run.rendering = nullptr;
    r.validationMessages = context.validationMessageCount() - validationBefore;
    r.hostBytes = residentBytes();
    const vk::MemoryStats device = context.allocator().stats();
    r.deviceBytes = device.allocatedBytes;
    report.peakHostBytes = std::max(report.peakHostBytes, r.hostBytes);
    report.peakDeviceBytes = std::max(report.peakDeviceBytes, r.deviceBytes);
    report.peakDeviceMemoryBytes = std::max(report.peakDeviceMemoryBytes, device.deviceMemoryBytes);
    if (report.precomputeMs < 0.0) report.precomputeMs = run.session.renderer().lastPrecompute().frameMs;
    if (run.batch) {
        // Nothing of this scene stays, on the device or on the host.
        run.session.device().release();
        scene.reset();
        returnFreedHeapMemory();
        r.retainedHostBytes = residentBytes();
        r.retainedDeviceBytes = context.allocator().stats().allocatedBytes;
    }
}

// After the last scene: the report and page, --explain, the graph exports of the last frame and
// the summary lines; returns the exit code (rethrows a single scene's failure).
int finishRun(Run& run, const RunReport& report) {
    const RenderOptions& options = run.options;
    if (log::verbose()) {
        for (const SceneReport& scene : report.scenes)
            if (scene.ok && !scene.resumed) log::info(sceneTimeLine(scene));
        log::info(runTimeLine(report));
    }
    if (!options.report.empty()) writeText(options.report, reportJson(report));
    if (!options.html.empty()) reports::writeHtmlPage(options.html, renderPage(report, options.html), options.inlineImages);
    if (run.singleFailure) std::rethrow_exception(run.singleFailure);

    Renderer& renderer = run.session.renderer();
    if (options.explain && run.anyFrame)
        for (const std::string& line : renderer.explain()) std::printf("%s\n", line.c_str());
    if (run.anyFrame) {
        // The graph exports describe the last frame.
        const graph::RenderGraph& graph = renderer.lastGraph();
        const CapturedFrame& lastFrame = Access::impl(run.session.device()).lastFrame;
        if (!options.graphDot.empty())
            writeText(options.graphDot, graph::exportDot(graph.declaration(), graph.compiled(), &lastFrame.timings));
        if (!options.graphJson.empty())
            writeText(options.graphJson, graph::exportJson(graph.declaration(), graph.compiled(), &lastFrame.timings));
    }
    const size_t scenes = report.scenes.size();
    if (run.batch) {
        const size_t resumed = size_t(std::count_if(report.scenes.begin(), report.scenes.end(), [](const SceneReport& r) { return r.resumed; }));
        if (resumed > 0) std::printf("%zu of %zu scenes were complete already (--resume)\n", resumed, scenes);
        std::printf("rendered %zu of %zu scenes in %.2f s (%.3f s a scene after start-up; environment precomputed %u time%s)\n",
                    scenes - report.failed() - resumed, scenes, report.totalMs / 1000.0,
                    scenes == 0 ? 0.0 : (report.totalMs - report.startupMs) / 1000.0 / double(scenes),
                    report.precomputes, report.precomputes == 1 ? "" : "s");
        if (options.shard.count > 1)
            std::printf("shard %u/%u: %zu of the %zu scenes listed\n", options.shard.index, options.shard.count, scenes, report.scenesListed);
    }
    if (report.failed() > 0) {
        log::error(std::to_string(report.failed()) + " of " + std::to_string(scenes) + " scenes failed:");
        int code = 0;
        for (const SceneReport& r : report.scenes)
            if (!r.ok) {
                std::fprintf(stderr, "  %s\n", r.error.c_str());
                if (code == 0) code = r.exitCode;
            }
        return code;
    }
    return run.session.exitCode(0);
}

}  // namespace

int runRender(const RenderOptions& options) {
    const auto runStart = Clock::now();
    const double processStartMs = processAgeMs();
    const std::vector<SceneInput> listed = listScenes(options);
    const std::vector<SceneInput> scenes = shardOf(listed, options.shard);
    const bool single = listed.size() == 1;
    const bool sequence = options.sequence();
    const assets::ImageFileFormat format = prepareOutputs(options, listed, scenes, sequence);

    // --resume: the scenes whose files are all complete are not rendered again (with --variant all,
    // each variant is checked once the file is read: renderScene). What a killed run left
    // half-written is removed.
    std::vector<size_t> pending;
    for (size_t i = 0; i < scenes.size(); ++i)
        if (!options.resume || options.variant == "all" || !outputsComplete(options, scenes[i], variantNameOf(options.variant), single))
            pending.push_back(i);
    if (options.resume)
        for (const std::string& path : {options.graphDot, options.graphJson, options.report, options.html})
            if (!path.empty()) assets::removeStaleTemporaries(path);

    // The first scene is read while the environment loads and the device starts, each of the three
    // on a thread of its own. Of one scene, bad input is reported rather than a device that failed
    // to start (as when the device started only after the load); a bad environment comes first.
    std::future<LoadedScene> next;
    const auto startLoad = [&](size_t i) { next = std::async(std::launch::async, load, std::cref(scenes[i]), std::cref(options)); };
    if (!pending.empty()) startLoad(pending[0]);
    Session session(options.common);
    const Session::Started started = session.loadWhileStarting(options.env);
    const double environmentMs = started.environmentMs;
    const double deviceMs = started.deviceMs;
    const std::exception_ptr deviceError = started.deviceError;
    if (deviceError && (!single || pending.empty())) std::rethrow_exception(deviceError);
    // One scene: the pipelines its first frame takes, whatever its scene, compile on the workers
    // while the file still loads (on an idle core, at low priority). They, and what the maps
    // build, count as the scene's.
    std::optional<vk::Context::PipelineCreation> pipelinesBeforeScene;
    if (single && !pending.empty() && !deviceError) {
        pipelinesBeforeScene = session.context().pipelineCreation();
        const scene::Scene none;
        try {
            RenderSettings settings = candela::renderSettings(apiOptionsOf(options, format), none, session.environment());
            applyRenderFlags(options, settings);
            session.renderer().prepareFirstFrame(settings);
        } catch (const std::exception&) {
            // Settings the frame will refuse, with this error, once it has its scene (or a
            // failure the frame meets again): an optimization only.
        }
    }
    // One scene: its environment's maps are read while the file still loads (the upload asks
    // again only for a scene with a sheen), timed with the environment.
    double environmentMapsMs = 0.0;
    if (single && !pending.empty() && !deviceError && session.environment()) {
        const auto mapsStart = Clock::now();
        session.prepareEnvironmentMaps(options);
        environmentMapsMs = msSince(mapsStart);
    }
    std::optional<LoadedScene> first;
    double firstWaitMs = 0.0;
    if (single && !pending.empty()) {
        const auto waitStart = Clock::now();
        first = next.get();
        firstWaitMs = msSince(waitStart);
        if (first->error) std::rethrow_exception(first->error);
        if (deviceError) std::rethrow_exception(deviceError);
    }
    Run run{options, session, format, !single, sequence};
    run.firstScenePipelinesFrom = pipelinesBeforeScene;
    const vk::Context& context = session.context();
    const assets::Environment* environment = session.environment();
    RunReport report{.version = versionText(),
                     .device = context.report().name,
                     .environment = environment ? environment->source : "none",
                     .width = options.width,
                     .height = options.height,
                     .shard = options.shard,
                     .scenesListed = listed.size(),
                     .gpuMsUnreliable = !vk::timestampsMeasurePasses(context.caps().driver)};
    report.startupMs = msSince(runStart);
    report.processStartMs = processStartMs;
    report.environmentMs = environmentMs + environmentMapsMs;
    report.deviceMs = deviceMs;
    size_t reported = 0;  // report.scenes holds scenes [0, reported)
    const auto addResumed = [&](size_t i) {
        SceneReport& r = report.scenes.emplace_back();
        r.input = scenes[i];
        r.ok = r.resumed = true;
        recordResumed(r, options, options.variant);
        log::info((r.input.file.empty() ? std::string("the default scene") : r.input.file.string()) + ": complete already (--resume)");
    };
    Progress progress("render", run.batch ? scenes.size() : options.frameCount(), options.common.quiet || (run.batch ? false : !sequence));
    report.scenes.reserve(scenes.size());  // the writer's pending image points at its scene's report
    for (size_t k = 0; k < pending.size(); ++k) {
        const size_t i = pending[k];
        // The scenes --resume found complete before this one: reported, not loaded.
        for (; reported < i; ++reported) addResumed(reported);
        const auto waitStart = Clock::now();
        LoadedScene loaded = first ? std::move(*first) : next.get();
        const double waitMs = first ? firstWaitMs : msSince(waitStart);
        first.reset();
        if (k + 1 < pending.size()) startLoad(pending[k + 1]);  // the next file is read while this one renders
        SceneReport& r = report.scenes.emplace_back();
        r.input = scenes[i];
        r.loadMs = loaded.ms;
        r.loadWaitMs = waitMs;  // the rest of the load overlapped the device's start-up or the scene before
        runScene(run, std::move(loaded), r, report, progress);
        if (run.batch) progress.step(i + 1, r.input.name);
        reported = i + 1;
    }
    for (; reported < scenes.size(); ++reported) addResumed(reported);
    run.writer.finish();
    progress.finish();
    report.precomputes = session.renderer().precomputeCount();
    report.totalMs = msSince(runStart);
    return finishRun(run, report);
}

}  // namespace candela::app
