// candela::Device (candela/device.h): a vk::Context and a Renderer; the public render options
// turned into the renderer's settings; frames read back into the public pixel formats.

#include "api/access.h"
#include "candela/device.h"
#include "core/cache_files.h"
#include "options/device_profile.h"
#include "pose/scene_pose.h"
#include "scene/camera.h"
#include "scene/material_variants.h"
#include "shared/tonemap.h"
#include "vk/check.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <cmath>
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

// An image of the size and format `options` ask for, its pixels zero. Made once the renderer has
// accepted the size (a size beyond the device's limit is an InputError, not an allocation).
Image blankImage(const RenderOptions& options) {
    return {options.width, options.height, options.format, std::vector<std::byte>(packedRowBytes(options) * options.height)};
}

// Checks the cancel flag and asks the callback; throws CancelledError for either.
void reportProgress(Device::Impl& device, const ProgressCallback& progress, const RenderProgress& where) {
    if (device.cancelled.exchange(false)) throw CancelledError();
    if (progress && !progress(where)) throw CancelledError();
}

glm::vec3 vec3Of(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

// The renderer's camera settings for `options` (intrinsics as fractions of the image).
CameraSettings cameraSettings(const RenderOptions& options) {
    const Camera& camera = options.camera;
    CameraSettings out;
    out.gltfCamera = camera.gltfCamera;
    if (camera.orbit) out.orbit = vec3Of(*camera.orbit);
    if (camera.target) out.target = vec3Of(*camera.target);
    out.fovYDegrees = camera.fovYDegrees;
    if (camera.cameraToWorld) {
        glm::mat4 m;
        std::memcpy(&m[0][0], camera.cameraToWorld->data(), sizeof(m));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r])) throw UserError("Camera::cameraToWorld: a value is not finite");
        if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
            throw UserError("Camera::cameraToWorld: the last row is not 0 0 0 1");
        if (std::abs(glm::determinant(glm::mat3(m))) < 1e-12f) throw UserError("Camera::cameraToWorld: the matrix is singular");
        out.cameraToWorld = m;
    }
    if (camera.intrinsics) {
        const auto& k = *camera.intrinsics;
        for (float value : k)
            if (!std::isfinite(value)) throw UserError("Camera::intrinsics: a value is not finite");
        if (!(k[0] > 0.0f && k[1] > 0.0f)) throw UserError("Camera::intrinsics: the focal lengths fx and fy must be positive");
        const float width = float(std::max(options.width, 1u)), height = float(std::max(options.height, 1u));
        out.intrinsics = scene::Intrinsics{.fx = k[0] / width, .fy = k[1] / height, .cx = k[2] / width, .cy = k[3] / height};
    }
    return out;
}

// The camera of `view` for an image of width × height, as the API reports it.
CameraInfo cameraInfo(const scene::ViewSetup& view, uint32_t width, uint32_t height) {
    CameraInfo info{.width = width, .height = height};
    const glm::mat4 cameraToWorld = glm::inverse(view.view);
    std::memcpy(info.cameraToWorld.data(), &cameraToWorld[0][0], sizeof(cameraToWorld));
    std::memcpy(info.projection.data(), &view.projection[0][0], sizeof(view.projection));
    const glm::mat4& p = view.projection;
    info.orthographic = p[2][3] == 0.0f;  // w does not depend on depth
    if (info.orthographic) {
        info.xmag = 1.0f / p[0][0];
        info.ymag = -1.0f / p[1][1];
        info.zfar = p[3][2] / p[2][2];
        info.znear = info.zfar - 1.0f / p[2][2];
        return info;
    }
    const scene::Intrinsics k = scene::intrinsicsOf(p);
    info.intrinsics = {k.fx * float(width), k.fy * float(height), k.cx * float(width), k.cy * float(height)};
    info.fovYDegrees = glm::degrees(2.0f * std::atan(0.5f / k.fy));
    info.znear = view.znear;
    if (p[2][2] != 0.0f) info.zfar = p[3][2] / p[2][2];
    return info;
}

