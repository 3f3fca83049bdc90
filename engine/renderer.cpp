#include "renderer.h"

#include "core/check.h"
#include "core/log.h"
#include "passes/readback_pass.h"
#include "shared/tonemap.h"
#include "vk/context.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace candela {

using namespace graph;

namespace {

// The bytes of `items`, for a host upload (an empty vector gives no bytes: memcpy from its null
// data() would be undefined even for 0 bytes).
template <typename T>
std::vector<std::byte> bytesOf(const std::vector<T>& items) {
    std::vector<std::byte> out(items.size() * sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), items.data(), out.size());
    return out;
}
constexpr VkFormat kLdrFormat = VK_FORMAT_R8G8B8A8_SRGB;

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

Renderer::Renderer(vk::Context& context, uint32_t framesInFlight)
    : mContext(context), mFrames(context, framesInFlight), mPattern(context), mEncode(context, kLdrFormat),
      mForward(context), mTonemap(context), mIbl(std::make_unique<ibl::IblMaps>(context)) {
    for (uint32_t i = 0; i < mFrames.slotCount(); ++i) mTransients.push_back(std::make_unique<TransientPool>(context));
    mHostBuffers.resize(mFrames.slotCount());
}

Renderer::~Renderer() { mFrames.waitIdle(); }

void Renderer::validateSettings(const RenderSettings& settings) const {
    const uint32_t limit = mContext.properties().limits.maxImageDimension2D;
    if (settings.width == 0 || settings.height == 0)
        throw UserError("image size must be at least 1x1 (got " + std::to_string(settings.width) + "x" +
                        std::to_string(settings.height) + ")");
    if (settings.width > limit || settings.height > limit)
        throw UserError("image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                        " exceeds the device limit of " + std::to_string(limit) + " pixels per side");
}

uint32_t Renderer::transientRebuilds() const {
    uint32_t total = 0;
    for (const auto& pool : mTransients) total += pool->rebuilds();
    return total;
}

std::vector<scene::Light> Renderer::defaultLights() {
    scene::Light key, fill;
    key.type = fill.type = scene::LightType::Directional;
    key.intensity = 3.0f;  // lux
    key.direction = glm::normalize(glm::vec3(-0.5f, -0.7f, -0.6f));
    fill.intensity = 1.0f;
    fill.direction = glm::normalize(glm::vec3(0.7f, -0.2f, -0.5f));
    fill.color = glm::vec3(0.9f, 0.95f, 1.0f);
    return {key, fill};
}

void Renderer::prepareScene(const RenderSettings& settings) {
    if (!settings.scene) return;
    const bool sceneLights = settings.sceneLights && !settings.scene->lights.empty();
    const bool addLights = settings.defaultLights && !sceneLights;
    if (settings.scene == mUploaded && addLights == mUploadedDefaultLights && sceneLights == mUploadedSceneLights) return;
    // The previous scene's buffers may still be used by a frame in flight: wait first.
    mFrames.waitIdle();
    // Software rasterizers pay ~1000× for anisotropic filtering (minutes per frame on lavapipe):
    // keep it for GPUs.
    const bool cpuDevice = mContext.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    mGpuScene = std::make_unique<scene::GpuScene>(mContext, *settings.scene,
                                                  addLights ? defaultLights() : std::vector<scene::Light>{},
                                                  cpuDevice ? 1.0f : 8.0f, sceneLights);
    mForward.setScene(*mGpuScene);
    mRestPose = settings.scene->deformations.empty() ? nullptr : std::make_unique<scene::ScenePose>(*settings.scene, std::vector<uint32_t>{});
    mUploaded = settings.scene;
    mUploadedDefaultLights = addLights;
    mUploadedSceneLights = sceneLights;
}

namespace {
// Whether a material of `scene` has a sheen (KHR_materials_sheen) the forward pass draws.
bool hasSheen(const scene::Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const scene::Material& m) { return !m.unlit && (m.layers() & scene::kLayerSheen); });
}
}  // namespace

