// candela::Device (candela/device.h): a vk::Context and a Renderer; the public render options
// turned into the renderer's settings; frames read back into the public pixel formats.

#include "api/access.h"
#include "api/outputs.h"
#include "api/cameras.h"
#include "candela/device.h"
#include "core/cache_files.h"
#include "core/parallel_for.h"
#include "geometry/lod_cache.h"
#include "options/device_profile.h"
#include "pose/scene_pose.h"
#include "scene/camera.h"
#include "scene/material_variants.h"
#include "shared/tonemap.h"
#include "vk/check.h"

#include <glm/gtc/packing.hpp>

#include <cstring>

namespace candela {
namespace {

options::Tonemap tonemapOf(Tonemap tonemap) {
    switch (tonemap) {
        case Tonemap::PbrNeutral: return options::Tonemap::PbrNeutral;
        case Tonemap::Aces: return options::Tonemap::Aces;
        case Tonemap::Agx: return options::Tonemap::Agx;
        case Tonemap::Reinhard: return options::Tonemap::Reinhard;
        case Tonemap::Linear: return options::Tonemap::Linear;
    }
    throw UserError("unknown tone mapping operator " + std::to_string(int(tonemap)));
}

options::ShadingPath shadingPathOf(ShadingPath path) {
    switch (path) {
        case ShadingPath::Auto: return options::ShadingPath::Auto;
        case ShadingPath::Forward: return options::ShadingPath::Forward;
        case ShadingPath::Visibility: return options::ShadingPath::Visibility;
    }
    throw UserError("unknown shading path " + std::to_string(int(path)));
}

vk::ContextDesc contextDescOf(const DeviceOptions& options) {
    vk::ContextDesc desc{.validation = options.validation,
                         .deviceSelector = options.device,
                         .deviceMemoryBudget = uint64_t(options.memoryBudgetMib) << 20};
    if (!options.profile.empty()) {
        desc.profile = options::parseDeviceProfile(options.profile);
        if (!desc.profile)
            throw UserError("device profile '" + options.profile + "': choose from " + options::deviceProfileList());
    }
    desc.pipelineCacheFolder = pipelineCacheFolder(options.pipelineCache);
    return desc;
}

// `frame` in `format`, into frame.height rows of `rowBytes` bytes at `out`.
void copyPixels(const CapturedFrame& frame, PixelFormat format, std::byte* out, size_t rowBytes) {
    const size_t width = frame.width;
    for (uint32_t y = 0; y < frame.height; ++y) {
        std::byte* row = out + y * rowBytes;
        switch (format) {
            case PixelFormat::Rgba8Srgb: std::memcpy(row, frame.rgba8.data() + y * width * 4, width * 4); break;
            case PixelFormat::Rgba32Float:
                std::memcpy(row, frame.rgba32f.data() + y * width * 4, width * 4 * sizeof(float));
                break;
            case PixelFormat::Rgba16Float: {
                // The GPU wrote half floats; the readback widened them: this narrows them back exactly.
                const float* in = frame.rgba32f.data() + y * width * 4;
                for (size_t i = 0; i < width * 4; ++i) {
                    const uint16_t half = glm::packHalf1x16(in[i]);
                    std::memcpy(row + i * 2, &half, 2);
                }
                break;
            }
        }
    }
}

// The bytes of one row of the image `options` ask for, without padding.
size_t packedRowBytes(const RenderOptions& options) { return size_t(options.width) * bytesPerPixel(options.format); }

// `frame` as the API's image of `options`: its pixels (none without colour) and other outputs.
Image imageOf(const CapturedFrame& frame, const RenderOptions& options, const CameraInfo& camera) {
    Image image{options.width, options.height, options.format, {}, camera, outputImagesOf(frame.outputs, options.width, options.height)};
    if (!frame.rgba8.empty() || !frame.rgba32f.empty()) {
        image.pixels.resize(packedRowBytes(options) * options.height);
        copyPixels(frame, options.format, image.pixels.data(), packedRowBytes(options));
    }
    return image;
}

// Checks the cancel flag and asks the callback; throws CancelledError for either.
void reportProgress(Device::Impl& device, const ProgressCallback& progress, const RenderProgress& where) {
    if (device.cancelled.exchange(false)) throw CancelledError();
    if (progress && !progress(where)) throw CancelledError();
}

}  // namespace

RenderSettings renderSettings(const RenderOptions& options, const scene::Scene& scene,
                              const assets::Environment* environment) {
    RenderSettings settings{.width = options.width, .height = options.height, .scene = &scene};
    settings.floatOutput = options.format != PixelFormat::Rgba8Srgb;
    settings.outputs = pixelOutputsOf(options.outputs);
    if (settings.outputs.empty()) throw UserError("RenderOptions::outputs: no output asked for; give at least one (Output::Color)");
    settings.camera = cameraSettings(options);
    settings.tonemap.op = tonemapOf(options.tonemap);
    settings.tonemap.exposureEv = options.exposureEv;
    settings.tonemap.dither = options.dither;
    settings.msaa = options.msaa;
    settings.shadingPath = shadingPathOf(options.shadingPath);
    settings.environment = environment;
    settings.ibl.rotationDegrees = options.environmentRotationDegrees;
    // With an environment the skybox is the background unless another one is asked for.
    Background background = options.background;
    constexpr float kGrey = 0x26 / 255.0f;  // #262626
    if (background.kind == Background::Kind::Auto)
        background = environment ? Background{Background::Kind::Environment, {}} : Background{Background::Kind::Color, {kGrey, kGrey, kGrey}};
    if (background.kind == Background::Kind::Environment && !environment)
        throw UserError("Background::Kind::Environment: there is no environment to show; give one, or another background");
    settings.ibl.skybox = background.kind == Background::Kind::Environment;
    if (background.kind == Background::Kind::Color)
        settings.tonemap.background = shading::srgbDecode(glm::vec3(background.srgb[0], background.srgb[1], background.srgb[2]));
    // The default key and fill lights stand in for an environment: with one, light-less scenes
    // are lit by it alone.
    if (environment) settings.defaultLights = false;
    return settings;
}

namespace {

// Starts the device `desc` describes; its start-up failures as the API's errors.
std::unique_ptr<Device::Impl> startDevice(const vk::ContextDesc& desc, const RendererOptions& options = {}) {
    std::unique_ptr<Device::Impl> impl;
    translateErrors("", [&] {
        try {
            impl = std::make_unique<Device::Impl>(desc, options);
        } catch (const UserError&) {
            throw;
        } catch (const vk::VulkanError&) {
            throw;
        } catch (const std::runtime_error& e) {
            throw DeviceError(e.what());  // no suitable device, or its start-up failed
        }
    });
    return impl;
}

}  // namespace

Device Access::device(const vk::ContextDesc& desc, const RendererOptions& options) {
    return Device(startDevice(desc, options));
}

Device::Device(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Device::Device(const DeviceOptions& options) {
    vk::ContextDesc desc;
    translateErrors("", [&] { desc = contextDescOf(options); });
    impl_ = startDevice(desc);
    impl_->iblCacheDir = iblCacheFolder(options.iblCache);
    impl_->lodCacheDir = lodCacheFolder(options.lodCache);
}
Device::Device(Device&&) noexcept = default;
Device& Device::operator=(Device&&) noexcept = default;
Device::~Device() = default;

const std::string& Device::name() const { return impl_->context.report().name; }

void Device::cancel() noexcept { impl_->cancelled = true; }

void Device::release() {
    translateErrors("", [&] { impl_->renderer.releaseScene(); });
}

uint32_t Device::validationMessages() const { return impl_->context.validationMessageCount(); }

namespace {

// Gives `held` the levels of detail its load deferred when drawing them at full detail for the
// frames drawn so far (by this process, and by earlier runs as `cacheDir` records) and the `frames`
// ahead costs more on `impl`'s device than building them, or reads the chains an earlier run built
// (geometry/lod_cache.h); the decision's line goes to the scene's report (--explain).
void provideLevelsOfDetail(Device::Impl& impl, Scene::Impl& held, uint32_t frames, float lodErrorPixels,
                           const std::filesystem::path& cacheDir) {
    scene::SceneLoadReport::GeometryPreparation& geometry = held.scene.report.geometry;
    if (!geometry.lodDeferred) return;
    const bool cpu = impl.context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const geometry::LodDecision decision =
        geometry::provideLevelsOfDetail(held.scene, held.framesDrawn, frames, lodErrorPixels,
                                        geometry::measuredTriangleCosts(cpu), hardwareThreads(), cacheDir);
    geometry.lodDecision = decision.reason;
    if (decision.build) impl.renderer.sceneReplaced();  // its index buffer grew: uploaded again
}

}  // namespace

void Access::renderFrames(Device& device, const Scene& scene, const RenderOptions& options,
                          const SequenceOptions& sequence, const CaptureSink& sink, const Environment* environment,
                          const ProgressCallback& progress, const SettingsHook& hook) {
    Device::Impl& impl = *device.impl_;
    Scene::Impl& held = *scene.impl_;
    translateErrors(held.scene.source, [&] {
        impl.cancelled = false;
        checkSequence(sequence);
        // A Scene or Environment at the address of a destroyed one the renderer drew: it is not
        // the one uploaded, whatever the address says.
        const auto replaced = [](Device::Impl::Drawn& last, const void* address, uint64_t id) {
            const bool same = last.address == address && last.id != id;
            last = {address, id};
            return same;
        };
        if (replaced(impl.lastScene, &held.scene, held.id)) impl.renderer.sceneReplaced();
        const auto* drawnEnvironment = environment ? &environment->impl_->environment : nullptr;
        if (environment && replaced(impl.lastEnvironment, drawnEnvironment, environment->impl_->id))
            impl.renderer.environmentReplaced();
        const std::optional<uint32_t> variant =
            options.variant.empty() ? std::nullopt : std::optional(scene::variantIndex(held.scene, options.variant));
        if (variant != held.variant) {
            impl.renderer.sceneReplaced();  // the draws' materials change: uploaded again
            scene::selectVariant(held.scene, variant);
            held.variant = variant;
        }
        RenderSettings settings =
            renderSettings(options, held.scene, environment ? &environment->impl_->environment : nullptr);
        settings.iblCacheDir = impl.iblCacheDir;
        settings.lodCacheDir = impl.lodCacheDir;
        pose::ScenePose pose(held.scene, pose::selectAnimations(held.scene, options.animations));
        pose.evaluate(options.time);
        settings.pose = &pose;

        const float aspect = float(settings.width) / float(settings.height);
        // Framing resolved once for the whole sequence: the camera holds still over it.
        const SequenceCamera framed = sequenceCamera(held.scene, settings.camera, aspect, pose, options, sequence);
        settings.camera = framed.camera;
        const uint32_t frames = frameCount(sequence);
        // Frame i's pose, camera and lighting, and the front end's settings for it.
        const auto setUpFrame = [&](uint32_t i) {
            if (frames > 1 && sequence.views.empty()) pose.evaluate(frameTime(options, sequence, i));
            if (!framed.orbits.empty()) settings.camera.orbit = framed.orbits[i];
            settings.ibl.rotationDegrees = frameEnvironmentRotation(options, sequence, i);
            if (hook) hook(settings);
        };
        setUpFrame(0);
        provideLevelsOfDetail(impl, held, frames, settings.drawSelection.lodErrorPixels, settings.lodCacheDir);
        held.framesDrawn += frames;
        reportProgress(impl, progress, {RenderProgress::Stage::Upload, 0, frames});
        impl.renderer.validateSettings(settings);
        impl.renderer.upload(settings);
        for (uint32_t i = 0; i < frames; ++i) {
            if (i > 0) setUpFrame(i);
            reportProgress(impl, progress, {RenderProgress::Stage::Frame, i, frames});
            const CameraInfo camera = cameraInfo(Renderer::resolveView(held.scene, settings.camera, aspect, settings.pose),
                                                 settings.width, settings.height);
            impl.lastFrame = impl.renderer.capture(settings);
            sink(i, impl.lastFrame, camera);
        }
    });
}

void Access::renderSequence(Device& device, const Scene& scene, const RenderOptions& options,
                            const SequenceOptions& sequence, const FrameCallback& onFrame,
                            const Environment* environment, const ProgressCallback& progress,
                            const SettingsHook& hook) {
    renderFrames(device, scene, options, sequence, [&](uint32_t i, const CapturedFrame& frame, const CameraInfo& camera) {
        onFrame(i, imageOf(frame, options, camera));
    }, environment, progress, hook);
}

void Device::renderSequence(const Scene& scene, const RenderOptions& options, const SequenceOptions& sequence,
                            const FrameCallback& onFrame, const Environment* environment,
                            const ProgressCallback& progress) {
    Access::renderSequence(*this, scene, options, sequence, onFrame, environment, progress, {});
}

Image Device::render(const Scene& scene, const RenderOptions& options, const Environment* environment,
                     const ProgressCallback& progress) {
    Image image;
    Access::renderFrames(*this, scene, options, {}, [&](uint32_t, const CapturedFrame& frame, const CameraInfo& camera) {
        image = imageOf(frame, options, camera);
    }, environment, progress, {});
    return image;
}

CameraInfo Device::renderInto(void* pixels, size_t rowBytes, const Scene& scene, const RenderOptions& options,
                              const Environment* environment, const ProgressCallback& progress) {
    const size_t packed = packedRowBytes(options);
    if (rowBytes < packed)
        throw InputError("", "renderInto: rows of " + std::to_string(rowBytes) + " bytes hold fewer than the " +
                                 std::to_string(options.width) + " pixels of a row (" + std::to_string(packed) + " bytes)");
    if (options.outputs != std::vector<Output>{Output::Color})
        throw InputError("", "renderInto: renders the colour image alone (RenderOptions::outputs {Output::Color}); render() gives the others");
    CameraInfo info;
    Access::renderFrames(*this, scene, options, {}, [&](uint32_t, const CapturedFrame& frame, const CameraInfo& camera) {
        copyPixels(frame, options.format, static_cast<std::byte*>(pixels), rowBytes);
        info = camera;
    }, environment, progress, {});
    return info;
}

}  // namespace candela