// The orbit camera's (θ°, φ°, r) for each frame of a turntable or of views, r fixed at the largest
// distance any frame's framing needs (framing from each direction would move the camera in and
// out) unless the orbit gives one; empty when the sequence is neither, or is not of the orbit camera.
std::vector<glm::vec3> sequenceOrbits(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                      const pose::ScenePose& pose, const SequenceOptions& sequence) {
    const bool turntable = sequence.views.empty() && sequence.frames > 1 && sequence.turntableDegrees != 0.0f;
    if (!turntable && sequence.views.empty()) return {};
    if (camera.gltfCamera || camera.cameraToWorld) {
        if (turntable) return {};  // a turntable of a fixed camera: it does not turn (as ever)
        throw UserError("views of a scene need the orbit camera, not a glTF or placed camera");
    }
    const glm::vec3 base = camera.orbit.value_or(glm::vec3(scene::defaultOrbitAngles(scene), 0.0f));
    std::vector<glm::vec3> orbits;
    for (uint32_t i = 0; i < frameCount(sequence); ++i)
        orbits.push_back(turntable ? base + glm::vec3(sequence.turntableDegrees * float(i) / float(sequence.frames), 0.0f, 0.0f)
                                   : glm::vec3(sequence.views[i][0], sequence.views[i][1], base.z));
    if (base.z <= 0.0f) {
        CameraSettings framed = camera;
        float radius = 0.0f;
        for (const glm::vec3& orbit : orbits) {
            framed.orbit = glm::vec3(orbit.x, orbit.y, 0.0f);
            radius = std::max(radius, Renderer::orbitCamera(scene, framed, aspect, &pose).radius);
        }
        for (glm::vec3& orbit : orbits) orbit.z = radius;
    }
    return orbits;
}

// The further turn of frame i's environment with jittered lighting: 360° × a uniform number from
// (seed, i) by SplitMix64, the same on every machine.
float lightingJitterDegrees(uint64_t seed, uint32_t i) {
    uint64_t z = seed + (uint64_t(i) + 1) * 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return float(double(z >> 11) * 0x1.0p-53 * 360.0);
}

void checkSequence(const SequenceOptions& sequence) {
    if (!sequence.views.empty()) {
        for (const auto& view : sequence.views)
            if (!std::isfinite(view[0]) || !std::isfinite(view[1])) throw UserError("a view direction is not finite");
        return;
    }
    if (sequence.frames == 0) throw UserError("an image sequence of 0 frames");
    if (!(sequence.fps > 0.0)) throw UserError("an image sequence at " + std::to_string(sequence.fps) + " frames per second");
}

// The time of frame i: views are all of one pose.
double frameTime(const RenderOptions& options, const SequenceOptions& sequence, uint32_t i) {
    return sequence.views.empty() ? options.time + double(i) / sequence.fps : options.time;
}

float frameEnvironmentRotation(const RenderOptions& options, const SequenceOptions& sequence, uint32_t i) {
    return options.environmentRotationDegrees + (sequence.lightingSeed ? lightingJitterDegrees(*sequence.lightingSeed, i) : 0.0f);
}

}  // namespace

