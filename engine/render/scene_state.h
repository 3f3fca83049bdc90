#pragma once
// SceneState: what the device holds of the scene a frame draws — the uploaded scene (GpuScene)
// and its materials' keys, the rest pose of a deformable scene, the image-based-lighting maps of
// the environment (with the memory fallback), the sheen LUT — and the user's edits of its lights
// and materials (through the parameter registry), written into its buffers. It decides when to
// upload: a different scene, a different light choice, a different environment or quality.
// Anything it replaces may be read by frames in flight: it waits for them first (FrameRunner).

#include "assets/environment.h"
#include "gpu_scene/gpu_scene.h"
#include "ibl/ibl_settings.h"
#include "ibl_maps/ibl_maps.h"
#include "ibl_maps/sheen_lut.h"
#include "passes/drawing/draw_list.h"
#include "pose/scene_pose.h"
#include "render/frame_runner.h"
#include "shader/parameter_registry.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace candela {

// The scene a frame draws, as far as the device is concerned.
struct SceneChoice {
    const scene::Scene* scene = nullptr;
    bool defaultLights = true;  // a scene without punctual lights gets a key and a fill light
    bool sceneLights = true;    // the scene's own punctual lights (false: left out)
};

class SceneState {
public:
    // Preconditions: `context` and `runner` outlive the state.
    SceneState(vk::Context& context, FrameRunner& runner);

    // Uploads `choice` (the passes then bind the new scene). `keys` are its materials'
    // (passes::MaterialKeys::of(*choice.scene)), computed once by the caller, who also queues their
    // pipelines ahead of the upload. Precondition: uploads(choice).
    void prepareScene(const SceneChoice& choice, passes::MaterialKeys keys);
    // Whether `choice` is not what is uploaded (prepareScene(choice) is then due).
    bool uploads(const SceneChoice& choice) const;
    // The punctual lights a frame of `choice` draws: the scene's own (sceneLights, when it has
    // some), else the default key and fill (defaultLights), else none.
    static std::vector<scene::Light> lightsOf(const SceneChoice& choice);
    // Gives the maps `environment` at `quality` (the sheen cube when `quality` asks for it or a
    // material has a sheen; maps with it also serve scenes without) unless they have it already.
    // Before any scene (Renderer::prepareEnvironment), no material has a sheen: a scene with one
    // asks again.
    void prepareEnvironment(const assets::Environment* environment, ibl::IblQuality quality,
                            const std::filesystem::path& cacheDir);
    // Waits for the GPU and gives the maps this environment and quality (see IblMaps::setEnvironment);
    // out of device memory, lowers the cube size (with a warning) rather than fail. `force`:
    // recompute, never read from the cache.
    void useEnvironment(const assets::Environment* environment, const ibl::IblQuality& quality,
                        const std::filesystem::path& cacheDir, bool force);
    // Runs the scene's lights and materials through `parameters` (their blocks in the forward
    // program's `reflection` and, for layers, `layered`); rewrites their buffers (after waiting for
    // the GPU) when the user changed one.
    void applyParameters(shader::ParameterRegistry& parameters, const shader::ShaderReflection& reflection,
                         const shader::ShaderReflection* layered);

    // The last frame completed: the maps and the sheen LUT take over what it computed.
    void frameCompleted(const graph::RenderGraph& graph);
    // The Scene object last drawn was replaced in place: the next frame uploads it anew.
    void sceneReplaced();
    // The Environment object last used was replaced in place: its maps are dropped (after waiting
    // for the GPU) and the next frame computes (or reads from the cache) the new one's.
    void environmentReplaced();
    // Frees what the device holds of the uploaded scene (after waiting for the frames in flight);
    // the next frame uploads its scene, whatever its address. The maps stay.
    void releaseScene();
    // After shaders were replaced: a replaced IBL shader discards the maps (computed again).
    void shadersReplaced(const std::vector<std::string>& names);
    // The next frame runs the IBL precompute again (not from the cache).
    void recomputeIbl();

    const gpu_scene::GpuScene& gpuScene() const { return *mGpuScene; }
    bool hasGpuScene() const { return mGpuScene != nullptr; }
    const passes::MaterialKeys& materialKeys() const { return mKeys; }
    // The rest pose of an uploaded scene with skins or morph targets (drawn when a frame brings no
    // pose of its own: skinned meshes are placed by their joints even at rest); null otherwise.
    const pose::ScenePose* restPose() const { return mRestPose.get(); }
    bool defaultLightsAdded() const { return mUploaded.defaultLights; }
    bool sceneLightsUsed() const { return mUploaded.sceneLights; }
    bool hasSheen() const { return mHasSheen; }
    ibl_maps::IblMaps& iblMaps() { return *mIbl; }
    ibl_maps::SheenLut& sheenLut() { return mSheenLut; }

    // The key and fill lights added to scenes without lights (SceneChoice::defaultLights).
    static std::vector<scene::Light> defaultLights();

private:
    void resetIblMaps();  // new, empty maps (after waiting for the frames in flight)

    vk::Context& mContext;
    FrameRunner& mRunner;
    std::unique_ptr<gpu_scene::GpuScene> mGpuScene;
    passes::MaterialKeys mKeys;
    std::unique_ptr<pose::ScenePose> mRestPose;
    SceneChoice mUploaded{nullptr, false, true};  // what mGpuScene holds (lights as resolved)
    bool mHasSheen = false;
    // Replaced whole when reset (a failed allocation's leftovers go with the old object).
    std::unique_ptr<ibl_maps::IblMaps> mIbl;
    ibl_maps::SheenLut mSheenLut;
    // What mIbl was last set up with (the environment is re-hashed only when these change).
    const assets::Environment* mEnvironment = nullptr;
    ibl::IblQuality mIblQuality;
    std::filesystem::path mIblCacheDir;
};

}  // namespace candela
