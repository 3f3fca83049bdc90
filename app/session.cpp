// The session of a drawing command (session.h) and what render, view and bench load for it.

#include "session.h"

#include "assets/builtin_scenes.h"
#include "assets/gltf_loader.h"
#include "assets/procedural_sky.h"
#include "core/cache_files.h"
#include "core/log.h"
#include "pose/animation_conflicts.h"
#include "scene/material_variants.h"
#include "shared/tonemap.h"

namespace candela::app {

vk::ContextDesc contextDesc(const CommonOptions& common) {
    log::setVerbose(common.verbose);
    return {.validation = common.validate,
            .deviceSelector = common.device,
            .deviceMemoryBudget = uint64_t(common.memoryBudgetMib) << 20,
            .profile = common.deviceProfile,
            .pipelineCacheFolder = common.pipelineCache == "off" ? std::filesystem::path()
                                   : common.pipelineCache.empty() ? userCacheFolder()
                                                                  : std::filesystem::path(common.pipelineCache)};
}

Session::Session(const CommonOptions& common, const EnvironmentChoice& env)
    : desc_(app::contextDesc(common)), environment_(loadEnvironment(env)) {}

void Session::start(const RendererOptions& options) {
    context_.emplace(desc_);
    renderer_.emplace(*context_, options);
}

std::unique_ptr<assets::Environment> Session::takeEnvironment() {
    if (!environment_) return nullptr;
    auto out = std::make_unique<assets::Environment>(std::move(*environment_));
    environment_.reset();
    return out;
}

int Session::exitCode(int code) const {
    if (context_->validationMessageCount() == 0) return code;
    log::error(std::to_string(context_->validationMessageCount()) + " validation messages");
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


scene::Scene readScene(const SceneOptions& options, const std::string& file) {
    return !file.empty() ? assets::loadGltf(file, {.sceneIndex = options.sceneIndex})
                         : assets::makeSphereGrid(options.grid.value_or(7), options.distinctMaterials);
}

scene::Scene loadScene(const SceneOptions& options) {
    scene::Scene scene = readScene(options, options.scene);
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

RenderSettings renderSettings(const SceneRenderOptions& options, const scene::Scene& scene,
                              const assets::Environment* environment) {
    RenderSettings settings{.width = options.width, .height = options.height, .scene = &scene};
    settings.disabledPasses = options.disabledPasses;
    settings.defaultLights = options.defaultLights;
    settings.sceneLights = options.sceneLights;
    settings.drawSelection = {.frustumCulling = options.frustumCulling, .lodErrorPixels = options.lodErrorPixels};
    settings.shadingOptions.specularAntiAliasing = options.specularAa;
    settings.msaa = options.msaa;
    settings.precompile = options.precompile;
    settings.shadingPath = options.shadingPath;
    if (options.camera) settings.camera.gltfCamera = *options.camera;
    if (options.cameraOrbit) settings.camera.orbit = glm::vec3((*options.cameraOrbit)[0], (*options.cameraOrbit)[1], (*options.cameraOrbit)[2]);
    if (options.target) settings.camera.target = glm::vec3((*options.target)[0], (*options.target)[1], (*options.target)[2]);
    settings.camera.fovYDegrees = options.fovDegrees;
    settings.shading = options.shading;
    settings.tonemap.op = options.tonemap;
    settings.debugView = options.debugView;
    settings.tonemap.exposureEv = options.exposureEv;
    settings.environment = environment;
    settings.iblQuality = options.iblQuality;
    settings.ibl = options.iblLook;
    settings.iblCacheDir = options.iblCache;
    // With an environment the skybox is the background unless another one is asked for.
    Background background = options.background;
    constexpr float kGrey = 0x26 / 255.0f;  // #262626
    if (background.kind == Background::Kind::Auto)
        background = environment ? Background{Background::Kind::Skybox} : Background{Background::Kind::Color, {kGrey, kGrey, kGrey}};
    settings.ibl.skybox = background.kind == Background::Kind::Skybox;
    if (background.kind == Background::Kind::Color)
        settings.tonemap.background = shading::srgbDecode(glm::vec3(background.srgb[0], background.srgb[1], background.srgb[2]));
    // The default key and fill lights stand in for an environment: with one, light-less scenes
    // are lit by it alone.
    if (environment) settings.defaultLights = false;
    return settings;
}

}  // namespace candela::app
