#pragma once
// Internal to Candela (not installed): what the public API's objects hold, and the way in for
// Candela's own front end, which renders through the API and reads what the API does not offer
// (the frame's graph and pass timings, draw statistics: app/render_command.cpp).

#include "candela/device.h"
#include "candela/render.h"
#include "candela/scene.h"
#include "assets/environment.h"
#include "core/errors.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "vk/context.h"

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace candela {

// A number no other Scene or Environment of the process has had: a Device tells a new object
// from a destroyed one that had the same address (whose uploads it holds) by it.
uint64_t newObjectId();

struct Scene::Impl {
    scene::Scene scene;
    std::optional<uint32_t> variant;  // the variant selected in `scene` (nullopt: its defaults)
    uint64_t id = newObjectId();
    // Frames drawn of it so far: with those asked next, what decides whether its levels of detail,
    // deferred at load, are built (geometry/lod_cost.h).
    uint64_t framesDrawn = 0;
};

struct Environment::Impl {
    assets::Environment environment;
    uint64_t id = newObjectId();
};

struct Device::Impl {
    Impl(const vk::ContextDesc& desc, const RendererOptions& options) : context(desc), renderer(context, options) {}
    vk::Context context;
    Renderer renderer;
    std::atomic<bool> cancelled{false};
    std::filesystem::path iblCacheDir;  // DeviceOptions::iblCache (empty: none; a front end's hook may set its own)
    std::filesystem::path lodCacheDir;  // DeviceOptions::lodCache (the same)
    CapturedFrame lastFrame;  // the last image read back (its timings: the front end's report)
    // The Scene and Environment objects last drawn (their Impl addresses, as the renderer compares
    // them, and ids): one at a known address with another id replaced a destroyed one.
    struct Drawn {
        const void* address = nullptr;
        uint64_t id = 0;
    };
    Drawn lastScene, lastEnvironment;
};

// The internal settings `options` ask for when `scene` is drawn lit by `environment` (null: none).
// Throws InputError for an animation or variant the scene does not have.
RenderSettings renderSettings(const RenderOptions& options, const scene::Scene& scene,
                              const assets::Environment* environment);

// Called with the internal settings of each frame just before it is drawn (its pose evaluated, its
// camera turned): the front end sets what its flags ask that the API does not have (debug views,
// draw selection, IBL quality...) and prints the camera it uses.
using SettingsHook = std::function<void(RenderSettings& settings)>;

struct Access {
    // A Device on the context `desc` describes, its renderer made with `options` (the viewer's
    // window system and tolerance of unknown pass names, the front end's memory budget...).
    static Device device(const vk::ContextDesc& desc, const RendererOptions& options = {});
    static Scene scene(scene::Scene scene);
    static Environment environment(assets::Environment environment);
    static Device::Impl& impl(Device& device) { return *device.impl_; }
    static Scene::Impl& impl(const Scene& scene) { return *scene.impl_; }
    static const assets::Environment& impl(const Environment& environment) { return environment.impl_->environment; }
    // Device::renderSequence's frames, each handed to `sink` as the renderer captured it (valid
    // during the call; also kept in Impl::lastFrame) with its camera, with `hook` applied to each
    // frame's settings.
    using CaptureSink = std::function<void(uint32_t index, const CapturedFrame& frame, const CameraInfo& camera)>;
    static void renderFrames(Device& device, const Scene& scene, const RenderOptions& options,
                             const SequenceOptions& sequence, const CaptureSink& sink, const Environment* environment,
                             const ProgressCallback& progress, const SettingsHook& hook);
    // Device::renderSequence with `hook` applied to each frame's settings.
    static void renderSequence(Device& device, const Scene& scene, const RenderOptions& options,
                               const SequenceOptions& sequence, const FrameCallback& onFrame,
                               const Environment* environment, const ProgressCallback& progress,
                               const SettingsHook& hook);
};

// Runs `call`, turning what Candela's internals throw into the API's errors (errors.h): UserError
// into InputError (`file` named when the message begins with it), the device's into DeviceError,
// DeviceLostError or OutOfMemoryError, InternalError and anything else into InternalFailure.
void translateErrors(const std::string& file, const std::function<void()>& call);

}  // namespace candela
