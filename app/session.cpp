// The session of a drawing command (session.h) and what render, view and bench load for it.

#include "session.h"

#include "stopwatch.h"
#include "api/access.h"
#include "assets/builtin_scenes.h"
#include "assets/gltf_loader.h"
#include "assets/procedural_sky.h"
#include "core/cache_files.h"
#include "core/log.h"
#include "pose/animation_conflicts.h"
#include "scene/material_variants.h"

#include <future>

namespace candela::app {

vk::ContextDesc contextDesc(const CommonOptions& common) {
    log::setVerbose(common.verbose);
    return {.validation = common.validate,
            .deviceSelector = common.device,
            .deviceMemoryBudget = uint64_t(common.memoryBudgetMib) << 20,
            .profile = common.deviceProfile,
            .pipelineCacheFolder = pipelineCacheFolder(common.pipelineCache)};
}

Session::Session(const CommonOptions& common) : desc_(app::contextDesc(common)) {}

Session::Session(const CommonOptions& common, const EnvironmentChoice& env) : Session(common) {
    if (std::optional<assets::Environment> loaded = loadEnvironment(env)) environment_.emplace(Access::environment(std::move(*loaded)));
}

void Session::start(const RendererOptions& options) { device_.emplace(Access::device(desc_, options)); }

Session::Started Session::loadWhileStarting(const EnvironmentChoice& env, const RendererOptions& options) {
    Started started;
    // The device's thread writes device_ and started.deviceMs/deviceError only; this one
    // environment_ and started.environmentMs.
    std::future<void> device = std::async(std::launch::async, [this, &options, &started] {
        const auto start = Clock::now();
        try {
            this->start(options);
        } catch (...) {
            started.deviceError = std::current_exception();
        }
        started.deviceMs = msSince(start);
    });
    const auto environmentStart = Clock::now();
    std::optional<assets::Environment> loaded;
    try {
        loaded = loadEnvironment(env);
    } catch (...) {
        device.wait();
        throw;
    }
    if (loaded) environment_.emplace(Access::environment(std::move(*loaded)));
    started.environmentMs = msSince(environmentStart);
    device.wait();
    return started;
}

void Session::prepareEnvironmentMaps(const SceneRenderOptions& options) {
    RenderSettings flags;
    applyRenderFlags(options, flags);
    try {
        renderer().prepareEnvironment(environment(), flags.iblQuality, flags.iblCacheDir);
    } catch (...) {
    }
}

vk::Context& Session::context() { return Access::impl(*device_).context; }
Renderer& Session::renderer() { return Access::impl(*device_).renderer; }

const assets::Environment* Session::environment() const { return environment_ ? &Access::impl(*environment_) : nullptr; }

std::unique_ptr<assets::Environment> Session::takeEnvironment() {
    if (!environment_) return nullptr;
    auto out = std::make_unique<assets::Environment>(std::move(Access::impl(*environment_)));
    environment_.reset();
    return out;
}

int Session::exitCode(int code) const {
    const uint32_t messages = device_->validationMessages();
    if (messages == 0) return code;
    log::error(std::to_string(messages) + " validation messages");
    return 3;
}

std::optional<assets::Environment> loadEnvironment(const EnvironmentChoice& choice) {
    if (choice.kind == EnvironmentChoice::Kind::None) return std::nullopt;
    assets::Environment env =
        choice.kind == EnvironmentChoice::Kind::Sky ? assets::makeProceduralSky() : assets::loadEnvironment(choice.file);
    for (const std::string& warning : env.report.warnings) log::warn(warning);
    for (const std::string& note : env.report.notes) log::info(note);
    return env;
}


scene::Scene readScene(const SceneOptions& options, const std::string& file, bool deferLevelsOfDetail) {
    return !file.empty() ? assets::loadGltf(file, {.sceneIndex = options.sceneIndex, .deferLevelsOfDetail = deferLevelsOfDetail})
                         : assets::makeSphereGrid(options.grid.value_or(7), options.distinctMaterials);
}

scene::Scene loadScene(const SceneOptions& options) {
    scene::Scene scene = readScene(options, options.scene, false);
    for (const std::string& warning : scene.report.warnings) log::warn(options.scene + ": " + warning);
    for (const std::string& note : scene.report.notes) log::info(options.scene + ": " + note);
    if (!options.variant.empty()) scene::selectVariant(scene, scene::variantIndex(scene, options.variant));
    return scene;
}

pose::ScenePose loadPose(const SceneOptions& options, const scene::Scene& scene) {
    pose::ScenePose pose(scene, pose::selectAnimations(scene, options.animations));
    pose.evaluate(options.time);
    return pose;
}

void warnAnimationConflicts(const SceneOptions& options, const scene::Scene& scene) {
    const std::vector<uint32_t> playing = pose::selectAnimations(scene, options.animations);
    const std::string line = pose::describeAnimationConflicts(scene, pose::animationConflicts(scene, playing));
    if (!line.empty()) log::warn(scene.source + ": " + line);
}

// The API's enumerations list the same choices in the same order as the flags' tables.
static_assert(int(candela::Tonemap::PbrNeutral) == int(options::Tonemap::PbrNeutral) &&
              int(candela::Tonemap::Aces) == int(options::Tonemap::Aces) && int(candela::Tonemap::Agx) == int(options::Tonemap::Agx) &&
              int(candela::Tonemap::Reinhard) == int(options::Tonemap::Reinhard) &&
              int(candela::Tonemap::Linear) == int(options::Tonemap::Linear));
static_assert(int(candela::ShadingPath::Auto) == int(options::ShadingPath::Auto) &&
              int(candela::ShadingPath::Forward) == int(options::ShadingPath::Forward) &&
              int(candela::ShadingPath::Visibility) == int(options::ShadingPath::Visibility));

candela::RenderOptions apiRenderOptions(const SceneRenderOptions& options) {
    candela::RenderOptions api;
    api.width = options.width;
    api.height = options.height;
    api.camera.gltfCamera = options.camera;
    api.camera.orbit = options.cameraOrbit;
    api.camera.target = options.target;
    api.camera.fovYDegrees = options.fovDegrees;
    api.tonemap = candela::Tonemap(int(options.tonemap));
    api.exposureEv = options.exposureEv;
    api.msaa = options.msaa;
    api.shadingPath = candela::ShadingPath(int(options.shadingPath));
    using Kind = candela::Background::Kind;
    switch (options.background.kind) {
        case Background::Kind::Auto: api.background.kind = Kind::Auto; break;
        case Background::Kind::Skybox: api.background.kind = Kind::Environment; break;
        case Background::Kind::Transparent: api.background.kind = Kind::Transparent; break;
        case Background::Kind::Color: api.background.kind = Kind::Color; break;
    }
    api.background.srgb = options.background.srgb;
    api.animations = options.animations;
    api.time = options.time;
    api.variant = options.variant;
    api.environmentRotationDegrees = options.iblLook.rotationDegrees;
    return api;
}

void applyRenderFlags(const SceneRenderOptions& options, RenderSettings& settings) {
    settings.disabledPasses = options.disabledPasses;
    if (!options.defaultLights) settings.defaultLights = false;
    settings.sceneLights = options.sceneLights;
    settings.drawSelection = {.frustumCulling = options.frustumCulling, .lodErrorPixels = options.lodErrorPixels};
    settings.shadingOptions.specularAntiAliasing = options.specularAa;
    settings.precompile = options.precompile;
    settings.shading = options.shading;
    settings.debugView = options.debugView;
    settings.iblQuality = options.iblQuality;
    // The background's skybox and the environment's rotation (--env-rotation, jittered per view)
    // come from the API's options.
    const bool skybox = settings.ibl.skybox;
    const float rotation = settings.ibl.rotationDegrees;
    settings.ibl = options.iblLook;
    settings.ibl.skybox = skybox;
    settings.ibl.rotationDegrees = rotation;
    settings.iblCacheDir = iblCacheFolder(options.iblCache);
    settings.lodCacheDir = lodCacheFolder(options.lodCache);
}

RenderSettings renderSettings(const SceneRenderOptions& options, const scene::Scene& scene,
                              const assets::Environment* environment) {
    RenderSettings settings = candela::renderSettings(apiRenderOptions(options), scene, environment);
    applyRenderFlags(options, settings);
    return settings;
}

}  // namespace candela::app
