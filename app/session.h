#pragma once
// What the drawing commands set up before their first frame: the environment that lights their
// scenes, then the device (with its pipeline cache) and a renderer on it, both held as the public
// API's objects (candela::Environment, candela::Device: render draws through the API, and the other
// commands reach the renderer inside); and the scene, pose and render settings that render, view
// and bench's flags ask for. The session holds no scene: render
// loads a batch on a loading thread and the viewer replaces its scene when a file is dropped, so
// each command holds its scenes, read by the functions below.

#include "cli.h"
#include "candela/device.h"
#include "candela/render.h"
#include "assets/environment.h"
#include "pose/scene_pose.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "vk/context.h"

#include <exception>
#include <memory>
#include <optional>
#include <string>

namespace candela::app {

// The context description the common flags ask for (with the pipeline cache's folder:
// --pipeline-cache, else the user's cache folder). Sets the log's verbosity (--verbose).
vk::ContextDesc contextDesc(const CommonOptions& common);

class Session {
public:
    // Loads the environment `env` asks for: a file, the procedural sky, or none; its warnings are
    // logged, and its notes with --verbose. The device does not start yet (start()).
    Session(const CommonOptions& common, const EnvironmentChoice& env);
    // Loads no environment yet: loadWhileStarting() does, with the device's start.
    explicit Session(const CommonOptions& common);
    Session(const Session&) = delete;  // the renderer points at the context
    Session& operator=(const Session&) = delete;

    // The description the device will start from; before start(), a caller may add to it (the
    // viewer's window system: ui::WindowSystem::addTo).
    vk::ContextDesc& contextDesc() { return desc_; }
    // Starts the device and a renderer made with `options`. Precondition: not started.
    void start(const RendererOptions& options = {});
    // What loadWhileStarting() took, each on its own thread.
    struct Started {
        double environmentMs = 0.0;      // loading (or making) the environment
        double deviceMs = 0.0;           // starting the device and the renderer
        std::exception_ptr deviceError;  // why the device did not start; null when it did
    };
    // Loads the environment `env` asks for (as the constructor that takes it does) while the device
    // and a renderer made with `options` start on a thread of their own (start()): neither needs
    // the other, and a device's start is the longest wait before a single render's first frame on a
    // GPU (docs/measurements.md). An environment's error is thrown, once the device's thread has
    // ended, whether or not the device started (as when the device started only after it); a
    // device's failure is returned, for the caller to report when it chooses. Preconditions: made
    // by Session(common), not started.
    Started loadWhileStarting(const EnvironmentChoice& env, const RendererOptions& options = {});
    // Precondition: started.
    candela::Device& device() { return *device_; }
    vk::Context& context();
    Renderer& renderer();

    // The environment; null for --env none.
    const assets::Environment* environment() const;
    // Gives the renderer the environment's maps for frames of `options`, as a render's upload would
    // (read from the IBL cache, or their precompute set up), before it has the scene: a single
    // render does this while its file loads. A failure is left to the upload, which asks again and
    // reports it as a scene's failure. Precondition: started.
    void prepareEnvironmentMaps(const SceneRenderOptions& options);
    const candela::Environment* apiEnvironment() const { return environment_ ? &*environment_ : nullptr; }
    // Hands the environment over (to the viewer, which owns what it draws); null for --env none.
    std::unique_ptr<assets::Environment> takeEnvironment();

    // `code`, or 3 when the device reported validation messages (their number logged as an
    // error): the exit code of a command that drew on it. Precondition: started.
    int exitCode(int code) const;

private:
    vk::ContextDesc desc_;
    std::optional<candela::Environment> environment_;
    std::optional<candela::Device> device_;
};

// The environment `choice` asks for (nullopt: none), its warnings logged, and its notes with --verbose.
std::optional<assets::Environment> loadEnvironment(const EnvironmentChoice& choice);
// The scene of `file` (a glTF file; "": the built-in sphere grid --grid and --distinct-materials
// ask for), as read: nothing logged, the default variant; its levels of detail built, or left for
// the API to build if they pay (`deferLevelsOfDetail`: geometry/lod_cost.h). Safe to call on
// another thread.
scene::Scene readScene(const SceneOptions& options, const std::string& file, bool deferLevelsOfDetail);
// readScene of --scene with its warnings logged (notes with --verbose) and --variant selected, its
// levels of detail built (the viewer and bench draw frames without end, or many).
scene::Scene loadScene(const SceneOptions& options);
// The pose --animation and --time ask for (a UserError names the scene's animations when one
// does not exist). Precondition: `scene` outlives it.
pose::ScenePose loadPose(const SceneOptions& options, const scene::Scene& scene);
// Logs one warning naming the scene when the animations --animation asks for drive the same
// channels (which, and which wins: pose::describeAnimationConflicts); nothing otherwise.
void warnAnimationConflicts(const SceneOptions& options, const scene::Scene& scene);
// What the flags of render, view and bench ask of the public API's render options (undithered:
// render and bench set --dither, the viewer always dithers).
candela::RenderOptions apiRenderOptions(const SceneRenderOptions& options);
// What those flags ask that the API does not offer (debug views, draw selection, lights, IBL
// quality and look...), set in the settings the API made from apiRenderOptions.
void applyRenderFlags(const SceneRenderOptions& options, RenderSettings& settings);
// The render settings the flags choose: the API's settings for apiRenderOptions, with
// applyRenderFlags. Precondition: `scene` and `environment` outlive them.
RenderSettings renderSettings(const SceneRenderOptions& options, const scene::Scene& scene,
                              const assets::Environment* environment);

}  // namespace candela::app
