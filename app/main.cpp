// The `candela` executable: parses the command line and runs a subcommand. Every error reaches the
// user as one line on stderr and a non-zero exit code.

#include "commands.h"
#include "assets/builtin_scenes.h"
#include "assets/gltf_loader.h"
#include "assets/image_file.h"
#include "assets/procedural_sky.h"
#include "core/cache_files.h"
#include "core/log.h"
#include "pose/animation_conflicts.h"
#include "render/renderer.h"
#include "render/visibility_path.h"
#include "scene/material_variants.h"
#include "shared/tonemap.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/device_select.h"

#include <cstdio>
#include <fstream>

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

scene::Scene readScene(const RenderOptions& options, const std::string& file) {
    return !file.empty() ? scene::loadGltf(file, {.sceneIndex = options.sceneIndex})
                         : scene::makeSphereGrid(options.grid.value_or(7), options.distinctMaterials);
}

scene::Scene loadScene(const RenderOptions& options) {
    scene::Scene scene = readScene(options, options.scene);
    for (const std::string& warning : scene.warnings) log::warn(options.scene + ": " + warning);
    for (const std::string& note : scene.notes) log::info(options.scene + ": " + note);
    if (!options.variant.empty()) scene::selectVariant(scene, scene::variantIndex(scene, options.variant));
    return scene;
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw UserError(path + ": cannot write");
}

void prepareReportFolder(const std::filesystem::path& out, std::initializer_list<const char*> files) {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) throw UserError(out.string() + ": cannot create the report folder: " + ec.message());
    for (const char* file : files) io::checkWritable(out / file);
}

scene::ScenePose loadPose(const RenderOptions& options, const scene::Scene& scene) {
    scene::ScenePose pose(scene, scene::selectAnimations(scene, options.animations));
    pose.evaluate(options.time);
    return pose;
}

void warnAnimationConflicts(const RenderOptions& options, const scene::Scene& scene) {
    const std::vector<uint32_t> playing = scene::selectAnimations(scene, options.animations);
    const std::string line = scene::describeAnimationConflicts(scene, scene::animationConflicts(scene, playing));
    if (!line.empty()) log::warn(scene.source + ": " + line);
}

std::optional<scene::Environment> loadEnvironment(const EnvironmentChoice& choice) {
    if (choice.kind == EnvironmentChoice::Kind::None) return std::nullopt;
    scene::Environment env =
        choice.kind == EnvironmentChoice::Kind::Sky ? scene::makeProceduralSky() : scene::loadEnvironment(choice.file);
    for (const std::string& warning : env.warnings) log::warn(warning);
    for (const std::string& note : env.notes) log::info(note);
    return env;
}


