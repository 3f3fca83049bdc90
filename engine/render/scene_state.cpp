#include "render/scene_state.h"

#include "core/log.h"
#include "passes/drawing/scene_blocks.h"
#include "vk/check.h"
#include "vk/context.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace candela {

namespace {

// Whether a material of `scene` has a sheen (KHR_materials_sheen) the forward pass draws.
bool anySheen(const scene::Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const scene::Material& m) { return !m.unlit && (m.layers() & scene::kLayerSheen); });
}

// Applies the user's values to each element of `items`, a runtime array of T in `reflection`
// ("Lights[i]", "Materials[i]", ...); elements for which `edited(i)` is false are left alone.
template <class T, class Edited>
void applyElements(shader::ParameterRegistry& parameters, const shader::ShaderReflection& reflection, std::vector<T>& items,
                   Edited&& edited) {
    const std::span<const shader::BlockMember> members = passes::sceneBlockElement<T>(reflection);
    const std::string prefix = std::string(passes::SceneBlock<T>::name) + "[";
    for (size_t i = 0; i < items.size(); ++i)
        if (edited(i)) parameters.apply("forward", prefix + std::to_string(i) + "]", members, items[i]);
}

ibl::IblQuality withSheen(ibl::IblQuality quality) {
    quality.sheen = true;
    return quality;
}