void Renderer::prepareEnvironment(const RenderSettings& settings) {
    if (!settings.scene) return;
    // The sheen cube is computed only for scenes that have a sheen.
    ibl::IblQuality quality = settings.iblQuality;
    quality.sheen = hasSheen(*settings.scene);
    if (settings.environment == mEnvironment && quality == mIblQuality && settings.iblCacheDir == mIblCacheDir) return;
    useEnvironment(settings.environment, quality, settings.iblCacheDir, false);
}

void Renderer::useEnvironment(const scene::Environment* environment, const ibl::IblQuality& quality,
                              const std::filesystem::path& cacheDir, bool force) {
    quality.validate();
    // The maps may be read by a frame in flight: wait before replacing them.
    mFrames.waitIdle();
    // Out of device memory: degrade to a lower cube resolution (with a warning) rather than fail.
    ibl::IblQuality effective = quality;
    for (;;) {
        try {
            mIbl->setEnvironment(environment, effective, cacheDir, force);
            break;
        } catch (const OutOfDeviceMemory& e) {
            if (effective.cubeSize <= 32) throw;
            resetIblMaps();  // drops (and, once collected, frees) what the failed attempt allocated
            mFrames.waitIdle();
            effective.cubeSize /= 2;
            effective.shSourceSize = std::min(effective.shSourceSize, effective.cubeSize);
            effective.irradianceSize = std::min(effective.irradianceSize, effective.cubeSize);
            log::warn(std::string("not enough device memory for the IBL maps (") + e.what() +
                      "): lowering the environment cube to " + std::to_string(effective.cubeSize) + " texels");
            force = true;
        }
    }
    mEnvironment = environment;
    mIblQuality = quality;
    mIblCacheDir = cacheDir;
}

void Renderer::applySceneParameters() {
    // The reflected members of one element of `buffer`, a runtime array in `reflection`.
    const auto elementsOf = [](const shader::ShaderReflection& reflection,
                               const char* buffer) -> std::span<const shader::BlockMember> {
        for (const shader::DescriptorBinding& b : reflection.bindings)
            if (b.name == buffer && b.members.size() == 1) return b.members[0].elementMembers;
        return {};
    };
    const shader::ShaderReflection& reflection = mForward.reflection();
    const auto elements = [&](const char* buffer) { return elementsOf(reflection, buffer); };
    // The scene's values with the user's applied, compared with what the buffers hold.
    std::vector<shading::LightData> lights = mGpuScene->sceneLights();
    std::vector<shading::MaterialData> materials = mGpuScene->sceneMaterials();
    for (size_t i = 0; i < lights.size(); ++i)
        mParameters.apply("forward", "Lights[" + std::to_string(i) + "]", elements("Lights"), lights[i]);
    for (size_t i = 0; i < materials.size(); ++i)
        mParameters.apply("forward", "Materials[" + std::to_string(i) + "]", elements("Materials"), materials[i]);
    // The layers of the materials that have some, from the layered program's reflection.
    std::vector<shading::MaterialLayerData> layers = mGpuScene->sceneMaterialLayers();
    if (const shader::ShaderReflection* layered = mForward.layeredReflection())
        for (size_t i = 0; i < layers.size(); ++i)
            if (mGpuScene->scene().materials[i].layers() != 0)
                mParameters.apply("forward", "MaterialLayers[" + std::to_string(i) + "]", elementsOf(*layered, "MaterialLayers"),
                                  layers[i]);
    const auto same = [](const auto& a, const auto& b) {
        // (memcmp with an empty vector's null data() is undefined even for 0 bytes.)
        return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
    };
    if (same(lights, mGpuScene->lights()) && same(materials, mGpuScene->materials()) &&
        same(layers, mGpuScene->materialLayers()))
        return;
    // The buffers may be read by frames in flight.
    mFrames.waitIdle();
    mGpuScene->rewrite(lights, materials, layers);
}

void Renderer::shadersReplaced(const std::vector<std::string>& names) {
    if (std::none_of(names.begin(), names.end(), [](const std::string& n) { return n.rfind("ibl_", 0) == 0; })) return;
    resetIblMaps();
    // Recomputed (never read from the cache) by the next frame, with the new shaders.
    if (mEnvironment) useEnvironment(mEnvironment, mIblQuality, mIblCacheDir, /*force=*/true);
}