RenderSettings renderSettings(const RenderOptions& options, const scene::Scene& scene,
                              const scene::Environment* environment) {
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
    settings.tonemap.dither = options.dither;
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

namespace {
std::string apiVersion(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

}  // namespace

int runInfo(const InfoOptions& options) {
    vk::ContextDesc desc = contextDesc(options.common);
    desc.pipelineCacheFolder.clear();  // info builds no pipeline: it neither reads nor writes the cache
    vk::Context context(desc);
    // List every device the loader sees, with the reason it is or is not usable.
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(context.instance(), &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(context.instance(), &count, devices.data()));
    std::printf("Vulkan devices:\n");
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devices[i], &p);
        std::printf("  [%u] %s (%s, Vulkan %s)%s\n", i, p.deviceName, vk::deviceTypeName(p.deviceType),
                    apiVersion(p.apiVersion).c_str(), devices[i] == context.physicalDevice() ? "  <- chosen" : "");
    }
    const vk::DeviceReport& r = context.report();
    std::printf("chosen: %s (%s)\n  why: %s\n  API version: %s\n  driver: %s %s\n", r.name.c_str(), r.type.c_str(),
                r.reason.c_str(), apiVersion(r.apiVersion).c_str(), r.driverName.c_str(), r.driverInfo.c_str());
    std::printf("  queue families: graphics %u, compute %u, transfer %u\n", r.graphicsFamily, r.computeFamily,
                r.transferFamily);
    std::printf("  timestamps: %s\n", r.timestampValidBits
                                          ? (std::to_string(r.timestampValidBits) + " valid bits, period " +
                                             std::to_string(r.timestampPeriodNs) + " ns")
                                                .c_str()
                                          : "not supported");
    const vk::MsaaChoice msaa = vk::chooseMsaa(context.properties().deviceType, context.attachmentSampleCounts(), std::nullopt);
    std::printf("  MSAA: %s; supported: %s\n", msaa.reason.c_str(), vk::sampleCountList(context.attachmentSampleCounts()).c_str());
    const auto [shadingPath, shadingWhy] = defaultShadingPath(context);
    std::printf("  shading path: %s (%s; --shading-path)\n", passes::shadingPathName(shadingPath), shadingWhy.c_str());
    const vk::DeviceCaps& caps = context.caps();
    std::printf("  device profile: %s (%s)\n", r.profile.c_str(), vk::deviceProfileSource(context.profile()));
    std::printf("  per-stage limits: %u samplers, %u sampled images, %u storage buffers, %u storage images\n",
                caps.limits.maxPerStageDescriptorSamplers, caps.limits.maxPerStageDescriptorSampledImages,
                caps.limits.maxPerStageDescriptorStorageBuffers, caps.limits.maxPerStageDescriptorStorageImages);
    std::printf("  sizes: storage buffer range %s, allocation %s, buffer %s, 2D image %u\n",
                formatBytes(caps.limits.maxStorageBufferRange).c_str(), formatBytes(caps.limits.maxMemoryAllocationSize).c_str(),
                formatBytes(caps.limits.maxBufferSize).c_str(), caps.limits.maxImageDimension2D);
    std::printf("  memory: %s; %s\n",
                caps.hasMemoryType(VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT) ? "lazily allocated memory for transient attachments"
                                                                            : "no lazily allocated memory",
                caps.hasMemoryType(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
                    ? "per-frame data in host-visible device-local memory"
                    : "per-frame data in system memory");
    const auto heaps = context.allocator().heapBudgets();
    std::printf("  heap budgets (VK_EXT_memory_budget):%s", heaps.empty() ? " not available\n" : "");
    for (size_t i = 0; i < heaps.size(); ++i)
        std::printf(" heap %zu %s of %s%s", i, formatBytes(heaps[i].first).c_str(), formatBytes(heaps[i].second).c_str(),
                    i + 1 == heaps.size() ? "\n" : ";");
    std::printf("  fallbacks:");
    if (context.choices().fallbacks.empty()) std::printf(" none (the device has every format feature Candela prefers)");
    std::printf("\n");
    for (const std::string& f : context.choices().fallbacks) std::printf("    %s\n", f.c_str());
    std::printf("  features enabled:");
    for (const std::string& f : r.enabledFeatures) std::printf(" %s", f.c_str());
    std::printf("\n  extensions enabled:");
    if (r.enabledExtensions.empty()) std::printf(" (none)");
    for (const std::string& e : r.enabledExtensions) std::printf(" %s", e.c_str());
    std::printf("\n  layers enabled:");
    if (r.enabledLayers.empty()) std::printf(" (none)");
    for (const std::string& l : r.enabledLayers) std::printf(" %s", l.c_str());
    std::printf("\n");
    return 0;
}

}  // namespace candela::app

int main(int argc, char** argv) {
    using namespace candela;
    try {
        const app::Command command = app::parseCommandLine(std::vector<std::string>(argv + 1, argv + argc));
        log::setVerbose(command.common().verbose);  // before anything loads: loaders print notes with --verbose
        switch (command.kind) {
            case app::Command::Kind::Help:
                std::fputs((command.helpCommand.empty() ? app::usageText() : app::commandHelp(command.helpCommand)).c_str(), stdout);
                return 0;
            case app::Command::Kind::Version: std::printf("%s\n", app::versionText().c_str()); return 0;
            case app::Command::Kind::Render: return app::runRender(command.render);
            case app::Command::Kind::View: return app::runView(command.render);
            case app::Command::Kind::Info: return app::runInfo(command.info);
            case app::Command::Kind::Bench: return app::runBench(command.render);
            case app::Command::Kind::IblReport: return app::runIblReport(command.iblReport);
            case app::Command::Kind::Soak: return app::runSoak(command.soak);
            case app::Command::Kind::ScaleReport: return app::runScaleReport(command.scaleReport);
            case app::Command::Kind::QualityReport: return app::runQualityReport(command.qualityReport);
            case app::Command::Kind::Diff: return app::runDiff(command.diff);
        }
    } catch (const UserError& e) {
        log::error(e.what());
        return 2;
    } catch (const OutOfDeviceMemory& e) {
        log::error(std::string("out of device memory: ") + e.what());
        return 4;
    } catch (const InternalError& e) {
        log::error(std::string("internal error (a bug in Candela, please report it): ") + e.what());
        return 1;
    } catch (const std::exception& e) {
        log::error(e.what());
        return 1;
    }
    return 1;
}
