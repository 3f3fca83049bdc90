#include "render/renderer.h"

#include "core/errors.h"
#include "passes/post/readback_pass.h"
#include "vk/context.h"

#include <chrono>
#include <utility>

namespace candela {

using namespace graph;

namespace {
double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

Renderer::Renderer(vk::Context& context, RendererOptions options)
    : mContext(context), mOptions(options), mRunner(context, options.framesInFlight), mScene(context, mRunner),
      mBuilder(context, mScene, mParameters), mReadback(context), mOutputReadback(context) {}

Renderer::~Renderer() { mRunner.waitIdle(); }

void Renderer::validateSettings(const RenderSettings& settings) const {
    const uint32_t limit = mContext.caps().limits.maxImageDimension2D;
    if (settings.width == 0 || settings.height == 0)
        throw UserError("image size must be at least 1x1 (got " + std::to_string(settings.width) + "x" +
                        std::to_string(settings.height) + ")");
    if (settings.width > limit || settings.height > limit)
        throw UserError("image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                        " exceeds the device limit of " + std::to_string(limit) + " pixels per side");
}

vk::MsaaChoice Renderer::msaa(std::optional<uint32_t> requested) const { return mBuilder.msaa(requested); }

VkDeviceSize Renderer::sceneTextureBytes() const { return mScene.hasGpuScene() ? mScene.gpuScene().textureBytes() : 0; }

void Renderer::sceneReplaced() { mScene.sceneReplaced(); }
void Renderer::environmentReplaced() { mScene.environmentReplaced(); }
void Renderer::releaseScene() { mScene.releaseScene(); }

void Renderer::upload(const RenderSettings& settings) {
    const SceneChoice choice{settings.scene, settings.defaultLights, settings.sceneLights};
    if (mScene.uploads(choice)) {
        passes::MaterialKeys keys = passes::MaterialKeys::of(*settings.scene);
        // A new scene's pipelines compile on the workers while its textures upload.
        if (settings.precompile != options::Precompile::Off) mBuilder.prepareAhead(keys, settings, SceneState::lightsOf(choice));
        mScene.prepareScene(choice, std::move(keys));
        mBuilder.sceneUploaded();
    }
    prepareEnvironment(settings.environment, settings.iblQuality, settings.iblCacheDir);
}
void Renderer::prepareEnvironment(const assets::Environment* environment, const ibl::IblQuality& quality,
                                  const std::filesystem::path& cacheDir) {
    mScene.prepareEnvironment(environment, quality, cacheDir);
}

void Renderer::shadersReplaced(const std::vector<std::string>& names) { mScene.shadersReplaced(names); }
void Renderer::recomputeIbl() { mScene.recomputeIbl(); }

void Renderer::setReferenceEnvironment(const assets::Environment& environment) {
    mRunner.waitIdle();
    mScene.iblMaps().setReferenceEnvironment(environment);
}

Frame Renderer::beginFrame(const RenderSettings& settings, const PresentTarget* present) {
    Frame frame;  // started now: a precompute's frame time includes the environment's upload
    validateSettings(settings);
    if (present && !settings.scene) throw UserError("rendering to a window needs a scene");
    if (settings.scene) upload(settings);
    std::optional<TextureId> target;
    if (present) {
        // The image's old contents are discarded; the semaphore wait (at colour-attachment output)
        // orders the first write after the presentation engine has released it.
        const ResourceState acquiredState{.stages = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
        const ResourceState presentState{.stages = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                         .layout = present->finalLayout};
        target = frame.graph->importTexture(
            "swapchain", {.width = settings.width, .height = settings.height, .format = present->format},
            acquiredState, presentState);
        frame.imports.bind(*target, present->image, present->view);
    }
    if (settings.scene) mBuilder.buildScene(frame, settings, target);
    else mBuilder.buildPattern(frame, settings);
    return frame;
}

std::chrono::steady_clock::time_point Renderer::submit(Frame frame, const RenderSettings& settings,
                                                       const PresentTarget* present) {
    return mRunner.submit(std::move(frame), {.disabledPasses = settings.disabledPasses,
                                             .unknownPassIsError = mOptions.unknownPassIsError,
                                             .emitBarriers = mOptions.emitBarriers,
                                             .present = present,
                                             .serialPasses = settings.serialPasses});
}

void Renderer::finishFrame() {
    const Frame& last = mRunner.last();
    mScene.frameCompleted(*last.graph);
    if (!last.precomputes()) return;
    mLastPrecompute = {.frameMs = msSince(last.started), .gpuMs = mRunner.lastPrecomputeGpuMs()};
    ++mPrecomputes;
}

FrameTiming Renderer::execute(Frame frame, const RenderSettings& settings) {
    const auto started = frame.started;
    const auto submitted = submit(std::move(frame), settings);
    mRunner.waitCurrent();
    FrameTiming timing;
    timing.cpuMs = std::chrono::duration<double, std::milli>(submitted - started).count();
    timing.submitWaitMs = msSince(submitted);
    finishFrame();
    timing.timings = mRunner.completedTimings();
    return timing;
}

FrameTiming Renderer::renderFrame(const RenderSettings& settings) {
    Frame frame = beginFrame(settings);
    // Without a readback the frame's results (the image, and the per-pixel outputs asked for) are
    // kept alive as exported outputs, as a swapchain image would be.
    // Without colour among the outputs, the passes that make the image are culled, as in a capture.
    if (settings.outputs.has(options::PixelOutput::Color) || !frame.aov) frame.graph->exportTexture(frame.ldr);
    if (frame.aov)
        for (const auto& [target, image] : frame.aov->images(settings.outputs.has(options::PixelOutput::ClipDepth)))
            frame.graph->exportTexture(image);
    return execute(std::move(frame), settings);
}

FrameTiming Renderer::renderCalibration(uint32_t width, uint32_t height) {
    validateSettings({.width = width, .height = height});
    Frame frame;
    mBuilder.buildCalibration(frame, width, height);
    return execute(std::move(frame), {});
}

FrameTiming Renderer::precomputeIbl(const assets::Environment& environment, const ibl::IblQuality& quality) {
    Frame frame;  // started now: the frame time includes the environment's upload, as beginFrame's does
    mScene.useEnvironment(&environment, quality, {}, /*force=*/true);
    mBuilder.addIblMaps(frame, /*reference=*/false);
    return execute(std::move(frame), {});
}

namespace {

// Why a frame whose readback was culled has nothing to capture: the disabled pass at the root of
// the lost inputs and the passes lost with it, or the readback's own cull detail.
std::string nothingToCapture(const RenderGraph& graph) {
    const CompiledGraph& compiled = graph.compiled();
    uint32_t pass = *graph.findPass("readback");
    std::vector<std::string> lost;
    while (compiled.passes[pass].cullReason == CullReason::LostInput && compiled.passes[pass].lostProducer != graph::kInvalidIndex &&
           lost.size() < compiled.passes.size()) {
        lost.insert(lost.begin(), graph.declaration().passes[pass].name);
        pass = compiled.passes[pass].lostProducer;
    }
    if (compiled.passes[pass].cullReason != CullReason::Disabled)
        return "nothing to capture: the readback pass was culled (" + compiled.passes[*graph.findPass("readback")].cullDetail + ")";
    std::string chain;
    for (const std::string& name : lost) chain += (chain.empty() ? "" : ", ") + name;
    return "nothing to capture: pass '" + graph.declaration().passes[pass].name +
           "' is disabled and the image cannot be made without it (lost with it: " + chain + ")";
}

}  // namespace

CapturedFrame Renderer::capture(const RenderSettings& settings) {
    Frame frame = beginFrame(settings);
    const VkDeviceSize texel = settings.floatOutput ? 8 : 4;  // RGBA16F or RGBA8
    const size_t texels = static_cast<size_t>(settings.width) * settings.height;
    // A frame without a scene (the test pattern) has colour only.
    const bool color = settings.outputs.has(options::PixelOutput::Color) || !frame.aov;
    if (color)
        passes::addReadbackPass(*frame.graph, settings.floatOutput ? frame.hdr : frame.ldr, mReadback.import(frame, texel * texels));
    const std::vector<ReadbackSource> sources = frame.aov ? mOutputReadback.addOutputs(frame, settings.outputs, texels)
                                                          : std::vector<ReadbackSource>{};
    const FrameTiming timing = execute(std::move(frame), settings);

    CapturedFrame captured;
    captured.width = settings.width;
    captured.height = settings.height;
    captured.submitWaitMs = timing.submitWaitMs;
    captured.timings = timing.timings;
    const RenderGraph& graph = *mRunner.last().graph;
    const auto readStart = std::chrono::steady_clock::now();
    if (color) {
        const PassInfo& readbackInfo = graph.compiled().passes[*graph.findPass("readback")];
        if (readbackInfo.cullReason != CullReason::None) throw UserError(nothingToCapture(graph));
        if (settings.floatOutput) captured.rgba32f = mReadback.rgba32f(texels);
        else captured.rgba8 = mReadback.rgba8(texels, VK_FORMAT_R8G8B8A8_UNORM);
    }
    if (!sources.empty()) {
        const PassInfo& readbackInfo = graph.compiled().passes[*graph.findPass("readback_outputs")];
        if (readbackInfo.cullReason != CullReason::None)
            throw UserError("no per-pixel outputs to capture: pass 'aov' did not run (" + readbackInfo.cullDetail + ")");
        captured.outputs = mOutputReadback.outputs(settings.outputs, sources, texels);
    }
    captured.readbackMs = msSince(readStart);
    return captured;
}

void Renderer::renderToTarget(const RenderSettings& settings, const PresentTarget& target, const OverlayFn& overlay,
                              CapturedFrame* screenshot) {
    Frame frame = beginFrame(settings, &target);
    TextureId output = frame.ldr;
    if (overlay) output = overlay(*frame.graph, output);
    const size_t texels = size_t(settings.width) * settings.height;
    if (screenshot) passes::addReadbackPass(*frame.graph, output, mReadback.import(frame, VkDeviceSize(4) * texels));
    submit(std::move(frame), settings, &target);
    // Only a frame that computed persistent maps (the IBL precompute, the sheen LUT) is waited for,
    // so that the maps are marked current before the next frame is built: that frame imports them
    // as computed instead of running the precompute again, and their owners free the precompute's
    // inputs and write the cache. Every other frame, with an environment or without, runs ahead
    // (up to framesInFlight in flight): it only reads the maps, which the precompute frame's final
    // barriers left visible to every later submission.
    if (!screenshot && !mRunner.last().computesMaps()) return;
    mRunner.waitCurrent();
    finishFrame();
    if (!screenshot) return;
    screenshot->width = settings.width;
    screenshot->height = settings.height;
    screenshot->timings = mRunner.completedTimings();
    screenshot->rgba8 = mReadback.rgba8(texels, target.format);
}

std::vector<std::string> Renderer::explain() const {
    std::vector<std::string> lines;
    const RenderGraph& graph = *mRunner.last().graph;
    const GraphDecl& decl = graph.declaration();
    for (uint32_t p = 0; p < decl.passes.size(); ++p) {
        const PassInfo& info = graph.compiled().passes[p];
        if (info.cullReason != CullReason::None)
            lines.push_back("left out: pass '" + decl.passes[p].name + "' (" + info.cullDetail + ")");
    }
    lines.insert(lines.end(), mRunner.last().explanation.begin(), mRunner.last().explanation.end());
    return lines;
}

Renderer::Backdrop Renderer::lastBackdrop() const {
    const Frame& frame = mRunner.last();
    const std::optional<uint32_t> skybox = frame.graph->findPass("skybox");
    const bool skyboxRan = skybox && frame.graph->isCompiled() &&
                           frame.graph->compiled().passes[*skybox].cullReason == CullReason::None;
    if ((frame.plan && frame.plan->sky == SkyPlacement::Tonemap) || skyboxRan) return Backdrop::Sky;
    return frame.solidBackground ? Backdrop::Color : Backdrop::Transparent;
}

}  // namespace candela