// Whether two vectors of plain data hold the same bytes.
template <class T>
bool same(const std::vector<T>& a, const std::vector<T>& b) {
    // (memcmp with an empty vector's null data() is undefined even for 0 bytes.)
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

SceneState::SceneState(vk::Context& context, FrameRunner& runner)
    : mContext(context), mRunner(runner), mIbl(std::make_unique<ibl_maps::IblMaps>(context)), mSheenLut(context) {}

std::vector<scene::Light> SceneState::defaultLights() {
    scene::Light key, fill;
    key.type = fill.type = scene::LightType::Directional;
    key.intensity = 3.0f;  // lux
    key.direction = glm::normalize(glm::vec3(-0.5f, -0.7f, -0.6f));
    fill.intensity = 1.0f;
    fill.direction = glm::normalize(glm::vec3(0.7f, -0.2f, -0.5f));
    fill.color = glm::vec3(0.9f, 0.95f, 1.0f);
    return {key, fill};
}

namespace {

// Which lights a frame of `choice` draws: the scene's own, the default ones, or neither.
struct LightChoice {
    bool scene = false, defaults = false;
};
LightChoice lightChoice(const SceneChoice& choice) {
    const bool scene = choice.sceneLights && !choice.scene->lights.empty();
    return {scene, choice.defaultLights && !scene};
}

}  // namespace

bool SceneState::uploads(const SceneChoice& choice) const {
    const LightChoice lights = lightChoice(choice);
    return choice.scene != mUploaded.scene || lights.defaults != mUploaded.defaultLights || lights.scene != mUploaded.sceneLights;
}

std::vector<scene::Light> SceneState::lightsOf(const SceneChoice& choice) {
    const LightChoice lights = lightChoice(choice);
    return lights.scene ? choice.scene->lights : lights.defaults ? defaultLights() : std::vector<scene::Light>{};
}

void SceneState::prepareScene(const SceneChoice& choice, passes::MaterialKeys keys) {
    const LightChoice lights = lightChoice(choice);
    const bool sceneLights = lights.scene, addLights = lights.defaults;
    // The previous scene's buffers may still be used by a frame in flight: wait first, and free
    // them before the new scene takes its memory.
    releaseScene();
    // Software rasterizers pay ~1000× for anisotropic filtering (minutes per frame on lavapipe):
    // keep it for GPUs.
    const bool cpuDevice = mContext.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    mGpuScene = std::make_unique<gpu_scene::GpuScene>(mContext, *choice.scene,
                                                  addLights ? defaultLights() : std::vector<scene::Light>{},
                                                  cpuDevice ? 1.0f : 8.0f, sceneLights);
    mKeys = std::move(keys);
    mRestPose = choice.scene->deformations.empty()
                    ? nullptr
                    : std::make_unique<pose::ScenePose>(*choice.scene, std::vector<uint32_t>{});
    mHasSheen = anySheen(*choice.scene);
    mUploaded = {choice.scene, addLights, sceneLights};
}

void SceneState::prepareEnvironment(const assets::Environment* environment, ibl::IblQuality quality,
                                    const std::filesystem::path& cacheDir) {
    // The sheen cube is computed for scenes that have a sheen (or when asked for); maps that have
    // it serve scenes without a sheen as well.
    quality.sheen = quality.sheen || mHasSheen;
    if (environment == mEnvironment && cacheDir == mIblCacheDir &&
        (quality == mIblQuality || (mIblQuality.sheen && !quality.sheen && withSheen(quality) == mIblQuality)))
        return;
    useEnvironment(environment, quality, cacheDir, false);
}

void SceneState::useEnvironment(const assets::Environment* environment, const ibl::IblQuality& quality,
                                const std::filesystem::path& cacheDir, bool force) {
    quality.validate();
    // The maps may be read by a frame in flight: wait before replacing them.
    mRunner.waitIdle();
    ibl::IblQuality effective = quality;
    for (;;) {
        try {
            mIbl->setEnvironment(environment, effective, cacheDir, force);
            break;
        } catch (const vk::OutOfDeviceMemory& e) {
            if (effective.cubeSize <= 32) throw;
            resetIblMaps();  // drops (and, once collected, frees) what the failed attempt allocated
            mRunner.waitIdle();
            effective.cubeSize /= 2;
            effective.shSourceSize = std::min(effective.shSourceSize, effective.cubeSize);
            effective.irradianceSize = std::min(effective.irradianceSize, effective.cubeSize);
            // The environment's upload shrinks too (halved, down to 4 × the cube's face).
            const uint32_t equirect = effective.equirectMaxSize ? effective.equirectMaxSize
                                                                 : std::max(environment->width, environment->height);
            effective.equirectMaxSize = std::max(equirect / 2, 4 * effective.cubeSize);
            log::warn(std::string("not enough device memory for the IBL maps (") + e.what() +
                      "): lowering the environment cube to " + std::to_string(effective.cubeSize) +
                      " texels and the environment to at most " + std::to_string(effective.equirectMaxSize) + " texels a side");
            force = true;
        }
    }
    mEnvironment = environment;
    mIblQuality = quality;
    mIblCacheDir = cacheDir;
}

void SceneState::applyParameters(shader::ParameterRegistry& parameters, const shader::ShaderReflection& reflection,
                                 const shader::ShaderReflection* layered) {
    // The scene's values with the user's applied, compared with what the buffers hold.
    std::vector<shading::LightData> lights = mGpuScene->sceneLights();
    std::vector<shading::MaterialData> materials = mGpuScene->sceneMaterials();
    std::vector<shading::MaterialLayerData> layers = mGpuScene->sceneMaterialLayers();
    const auto every = [](size_t) { return true; };
    applyElements(parameters, reflection, lights, every);
    applyElements(parameters, reflection, materials, every);
    // The layers of the materials that have some, from the layered program's reflection.
    if (layered)
        applyElements(parameters, *layered, layers, [&](size_t i) { return mGpuScene->scene().materials[i].layers() != 0; });
    if (same(lights, mGpuScene->lights()) && same(materials, mGpuScene->materials()) &&
        same(layers, mGpuScene->materialLayers()))
        return;
    // The buffers may be read by frames in flight.
    mRunner.waitIdle();
    mGpuScene->rewrite(lights, materials, layers);
}

void SceneState::frameCompleted(const graph::RenderGraph& graph) {
    mSheenLut.frameCompleted(graph);
    mIbl->frameCompleted(graph);
}

void SceneState::releaseScene() {
    mRunner.waitIdle();
    mGpuScene.reset();
    mRestPose.reset();
    mKeys = {};
    mHasSheen = false;
    mUploaded = {nullptr, false, true};
    mContext.waitIdleAndCollect();  // its memory is free now, not at a later frame's collection
}

void SceneState::sceneReplaced() {
    mRunner.waitIdle();
    mUploaded.scene = nullptr;
}

void SceneState::environmentReplaced() {
    if (mEnvironment) useEnvironment(nullptr, mIblQuality, mIblCacheDir, false);
}

void SceneState::shadersReplaced(const std::vector<std::string>& names) {
    if (std::none_of(names.begin(), names.end(), [](const std::string& n) { return n.rfind("ibl_", 0) == 0; })) return;
    resetIblMaps();
    // Recomputed (never read from the cache) by the next frame, with the new shaders.
    if (mEnvironment) useEnvironment(mEnvironment, mIblQuality, mIblCacheDir, /*force=*/true);
}

void SceneState::recomputeIbl() {
    if (mEnvironment) useEnvironment(mEnvironment, mIblQuality, {}, /*force=*/true);
}

void SceneState::resetIblMaps() {
    mRunner.waitIdle();
    mIbl = std::make_unique<ibl_maps::IblMaps>(mContext);
}

}  // namespace candela
