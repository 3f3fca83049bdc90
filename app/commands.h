#pragma once
// The `candela` subcommands. Each returns the process exit code; user errors are thrown as
// candela::UserError and reported by main().

#include "assets/environment.h"
#include "cli.h"
#include "pose/scene_pose.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "vk/context.h"

#include <filesystem>
#include <initializer_list>
#include <optional>

namespace candela::app {

int runRender(const RenderOptions& options);
int runBench(const RenderOptions& options);
int runView(const RenderOptions& options);
int runInfo(const InfoOptions& options);
int runIblReport(const IblReportOptions& options);
int runSoak(const SoakOptions& options);
int runScaleReport(const ScaleReportOptions& options);
int runQualityReport(const QualityReportOptions& options);
int runDiff(const DiffOptions& options);

// Shared by render and bench: the context description (with the pipeline cache's folder:
// --pipeline-cache, else the user's cache folder) and the render settings the flags choose.
vk::ContextDesc contextDesc(const CommonOptions& common);
// The scene of `file` (a glTF file; "": the built-in sphere grid --grid and --distinct-materials
// ask for), as read: nothing logged, the default variant. Safe to call on another thread.
scene::Scene readScene(const RenderOptions& options, const std::string& file);
// readScene of --scene with its warnings logged (notes with --verbose) and --variant selected.
scene::Scene loadScene(const RenderOptions& options);
// The environment --env asks for: a file, the procedural sky, or none (nullopt). Its warnings are
// logged, and its notes with --verbose.
std::optional<scene::Environment> loadEnvironment(const EnvironmentChoice& choice);
// The pose --animation and --time ask for (a UserError names the scene's animations when one
// does not exist). Precondition: `scene` outlives it.
scene::ScenePose loadPose(const RenderOptions& options, const scene::Scene& scene);
// Logs one warning naming the scene when the animations --animation asks for drive the same
// channels (which, and which wins: scene::describeAnimationConflicts); nothing otherwise.
void warnAnimationConflicts(const RenderOptions& options, const scene::Scene& scene);
// Writes `text` to the file `path` (replacing it); a UserError "PATH: cannot write" otherwise.
void writeText(const std::string& path, const std::string& text);
// Creates the report folder `out` and checks that each of `files` can be written in it; a
// UserError names the folder or file otherwise (ibl-report, scale-report).
void prepareReportFolder(const std::filesystem::path& out, std::initializer_list<const char*> files);
// Precondition: `scene` and `environment` outlive the settings.
RenderSettings renderSettings(const RenderOptions& options, const scene::Scene& scene,
                              const scene::Environment* environment);

}  // namespace candela::app