RenderSettings renderSettings(const RenderOptions& options, const scene::Scene& scene,
                              const assets::Environment* environment) {
    RenderSettings settings{.width = options.width, .height = options.height, .scene = &scene};
    settings.floatOutput = options.format != PixelFormat::Rgba8Srgb;
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
        pose::ScenePose pose(held.scene, pose::selectAnimations(held.scene, options.animations));
        pose.evaluate(options.time);
        settings.pose = &pose;

        const float aspect = float(settings.width) / float(settings.height);
        const std::vector<glm::vec3> orbits = sequenceOrbits(held.scene, settings.camera, aspect, pose, sequence);
        const uint32_t frames = frameCount(sequence);
        // Frame i's pose, camera and lighting, and the front end's settings for it.
        const auto setUpFrame = [&](uint32_t i) {
            if (frames > 1 && sequence.views.empty()) pose.evaluate(frameTime(options, sequence, i));
            if (!orbits.empty()) settings.camera.orbit = orbits[i];
            settings.ibl.rotationDegrees = frameEnvironmentRotation(options, sequence, i);
            if (hook) hook(settings);
        };
        setUpFrame(0);
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

RenderOptions sequenceFrame(const Scene& scene, const RenderOptions& options, const SequenceOptions& sequence,
                            uint32_t index) {
    const scene::Scene& held = Access::impl(scene).scene;
    RenderOptions out = options;
    translateErrors(held.source, [&] {
        checkSequence(sequence);
        if (index >= frameCount(sequence))
            throw UserError("frame " + std::to_string(index) + " of a sequence of " + std::to_string(frameCount(sequence)));
        if (options.width == 0 || options.height == 0) throw UserError("an image of " + std::to_string(options.width) + "x" + std::to_string(options.height) + " pixels");
        pose::ScenePose pose(held, pose::selectAnimations(held, options.animations));
        pose.evaluate(options.time);
        const float aspect = float(options.width) / float(options.height);
        out.time = frameTime(options, sequence, index);
        out.environmentRotationDegrees = frameEnvironmentRotation(options, sequence, index);
        const std::vector<glm::vec3> orbits = sequenceOrbits(held, cameraSettings(options), aspect, pose, sequence);
        if (!orbits.empty()) out.camera.orbit = std::array<float, 3>{orbits[index].x, orbits[index].y, orbits[index].z};
    });
    return out;
}

std::vector<std::array<float, 2>> sphereViews(uint32_t count) {
    std::vector<std::array<float, 2>> views;
    const double golden = 180.0 * (3.0 - std::sqrt(5.0));  // 137.5°
    for (uint32_t i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count;  // cos φ at equal steps
        views.push_back({float(std::fmod(golden * i, 360.0)), float(glm::degrees(std::acos(y)))});
    }
    return views;
}

std::vector<std::array<float, 2>> ringViews(uint32_t count, float elevationDegrees) {
    std::vector<std::array<float, 2>> views;
    for (uint32_t i = 0; i < count; ++i) views.push_back({360.0f * float(i) / float(count), 90.0f - elevationDegrees});
    return views;
}

Camera lookAt(const std::array<float, 3>& eye, const std::array<float, 3>& target, const std::array<float, 3>& up) {
    Camera camera;
    translateErrors("", [&] {
        const glm::vec3 from = vec3Of(eye), to = vec3Of(target), upward = vec3Of(up);
        const float distance = glm::length(to - from);
        if (!std::isfinite(distance) || !(distance > 0.0f)) throw UserError("lookAt: the eye and the target are one point");
        if (glm::length(glm::cross((to - from) / distance, upward)) < 1e-6f * glm::length(upward) || glm::length(upward) == 0.0f)
            throw UserError("lookAt: the up vector is parallel to the line of sight");
        const glm::mat4 cameraToWorld = glm::inverse(glm::lookAt(from, to, upward));
        camera.cameraToWorld.emplace();
        std::memcpy(camera.cameraToWorld->data(), &cameraToWorld[0][0], sizeof(cameraToWorld));
    });
    return camera;
}

void Access::renderSequence(Device& device, const Scene& scene, const RenderOptions& options,
                            const SequenceOptions& sequence, const FrameCallback& onFrame,
                            const Environment* environment, const ProgressCallback& progress,
                            const SettingsHook& hook) {
    Image image;
    renderFrames(device, scene, options, sequence, [&](uint32_t i, const CapturedFrame& frame, const CameraInfo& camera) {
        if (i == 0) image = blankImage(options);
        copyPixels(frame, options.format, image.pixels.data(), packedRowBytes(options));
        image.camera = camera;
        onFrame(i, image);
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
        image = blankImage(options);
        copyPixels(frame, options.format, image.pixels.data(), packedRowBytes(options));
        image.camera = camera;
    }, environment, progress, {});
    return image;
}

CameraInfo Device::renderInto(void* pixels, size_t rowBytes, const Scene& scene, const RenderOptions& options,
                              const Environment* environment, const ProgressCallback& progress) {
    const size_t packed = packedRowBytes(options);
    if (rowBytes < packed)
        throw InputError("", "renderInto: rows of " + std::to_string(rowBytes) + " bytes hold fewer than the " +
                                 std::to_string(options.width) + " pixels of a row (" + std::to_string(packed) + " bytes)");
    CameraInfo info;
    Access::renderFrames(*this, scene, options, {}, [&](uint32_t, const CapturedFrame& frame, const CameraInfo& camera) {
        copyPixels(frame, options.format, static_cast<std::byte*>(pixels), rowBytes);
        info = camera;
    }, environment, progress, {});
    return info;
}

}  // namespace candela