void Renderer::resetIblMaps() {
    mFrames.waitIdle();
    mIbl = std::make_unique<ibl::IblMaps>(mContext);
}

double Renderer::completedPassMs(std::string_view pass) const {
    for (const PassTime& t : mCompletedTimes)
        if (t.name == pass) return t.gpuMs;
    return -1.0;
}

void Renderer::sceneReplaced() {
    mFrames.waitIdle();
    mUploaded = nullptr;
}

void Renderer::recomputeIbl() {
    if (mEnvironment) useEnvironment(mEnvironment, mIblQuality, {}, /*force=*/true);
}

Frame Renderer::beginFrame(const RenderSettings& settings, const PresentTarget* present) {
    Frame frame;  // started now: a precompute's frame time includes the environment's upload
    validateSettings(settings);
    if (present && !settings.scene) throw UserError("rendering to a window needs a scene");
    prepareScene(settings);
    prepareEnvironment(settings);
    std::optional<TextureId> target;
    if (present) {
        // The image's old contents are discarded; the semaphore wait (at colour-attachment output)
        // orders the first write after the presentation engine has released it.
        const ResourceState acquiredState{.stages = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
        const ResourceState presentState{.stages = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                         .layout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
        target = frame.graph->importTexture(
            "swapchain", {.width = settings.width, .height = settings.height, .format = present->format},
            acquiredState, presentState);
        frame.imports.bind(*target, present->image, present->view);
    }
    if (settings.scene) buildSceneGraph(frame, settings, target);
    else buildPatternGraph(frame, settings);
    return frame;
}

std::chrono::steady_clock::time_point Renderer::submit(Frame frame, const RenderSettings& settings,
                                                       const PresentTarget* present) {
    RenderGraph& graph = *frame.graph;
    for (const std::string& name : settings.disabledPasses) {
        if (!graph.findPass(name)) {
            if (!settings.unknownPassIsError) continue;
            std::string names;
            for (const PassDecl& p : graph.declaration().passes) names += (names.empty() ? "" : ", ") + p.name;
            throw UserError("cannot disable pass '" + name + "': no such pass (passes: " + names + ")");
        }
        graph.setPassEnabled(name, false);
    }
    graph.compile({.memoryRequirements = deviceMemoryRequirements(mContext, graph.declaration())});
    vk::FrameSlot& slot = mFrames.begin();
    writeHostUploads(frame);
    TransientPool& transients = *mTransients[mFrames.currentSlot()];
    transients.realize(graph.declaration(), graph.compiled());
    ExecutionRecord record = executeGraph({.context = mContext,
                                           .graph = graph,
                                           .imports = frame.imports,
                                           .transients = transients,
                                           .cmd = slot.cmd,
                                           .descriptors = *slot.descriptors,
                                           .timestamps = slot.timestamps.get(),
                                           .emitBarriers = settings.emitBarriers});
    std::vector<std::string> names;
    for (uint32_t pass : graph.compiled().order) names.push_back(graph.declaration().passes[pass].name);
    slot.completed = [this, record = std::move(record), order = graph.compiled().order, names = std::move(names),
                      precompute = std::make_pair(frame.precomputeBegin, frame.precomputeEnd)](vk::FrameSlot& done) {
        mCompletedTimings = record.timings(*done.timestamps);
        mCompletedTimes.clear();
        for (size_t i = 0; i < order.size(); ++i)
            mCompletedTimes.push_back({names[i], order[i] < mCompletedTimings.gpuMs.size() ? mCompletedTimings.gpuMs[order[i]] : -1.0});
        if (precompute.first == precompute.second) return;
        mLastPrecompute.gpuMs = 0.0;
        for (uint32_t pass = precompute.first; pass < precompute.second; ++pass)
            mLastPrecompute.gpuMs += std::max(mCompletedTimings.gpuMs[pass], 0.0);
    };
    const auto submitted = std::chrono::steady_clock::now();
    if (present)
        mFrames.submit({{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                         .semaphore = present->acquired,
                         .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT}},
                       // Signalled when all the frame's work, the transition to PRESENT_SRC included,
                       // has completed (at the end of the batch, so it stalls nothing).
                       {{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                         .semaphore = present->rendered,
                         .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT}});
    else
        mFrames.submit();
    mLast = std::move(frame);
    return submitted;
}

void Renderer::finishFrame() {
    if (mLast.sheenLut) mSheenLut->frameCompleted(*mLast.graph);
    if (!mLast.ibl) return;
    mIbl->frameCompleted(*mLast.graph);
    if (mLast.precomputeBegin != mLast.precomputeEnd) mLastPrecompute.frameMs = msSince(mLast.started);
}

FrameTiming Renderer::execute(Frame frame, const RenderSettings& settings) {
    const auto started = frame.started;
    const auto submitted = submit(std::move(frame), settings);
    mFrames.waitCurrent();
    FrameTiming timing;
    timing.cpuMs = std::chrono::duration<double, std::milli>(submitted - started).count();
    timing.submitWaitMs = msSince(submitted);
    finishFrame();
    timing.timings = mCompletedTimings;
    return timing;
}

FrameTiming Renderer::renderFrame(const RenderSettings& settings) {
    Frame frame = beginFrame(settings);
    // Without a readback the frame's result is kept alive as an exported output, as a swapchain
    // image would be.
    frame.graph->exportTexture(frame.ldr);
    return execute(std::move(frame), settings);
}

FrameTiming Renderer::renderCalibration(uint32_t width, uint32_t height) {
    validateSettings({.width = width, .height = height});
    if (!mCalibration) mCalibration = std::make_unique<passes::CalibrationPass>(mContext);
    Frame frame;
    mCalibration->add(*frame.graph, width, height);
    return execute(std::move(frame), {});
}

FrameTiming Renderer::precomputeIbl(const scene::Environment& environment, const ibl::IblQuality& quality) {
    Frame frame;  // started now: the frame time includes the environment's upload, as beginFrame's does
    useEnvironment(&environment, quality, {}, /*force=*/true);
    addIblMaps(frame, /*reference=*/false);
    return execute(std::move(frame), {});
}

passes::IblHandles Renderer::addIblMaps(Frame& frame, bool reference) {
    const auto declared = [&] { return static_cast<uint32_t>(frame.graph->declaration().passes.size()); };
    frame.ibl = true;
    frame.precomputeBegin = declared();
    const passes::IblHandles maps = mIbl->addToGraph(*frame.graph, frame.imports, reference);
    frame.precomputeEnd = declared();
    return maps;
}

void Renderer::setReferenceEnvironment(const scene::Environment& environment) {
    mFrames.waitIdle();
    mIbl->setReferenceEnvironment(environment);
}

CapturedFrame Renderer::capture(const RenderSettings& settings) {
    Frame frame = beginFrame(settings);
    const VkDeviceSize texel = settings.floatOutput ? 8 : 4;  // RGBA16F or RGBA8
    const VkDeviceSize bytes = texel * settings.width * settings.height;
    passes::addReadbackPass(*frame.graph, settings.floatOutput ? frame.hdr : frame.ldr, importReadback(frame, bytes));
    const FrameTiming timing = execute(std::move(frame), settings);

    CapturedFrame captured;
    captured.width = settings.width;
    captured.height = settings.height;
    captured.submitWaitMs = timing.submitWaitMs;
    captured.timings = timing.timings;
    const PassInfo& readbackInfo = mLast.graph->compiled().passes[*mLast.graph->findPass("readback")];
    if (readbackInfo.cullReason != CullReason::None)
        throw UserError("nothing to capture: the readback pass was culled (" + readbackInfo.cullDetail + ")");
    const auto readStart = std::chrono::steady_clock::now();
    mReadback.invalidate();
    const size_t texels = static_cast<size_t>(settings.width) * settings.height;
    if (settings.floatOutput) {
        captured.rgba32f.resize(texels * 4);
        const auto* half = reinterpret_cast<const uint16_t*>(mReadback.mapped());
        for (size_t i = 0; i < texels * 4; ++i) captured.rgba32f[i] = glm::unpackHalf1x16(half[i]);
    } else {
        captured.rgba8.resize(texels * 4);
        std::memcpy(captured.rgba8.data(), mReadback.mapped(), captured.rgba8.size());
    }
    captured.readbackMs = msSince(readStart);
    return captured;
}

BufferId Renderer::importReadback(Frame& frame, VkDeviceSize bytes) {
    if (!mReadback || mReadback.size() != bytes)
        mReadback = vk::Buffer(mContext, {.size = bytes,
                                          .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          .memory = vk::MemoryUsage::Readback,
                                          .name = "readback"});
    const BufferId readback =
        frame.graph->importBuffer("readback", {.size = bytes}, ResourceState{}, passes::hostReadState());
    frame.imports.bind(readback, mReadback.handle());
    return readback;
}

std::optional<passes::ForwardPass::DeformedVertices> Renderer::addSkinMorph(Frame& frame, const scene::ScenePose& pose) {
    if (mUploaded->deformations.empty()) return std::nullopt;  // a static scene: its graph stays as it was
    passes::SkinMorphFrame work = passes::skinMorphFrame(*mGpuScene, pose);
    if (work.jobs.empty()) {
        frame.notes.emplace_back("left out: skin_morph (no draw is skinned or has a non-zero morph weight in this pose)");
        return std::nullopt;
    }
    const passes::SkinMorphPass::Inputs inputs{.scene = mGpuScene.get(),
                                               .jobs = work.jobs,
                                               .vertexCount = work.vertexCount,
                                               .joints = addHostUpload(frame, "joint_matrices", bytesOf(work.joints)),
                                               .activeTargets = addHostUpload(frame, "morph_weights", bytesOf(work.activeTargets))};
    if (!mSkinMorph) mSkinMorph = std::make_unique<passes::SkinMorphPass>(mContext);
    frame.notes.push_back("skin_morph: " + std::to_string(work.jobs.size()) + " draws deformed (" +
                          std::to_string(work.skinnedDraws) + " skinned), " + std::to_string(work.activeTargets.size()) +
                          " morph targets with a non-zero weight, " + std::to_string(work.vertexCount) + " vertices (" +
                          formatBytes(uint64_t(work.vertexCount) * sizeof(scene::Vertex)) + " per frame in flight)");
    return passes::ForwardPass::DeformedVertices{.vertices = mSkinMorph->add(*frame.graph, inputs),
                                                 .vertexOffset = std::move(work.vertexOffset)};
}

BufferId Renderer::addHostUpload(Frame& frame, std::string name, std::vector<std::byte> bytes) {
    // Nothing on the device wrote it before the frame: no barrier to wait for.
    const BufferId buffer = frame.graph->importBuffer(std::move(name), {.size = std::max<VkDeviceSize>(bytes.size(), 16)},
                                                      ResourceState{});
    frame.hostUploads.push_back({buffer, std::move(bytes)});
    return buffer;
}

void Renderer::writeHostUploads(Frame& frame) {
    // The slot's previous frame has completed (FrameRing::begin waited for it): its buffers are free.
    std::vector<vk::Buffer>& buffers = mHostBuffers[mFrames.currentSlot()];
    if (buffers.size() < frame.hostUploads.size()) buffers.resize(frame.hostUploads.size());
    for (size_t i = 0; i < frame.hostUploads.size(); ++i) {
        const Frame::HostUpload& upload = frame.hostUploads[i];
        const std::string& name = frame.graph->declaration().resources[upload.buffer.index].name;
        if (!buffers[i] || buffers[i].size() < upload.bytes.size())
            buffers[i] = vk::Buffer(mContext, {.size = frame.graph->declaration().resources[upload.buffer.index].buffer.size,
                                               .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                               .memory = vk::MemoryUsage::Upload,
                                               .name = name.c_str()});
        if (!upload.bytes.empty()) std::memcpy(buffers[i].mapped(), upload.bytes.data(), upload.bytes.size());
        buffers[i].flush();
        frame.imports.bind(upload.buffer, buffers[i].handle());
    }
}

void Renderer::renderToTarget(const RenderSettings& settings, const PresentTarget& target, const OverlayFn& overlay,
                              CapturedFrame* screenshot) {
    Frame frame = beginFrame(settings, &target);
    TextureId output = frame.ldr;
    if (overlay) output = overlay(*frame.graph, output);
    const VkDeviceSize bytes = VkDeviceSize(4) * settings.width * settings.height;
    if (screenshot) passes::addReadbackPass(*frame.graph, output, importReadback(frame, bytes));
    const bool ibl = frame.ibl;
    submit(std::move(frame), settings, &target);
    // A frame with image-based lighting is waited for, so that the maps learn that a precompute
    // completed before the next frame is built. (Only frames that ran one need it; waiting for
    // those alone would keep frames in flight with an environment — not changed here.)
    if (!screenshot && !ibl) return;
    mFrames.waitCurrent();
    finishFrame();
    if (!screenshot) return;
    screenshot->width = settings.width;
    screenshot->height = settings.height;
    screenshot->timings = mCompletedTimings;
    mReadback.invalidate();
    screenshot->rgba8.resize(bytes);
    std::memcpy(screenshot->rgba8.data(), mReadback.mapped(), bytes);
    const bool bgra = target.format == VK_FORMAT_B8G8R8A8_UNORM || target.format == VK_FORMAT_B8G8R8A8_SRGB;
    if (bgra)
        for (size_t i = 0; i < bytes; i += 4) std::swap(screenshot->rgba8[i], screenshot->rgba8[i + 2]);
}

void Renderer::buildPatternGraph(Frame& frame, const RenderSettings& settings) {
    RenderGraph& graph = *frame.graph;
    frame.hdr = mPattern.add(graph, settings.width, settings.height, settings.patternExposure);
    const TextureId ldr = graph.createTexture("ldr", {.width = settings.width, .height = settings.height, .format = kLdrFormat});
    frame.ldr = mEncode.add(graph, frame.hdr, ldr);
}

vk::MsaaChoice Renderer::msaa(std::optional<uint32_t> requested) const {
    return vk::chooseMsaa(mContext.properties().deviceType, mContext.attachmentSampleCounts(), requested);
}

void Renderer::buildSceneGraph(Frame& frame, const RenderSettings& settings, std::optional<TextureId> target) {
    RenderGraph& graph = *frame.graph;
    const vk::MsaaChoice msaa = this->msaa(settings.msaa);
    if (msaa.clamped && mMsaaWarnedFor != settings.msaa) {
        log::warn("--msaa: " + msaa.reason);
        mMsaaWarnedFor = settings.msaa;
    }
    const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
    const scene::ScenePose* pose = settings.pose ? settings.pose : mRestPose.get();
    const scene::ViewSetup view = resolveView(*settings.scene, settings.camera, aspect, pose);
    const std::optional<passes::ForwardPass::DeformedVertices> deformed =
        pose ? addSkinMorph(frame, *pose) : std::optional<passes::ForwardPass::DeformedVertices>();
    std::optional<passes::ForwardPass::PosedDraws> posed;
    if (pose && pose->animated()) {
        const std::vector<scene::Draw>& draws = pose->draws();
        std::vector<std::byte> data = bytesOf(scene::drawDataOf(*settings.scene, draws));
        posed = passes::ForwardPass::PosedDraws{.draws = draws, .data = addHostUpload(frame, "posed_draws", std::move(data))};
        if (!pose->animatedLights().empty() && mUploadedSceneLights) {
            // The lights as the buffer holds them (the user's edits included), moved where the pose puts them.
            std::vector<shading::LightData> lights = mGpuScene->lights();
            for (uint32_t l : pose->animatedLights()) {
                const shading::LightData placed = scene::lightData(pose->lights()[l]);
                lights[l].positionRange = glm::vec4(glm::vec3(placed.positionRange), lights[l].positionRange.w);
                lights[l].directionType = glm::vec4(glm::vec3(placed.directionType), lights[l].directionType.w);
            }
            posed->lights = addHostUpload(frame, "posed_lights", bytesOf(lights));
        }
    }
    std::optional<passes::ForwardPass::Ibl> ibl;
    if (mIbl->hasEnvironment()) {
        const float theta = glm::radians(settings.ibl.rotationDegrees);
        const float maxLod = float(mIbl->specularLevels() - 1);
        ibl = passes::ForwardPass::Ibl{
            .maps = addIblMaps(frame, settings.ibl.referenceSamples > 0),
            .params = {.rotation = glm::vec4(std::cos(theta), std::sin(theta), 0.0f, 0.0f),
                       .intensity = settings.ibl.intensity,
                       .maxLod = maxLod,
                       .skyboxLod = std::clamp(settings.ibl.skyboxBlur, 0.0f, 1.0f) * maxLod,
                       .lutSize = float(mIbl->lutSize())},
            .irradianceSh = mIbl->quality().irradiance == ibl::IrradianceMode::Sh9,
            .multiscatter = settings.ibl.multiscatter,
            .referenceSamples = settings.ibl.referenceSamples};
    }
    // The material layers' maps: the sheen LUT (computed once) and, with an environment, the sheen cube.
    std::optional<passes::LayerMaps> layerMaps;
    if (hasSheen(*settings.scene)) {
        if (!mSheenLut) mSheenLut = std::make_unique<ibl::SheenLut>(mContext);
        layerMaps = passes::LayerMaps{.sheenLut = mSheenLut->addToGraph(graph, frame.imports),
                                      .sheenCube = ibl ? ibl->maps.sheen : TextureId{}};
        frame.sheenLut = true;
    }
    mParameters.beginFrame();
    applySceneParameters();
    const passes::ForwardPass::Output forward =
        mForward.add(graph, {settings.width, settings.height, msaa.samples}, view, settings.shading, ibl ? &*ibl : nullptr, &mParameters,
                     settings.debugView, posed ? &*posed : nullptr, deformed ? &*deformed : nullptr,
                     layerMaps ? &*layerMaps : nullptr, settings.drawSelection,
                     settings.shadingOptions);
    frame.debugView = settings.debugView;
    passes::DrawTarget drawn = forward;
    frame.skybox = ibl && settings.ibl.skybox && settings.debugView == passes::DebugView::None;
    if (frame.skybox) {
        if (!mSkybox) mSkybox = std::make_unique<passes::SkyboxPass>(mContext);
        drawn = mSkybox->add(graph, view, {.target = drawn, .specular = ibl->maps.specular, .params = ibl->params}, &mParameters);
    }
    // Transmissive draws over the opaque image (sky included), which they see through.
    frame.transmission = mForward.hasTransmissiveDraws();
    if (frame.transmission) {
        if (!mTransmissionBackground) mTransmissionBackground = std::make_unique<passes::TransmissionBackgroundPass>(mContext);
        drawn = mForward.addTransmissive(graph, drawn, mTransmissionBackground->add(graph, drawn.hdr));
    }
    frame.hdr = drawn.hdr;
    // UNORM target: the tonemap shader encodes sRGB itself, which also lets it dither.
    const TextureId ldr = target ? *target
                                 : graph.createTexture("ldr", {.width = settings.width,
                                                               .height = settings.height,
                                                               .format = VK_FORMAT_R8G8B8A8_UNORM});
    passes::TonemapSettings tonemap = settings.tonemap;
    // Debug views have no skybox: where it was the background, a neutral grey (#262626) is.
    if (settings.debugView != passes::DebugView::None && ibl && settings.ibl.skybox && !tonemap.background)
        tonemap.background = shading::srgbDecode(glm::vec3(38.0f / 255.0f));
    if (settings.debugView != passes::DebugView::None && !passes::debugViewIsLight(settings.debugView)) {
        tonemap.op = passes::Tonemap::Linear;  // data as it is
        tonemap.exposureEv = 0.0f;
        tonemap.dither = false;
    }
    frame.ldr = mTonemap.add(graph, frame.hdr, ldr, tonemap, &mParameters);

    // What --explain says of this frame, taken now: the forward pass and the maps describe their last add.
    if (!mUploadedSceneLights && !settings.scene->lights.empty())
        frame.notes.emplace_back("left out: the scene's " + std::to_string(settings.scene->lights.size()) +
                                 " punctual lights (--scene-lights off)");
    if (mUploadedDefaultLights)
        frame.notes.emplace_back("added: default key and fill lights (the scene has no punctual lights; --no-default-lights)");
    frame.notes.push_back("msaa: " + msaa.reason +
                          (msaa.samples == 1 ? std::string()
                           : mContext.alphaToOne()
                               ? "; alpha-masked materials use alpha to coverage"
                               : "; alpha-masked materials keep the alpha test (the device has no alphaToOne)"));
    for (const std::string& line : mForward.explanation()) frame.notes.push_back(line);
    for (const std::string& line : mIbl->explanation()) frame.notes.push_back(line);
    if (frame.sheenLut)
        frame.notes.emplace_back(mSheenLut->computed() ? "sheen LUT: imported (computed by an earlier frame)"
                                                       : "sheen LUT: computed by this frame's ibl_sheen_lut pass (once per run)");
    else
        frame.notes.emplace_back("left out: sheen LUT (no material has a sheen)");
    if (frame.transmission)
        frame.notes.emplace_back("transmission: 'transmission_background' copies the opaque image into a mip chain; "
                                 "'forward_transmission' draws the transmissive and blended draws over it");
    else
        frame.notes.emplace_back(frame.debugView != passes::DebugView::None
                                     ? "left out: transmission background (debug view: transmissive draws show data)"
                                     : "left out: transmission background (no transmissive material in the frame)");
    if (frame.debugView != passes::DebugView::None)
        frame.notes.push_back(std::string("debug view: ") + passes::debugViewName(frame.debugView) +
                              (passes::debugViewIsLight(frame.debugView) ? " (tonemapped as the image is)"
                                                                         : " (shown as data: linear tonemap at exposure 0)"));
    if (frame.ibl && !frame.skybox)
        frame.notes.emplace_back(frame.debugView != passes::DebugView::None
                                     ? "left out: skybox (debug view)"
                                     : "left out: skybox (the background is not the environment)");
}

scene::ViewSetup Renderer::resolveView(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                       const scene::ScenePose* pose) {
    if (pose && !pose->animated()) pose = nullptr;
    if (camera.orbitCamera) {
        scene::ViewSetup view = camera.orbitCamera->view(aspect);
        if (camera.lensShiftX != 0.0f) {
            view.projection = glm::translate(glm::mat4(1.0f), glm::vec3(camera.lensShiftX, 0.0f, 0.0f)) * view.projection;
            view.viewProjection = view.projection * view.view;
        }
        return view;
    }
    if (camera.gltfCamera) {
        if (*camera.gltfCamera >= scene.cameras.size())
            throw UserError("--camera " + std::to_string(*camera.gltfCamera) + ": the scene has " +
                            std::to_string(scene.cameras.size()) + " cameras");
        return scene::cameraView((pose ? pose->cameras() : scene.cameras)[*camera.gltfCamera], aspect);
    }
    const glm::vec3 angles = camera.orbit.value_or(glm::vec3(0.0f, 90.0f, 0.0f));
    scene::OrbitCamera orbit = scene::OrbitCamera::framing(pose ? pose->animationBounds() : scene.bounds, aspect, angles.x,
                                                           angles.y, camera.fovYDegrees);
    if (angles.z > 0.0f) {
        orbit.radius = angles.z;
        orbit.znear = angles.z * 1e-3f;
    }
    if (camera.target) orbit.target = *camera.target;
    return orbit.view(aspect);
}

std::vector<std::string> Renderer::explain() const {
    std::vector<std::string> lines;
    const graph::GraphDecl& decl = mLast.graph->declaration();
    for (uint32_t p = 0; p < decl.passes.size(); ++p) {
        const graph::PassInfo& info = mLast.graph->compiled().passes[p];
        if (info.cullReason != graph::CullReason::None)
            lines.push_back("left out: pass '" + decl.passes[p].name + "' (" + info.cullDetail + ")");
    }
    lines.insert(lines.end(), mLast.notes.begin(), mLast.notes.end());
    return lines;
}

}  // namespace candela
