#include "ui/viewer.h"

#include "assets/gltf_loader.h"
#include "assets/image_file.h"
#include "assets/procedural_sky.h"
#include "core/errors.h"
#include "core/log.h"
#include "graph/graph_export.h"
#include "pose/animation_conflicts.h"
#include "pose/picking.h"
#include "pose/shown_points.h"
#include "render/camera_framing.h"
#include "scene/material_variants.h"
#include "shader/shader_library.h"
#include "ui/imgui_pass.h"
#include "ui/panels.h"
#include "vk/swapchain.h"
#include "vk/swapchain_choices.h"
#include "vk/timestamps.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <algorithm>
#include <cctype>
#include <fstream>

namespace candela::ui {

// The Dear ImGui context and its GLFW platform backend (the Vulkan side is ui::ImGuiPass).
class ImGuiContextOwner {
public:
    explicit ImGuiContextOwner(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;  // no imgui.ini in the user's working directory
        ImGui::StyleColorsDark();
        ImGui::GetStyle().WindowRounding = 0.0f;
        // Chains to the window's own drop, scroll and key callbacks installed before it.
        ImGui_ImplGlfw_InitForVulkan(window, true);
    }
    ~ImGuiContextOwner() {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiContextOwner(const ImGuiContextOwner&) = delete;
    ImGuiContextOwner& operator=(const ImGuiContextOwner&) = delete;
};

namespace {

template <class TimePoint>
double msBetween(TimePoint a, TimePoint b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace

Viewer::Viewer(const ViewerDesc& desc, ViewerContent content, vk::Context& context, Renderer& renderer)
    : mUi(desc.ui), mScene(std::move(content.scene)), mEnvironment(std::move(content.environment)),
      mSettings(std::move(content.settings)) {
    mVariant = content.variant;
    mPose = std::make_unique<pose::ScenePose>(mScene, pose::selectAnimations(mScene, content.animations));
    // Said once here; the animation panel shows it while the ticked animations overlap.
    if (const std::string overlap = pose::describeAnimationConflicts(mScene, pose::animationConflicts(mScene, mPose->playing()));
        !overlap.empty())
        log::warn(mScene.source + ": " + overlap);
    mAnimationTime = content.time;
    mPose->evaluate(mAnimationTime);
    mWindow = std::make_unique<Window>(desc.window);
    mContext = &context;
    mSwapchain = std::make_unique<vk::Swapchain>(*mContext, mWindow->createSurface(mContext->instance()), desc.vsync);
    mRenderer = &renderer;
    if (mUi) mImGui = std::make_unique<ImGuiContextOwner>(mWindow->handle());
    mHotReload = std::make_unique<ShaderHotReload>(desc.shaderDir.empty() ? sourceShadersOfExecutable() : desc.shaderDir);

    mSettings.floatOutput = false;
    const float aspect = visibleAspect();
    if (!mSettings.camera.orbitCamera) {
        // Start from the view the command line chose (framing the scene by default), as render does.
        mCamera = Renderer::orbitCamera(mScene, framedWhilePlaying(mSettings.camera), aspect, mPose.get());
        if (mSettings.camera.gltfCamera && *mSettings.camera.gltfCamera < mScene.cameras.size()) {
            // Orbit about the point the glTF camera looks at, at the depth of the scene's centre.
            const glm::mat4& world = mPose->cameras()[*mSettings.camera.gltfCamera].world;
            const glm::vec3 eye(world[3]);
            const glm::vec3 forward = -glm::normalize(glm::vec3(world[2]));
            const float depth = std::max(glm::dot(mCamera.target - eye, forward), mCamera.radius * 0.1f);
            mCamera.target = eye + forward * depth;
            setEye(mCamera, eye);
        }
    } else {
        mCamera = *mSettings.camera.orbitCamera;
    }
    mInitialCamera = mCamera;
    log::info("camera: " + scene::orbitCameraFlags(mCamera));
    mOpenPanels = desc.openPanels;
    if (!desc.iblReport.empty()) mIblReports.push_back(loadIblReport(desc.iblReport));
    mUserIblReport = !desc.iblReport.empty();
    for (IblReportTable& table : builtinIblReports()) mIblReports.push_back(std::move(table));
    environmentChanged();
    mLastFrame = std::chrono::steady_clock::now();
}

Viewer::~Viewer() {
    if (mRenderer) mRenderer->waitIdle();
    mImGuiPass.reset();
    // Replaced shaders are process-wide: later renderers start from the built-in ones again.
    shader::restoreBuiltinShaders();
}

uint32_t Viewer::swapchainRecreations() const { return mSwapchain->recreations(); }
VkExtent2D Viewer::swapchainExtent() const { return mSwapchain->extent(); }

void Viewer::setStatus(std::string line, bool error) {
    if (error)
        log::error(line);
    else
        log::info(line);
    mStatus = std::move(line);
    mStatusIsError = error;
}

void Viewer::setPassEnabled(const std::string& pass, bool enabled) {
    auto& disabled = mSettings.disabledPasses;
    disabled.erase(std::remove(disabled.begin(), disabled.end(), pass), disabled.end());
    if (!enabled) disabled.push_back(pass);
}

bool Viewer::passEnabled(const std::string& pass) const {
    const auto& disabled = mSettings.disabledPasses;
    return std::find(disabled.begin(), disabled.end(), pass) == disabled.end();
}

bool Viewer::openFile(const std::filesystem::path& path, std::optional<uint32_t> sceneIndex) {
    const std::string ext = lowerExtension(path);
    try {
        if (ext == ".gltf" || ext == ".glb") {
            scene::Scene loaded = assets::loadGltf(path, {.sceneIndex = sceneIndex});
            for (const std::string& warning : loaded.report.warnings) log::warn(path.string() + ": " + warning);
            for (const std::string& note : loaded.report.notes) log::info(path.string() + ": " + note);
            // Replaced in place: the renderer is told, waits for the frames in flight and uploads
            // the new one at the next frame.
            mRenderer->sceneReplaced();
            mScene = std::move(loaded);
            mVariant.reset();
            mPose = std::make_unique<pose::ScenePose>(mScene, pose::selectAnimations(mScene, {}));
            mAnimationTime = 0.0;
            mCamera = mInitialCamera =
                Renderer::orbitCamera(mScene, framedWhilePlaying({.fovYDegrees = mSettings.camera.fovYDegrees}), visibleAspect(),
                                      mPose.get());
            mSettings.camera.gltfCamera.reset();
            setStatus("opened " + path.string());
            return true;
        }
        if (ext == ".hdr" || ext == ".pic" || ext == ".exr") {
            // A new object (new address) while the old one is alive: the renderer hashes it and
            // runs the precompute in the next frame.
            auto loaded = std::make_unique<assets::Environment>(assets::loadEnvironment(path));
            for (const std::string& warning : loaded->report.warnings) log::warn(warning);
            for (const std::string& note : loaded->report.notes) log::info(note);
            mRenderer->waitIdle();
            mEnvironment = std::move(loaded);
            // Show it: the skybox becomes the background, as `--env` does with the default background.
            mSettings.ibl.skybox = true;
            mSettings.tonemap.background.reset();
            environmentChanged();
            setStatus("environment " + path.string());
            return true;
        }
        setStatus(path.string() + ": not a scene (.gltf, .glb) or an environment (.hdr, .exr)", true);
    } catch (const std::exception& e) {
        setStatus(e.what(), true);
    }
    return false;
}

void Viewer::requestScreenshot(const std::filesystem::path& path) { mScreenshot = path; }

float Viewer::visibleAspect() const {
    const VkExtent2D extent = mSwapchain->valid() ? mSwapchain->extent() : mWindow->framebufferSize();
    if (extent.height == 0 || extent.width == 0) return 16.0f / 9.0f;
    if (!mUi) return float(extent.width) / float(extent.height);
    return layoutPanels(float(extent.width), float(extent.height), mFontSize).sceneAspect(float(extent.height));
}

CameraSettings Viewer::framedWhilePlaying(const CameraSettings& camera) const {
    // (At most 256 poses: framing evaluates each three times, skinning every vertex.)
    return resolveFraming(mScene, camera, visibleAspect(), mPose.get(), pose::animationTimes(*mPose, 256), {}, /*loop=*/false);
}

void Viewer::frameScene() {
    const CameraSettings framed = framedWhilePlaying(
        {.orbit = glm::vec3(mCamera.thetaDegrees, mCamera.phiDegrees, 0.0f), .fovYDegrees = mCamera.fovYDegrees});
    mCamera.target = *framed.target;
    mCamera.radius = framed.orbit->z;
    mCamera.znear = mCamera.radius * 1e-3f;
}

void Viewer::resetCamera() { mCamera = mInitialCamera; }

void Viewer::setVsync(bool vsync) { mSwapchain->setVsync(vsync); }
bool Viewer::vsync() const { return mSwapchain->vsync(); }

void Viewer::useProceduralSky() {
    mRenderer->waitIdle();
    mEnvironment = std::make_unique<assets::Environment>(assets::makeProceduralSky());
    mSettings.ibl.skybox = true;
    mSettings.tonemap.background.reset();
    environmentChanged();
    setStatus("environment: procedural sky");
}

void Viewer::useNoEnvironment() {
    mRenderer->waitIdle();
    mEnvironment.reset();
    if (!mSettings.tonemap.background) mSettings.tonemap.background = glm::vec3(0.0194f);  // #262626
    environmentChanged();
    setStatus("environment: none");
}

void Viewer::environmentChanged() {
    if (mUserIblReport) return;  // the user's table (--ibl-report) stays shown
    if (const std::optional<size_t> table = findIblReportFor(mIblReports, mEnvironment ? mEnvironment->source : ""))
        mSelectedIblReport = int(*table);
}

std::string Viewer::behindScene() const {
    switch (mRenderer->lastBackdrop()) {
        case Renderer::Backdrop::Sky: {
            const std::string name = mEnvironment ? std::filesystem::path(mEnvironment->source).filename().string() : "";
            return "the sky (" + name + ")";
        }
        case Renderer::Backdrop::Color: return "the background colour";
        default: return "nothing (transparent, shown black)";
    }
}

void Viewer::recomputeIbl() { mRenderer->recomputeIbl(); }

bool Viewer::exportGraph(const std::filesystem::path& path, bool json) {
    const graph::RenderGraph& graph = mRenderer->lastGraph();
    // The latest completed frame may be an older graph than the last declared one: match by name.
    graph::GraphTimings timings;
    for (const graph::PassDecl& pass : graph.declaration().passes) timings.gpuMs.push_back(mRenderer->completedPassMs(pass.name));
    timings.gpuMsUnreliable = !vk::timestampsMeasurePasses(mContext->caps().driver);
    const std::string text = json ? graph::exportJson(graph.declaration(), graph.compiled(), &timings)
                                  : graph::exportDot(graph.declaration(), graph.compiled(), &timings);
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) {
        setStatus(path.string() + ": cannot write", true);
        return false;
    }
    setStatus("wrote " + path.string());
    return true;
}

void Viewer::selectVariant(std::optional<uint32_t> variant) {
    mRenderer->sceneReplaced();  // waits for the frames in flight; the next frame uploads again
    scene::selectVariant(mScene, variant);
    mVariant = variant;
    setPlayingAnimations(mPose->playing());  // the pose holds copies of the draws
    setStatus("variant: " + (variant ? mScene.variants[*variant] : std::string("the default materials")));
}

void Viewer::setPlayingAnimations(std::vector<uint32_t> animations) {
    mPose = std::make_unique<pose::ScenePose>(mScene, std::move(animations));
    mPose->evaluate(mAnimationTime, mAnimationLoop);
}

void Viewer::setAnimationTime(double seconds) {
    mAnimationTime = std::max(seconds, 0.0);
    mPose->evaluate(mAnimationTime, mAnimationLoop);
}

void Viewer::handleInput() {
    for (const std::string& path : mWindow->takeDroppedFiles()) openFile(path);
    const bool uiWantsKeys = mUi && ImGui::GetIO().WantCaptureKeyboard;
    for (int key : mWindow->takeKeyPresses()) {
        if (uiWantsKeys) continue;
        if (key == GLFW_KEY_F) frameScene();
        if (key == GLFW_KEY_R) resetCamera();
        if (key == GLFW_KEY_SPACE) mAnimationPaused = !mAnimationPaused;
        if (key == GLFW_KEY_F12 || key == GLFW_KEY_P) requestScreenshot("candela-screenshot.png");
        if (key == GLFW_KEY_ESCAPE) mWindow->requestClose();
    }
    const bool uiWantsMouse = mUi && ImGui::GetIO().WantCaptureMouse;
    const glm::vec2 cursor = mWindow->cursor();
    PointerInput input;
    input.delta = mLastCursor ? cursor - *mLastCursor : glm::vec2(0.0f);
    input.scroll = mWindow->takeScroll();
    input.viewportHeight = float(std::max(1u, mSwapchain->extent().height));
    if (!uiWantsMouse) {
        input.rotate = mWindow->mouseButton(GLFW_MOUSE_BUTTON_RIGHT);
        input.pan = mWindow->mouseButton(GLFW_MOUSE_BUTTON_MIDDLE);
        applyPointer(mCamera, input, mSpeeds);
        // A left click (press and release without moving) picks the mesh's material.
        const bool left = mWindow->mouseButton(GLFW_MOUSE_BUTTON_LEFT);
        if (left && !mPressedAt) mPressedAt = cursor;
        if (!left && mPressedAt) {
            if (glm::length(cursor - *mPressedAt) < 3.0f) pickMaterial(cursor);
            mPressedAt.reset();
        }
    } else {
        mPressedAt.reset();
    }
    mLastCursor = cursor;
}

bool Viewer::ensureSwapchain(VkExtent2D extent) {
    if (!vk::swapchainNeedsRecreate({.valid = mSwapchain->valid(),
                                     .outOfDate = mRecreate,
                                     .presentModeChanged = mSwapchain->needsRecreate(),
                                     .extent = mSwapchain->extent()},
                                    mSwapchain->wantedExtent(extent)))
        return true;
    if (!mSwapchain->recreate(extent)) return false;
    mRecreate = false;
    if (mUi) {
        if (!mImGuiPass || mImGuiPass->format() != mSwapchain->format()) {
            mImGuiPass.reset();
            mImGuiPass = std::make_unique<ImGuiPass>(*mContext, mSwapchain->format(), mSwapchain->minImageCount(),
                                                             mSwapchain->imageCount());
        }
        ImGui_ImplVulkan_SetMinImageCount(std::max(2u, mSwapchain->minImageCount()));
    }
    return true;
}

RenderSettings Viewer::frameSettings(VkExtent2D extent) const {
    RenderSettings settings = mSettings;
    settings.width = extent.width;
    settings.height = extent.height;
    settings.scene = &mScene;
    settings.pose = mPose.get();
    settings.environment = mEnvironment.get();
    if (!mEnvironment) settings.ibl.skybox = false;
    settings.camera.orbitCamera = mCamera;
    settings.camera.lensShiftX = mUi ? mLayout.lensShiftX(float(extent.width)) : 0.0f;
    return settings;
}

bool Viewer::pickMaterial(const glm::vec2& pixel) {
    const VkExtent2D extent = mSwapchain->extent();
    if (extent.width == 0 || extent.height == 0) return false;
    const RenderSettings settings = frameSettings(extent);
    const scene::ViewSetup view =
        Renderer::resolveView(mScene, settings.camera, float(extent.width) / float(extent.height), mPose.get());
    const glm::vec2 ndc(2.0f * (pixel.x + 0.5f) / float(extent.width) - 1.0f,
                        2.0f * (pixel.y + 0.5f) / float(extent.height) - 1.0f);
    // The mesh as it is posed on screen.
    const std::optional<pose::Pick> pick = pose::pickDraw(mScene, *mPose, pose::viewRay(view, ndc));
    if (!pick) return false;
    mSelectedMaterial = mPose->draws()[pick->draw].material;
    return true;
}

bool Viewer::frame() {
    mWindow->pollEvents();
    if (mWindow->shouldClose()) return false;
    const VkExtent2D extent = mSimulatedMinimized ? VkExtent2D{0, 0} : mWindow->framebufferSize();
    if (extent.width == 0 || extent.height == 0 || !ensureSwapchain(extent)) {
        // Minimized: nothing to draw into. Block on events rather than spin.
        ++mFramesSkipped;
        mWindow->waitEvents();
        return true;
    }
    const std::optional<vk::SwapchainImage> image = mSwapchain->acquire();
    if (!image) {
        mRecreate = true;
        return true;
    }
    if (const std::vector<std::string> replaced = mHotReload->poll(); !replaced.empty()) {
        mRenderer->shadersReplaced(replaced);
        mReloadSaved = mHotReload->lastSave();
        std::string names;
        for (const std::string& n : replaced) names += (names.empty() ? "" : ", ") + n;
        setStatus("reloaded " + names);
    }
    if (mUi) drawUi();
    handleInput();
    if (mPose->animated()) {
        // Advanced by the wall-clock time since the previous frame's pose, times the speed; the
        // first frame shows the starting time.
        const auto now = std::chrono::steady_clock::now();
        if (mFramesRendered > 0 && !mAnimationPaused)
            mAnimationTime += mAnimationSpeed * std::chrono::duration<double>(now - mAnimationClock).count();
        mAnimationClock = now;
        if (!mAnimationLoop) mAnimationTime = std::min(mAnimationTime, mPose->duration());
        mAnimationTime = std::max(mAnimationTime, 0.0);
        mPose->evaluate(mAnimationTime, mAnimationLoop);
    }

    const RenderSettings settings = frameSettings(mSwapchain->extent());
    const PresentTarget target{.image = image->image,
                               .view = image->view,
                               .format = mSwapchain->format(),
                               .acquired = image->acquired,
                               .rendered = image->rendered};
    OverlayFn overlay;
    if (mUi && mImGuiPass)
        overlay = [this](graph::RenderGraph& graph, graph::TextureId texture) { return mImGuiPass->add(graph, texture); };
    std::optional<CapturedFrame> shot;
    if (mScreenshot && mSwapchain->canReadBack()) shot.emplace();
    mRenderer->renderToTarget(settings, target, overlay, shot ? &*shot : nullptr);
    if (!mSwapchain->present(*image)) mRecreate = true;
    ++mFramesRendered;
    if (mReloadSaved) {
        // The first frame with the new shaders: its pixels exist once the GPU is done with it.
        mRenderer->waitIdle();
        mReloadLatencyMs = msBetween(*mReloadSaved, std::chrono::system_clock::now());
        mReloadSaved.reset();
        setStatus(mStatus + " (" + std::to_string(int(mReloadLatencyMs)) + " ms from save to new pixels)");
    }

    if (mScreenshot) {
        const std::filesystem::path path = *std::exchange(mScreenshot, std::nullopt);
        if (!shot) {
            setStatus("screenshot: this swapchain's images cannot be copied from", true);
        } else {
            try {
                assets::writePng(path, shot->width, shot->height, shot->rgba8);
                mLastScreenshot = path.string();
                setStatus("saved " + path.string());
            } catch (const std::exception& e) {
                setStatus(e.what(), true);
            }
        }
    }
    const auto now = std::chrono::steady_clock::now();
    mCpuFrameMs = msBetween(mLastFrame, now);
    mFrameTimes.push_back(mCpuFrameMs);
    mLastFrame = now;
    return true;
}

double Viewer::calibrationMs() {
    const VkExtent2D extent = mSwapchain->valid() ? mSwapchain->extent() : mWindow->framebufferSize();
    mRenderer->waitIdle();
    const double ms = mRenderer->renderCalibration(std::max(1u, extent.width), std::max(1u, extent.height)).submitWaitMs;
    mLastFrame = std::chrono::steady_clock::now();  // the calibration is not part of a frame's time
    return ms;
}

void Viewer::run(uint32_t maxFrames) {
    while (frame())
        if (maxFrames > 0 && mFramesRendered >= maxFrames) break;
    mRenderer->waitIdle();
}

}  // namespace candela::ui
