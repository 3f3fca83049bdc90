#pragma once
// Viewer: the interactive window of `candela view`. Owns, in start-up order (destruction runs in
// reverse): the window, the Vulkan context (with presentation), the swapchain, the renderer, the
// Dear ImGui context and its pass. Each frame(): events → UI → camera → render graph (scene
// passes + ImGui) into the acquired swapchain image → present; frames stay in flight.
//
// The UI's controls call the public actions below; tests and scripted runs call the same ones.

#include "render/renderer.h"
#include "pose/scene_pose.h"
#include "assets/environment.h"
#include "scene/scene.h"
#include "ui/hot_reload.h"
#include "ui/ibl_report_table.h"
#include "ui/orbit_controls.h"
#include "ui/panel_layout.h"
#include "options/viewer_panels.h"
#include "ui/window.h"
#include "vk/context.h"

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace candela::vk {
class Swapchain;
}
namespace candela::ui {
class ImGuiPass;
}

namespace candela::ui {

class ImGuiContextOwner;

struct ViewerDesc {
    WindowDesc window;
    bool vsync = true;
    bool ui = true;           // draw the ImGui panels (the ImGui pass is left out when off)
    // Hot reload of the shaders' GLSL from this folder; empty: the shaders/ folder of the source
    // tree the viewer was built from (when it exists).
    std::filesystem::path shaderDir;
    // An ibl-report CSV shown in the environment panel before the compiled-in ones (empty: none).
    std::filesystem::path iblReport;
    // The panels open at start.
    std::set<options::Panel> openPanels = options::kPanelsOpenByDefault;
};

// What the viewer shows at start: the scene and environment (owned by the viewer from now on) and
// the render settings the command line chose (their scene/environment pointers are ignored).
struct ViewerContent {
    scene::Scene scene;
    std::unique_ptr<assets::Environment> environment;  // null: no image-based lighting
    RenderSettings settings;
    std::vector<std::string> animations;  // the ones to play (pose::selectAnimations); empty: animation 0
    double time = 0.0;                    // where playback starts, seconds
    std::optional<uint32_t> variant;      // the KHR_materials_variants variant `scene` was given (scene::selectVariant)
};

class Viewer {
public:
    // What the viewer's renderer is made with: two frames in flight, and the render-graph panel's
    // toggles may name passes a frame does not have.
    static constexpr RendererOptions kRendererOptions{.framesInFlight = 2, .unknownPassIsError = false};

    // Opens the window and draws with `renderer` on `context`. Preconditions: `context` was made
    // from a description a WindowSystem added to (WindowSystem::addTo), and that WindowSystem,
    // `context` and `renderer` (made with kRendererOptions) outlive the viewer. Throws UserError
    // when no window can be opened or the device cannot present to it.
    Viewer(const ViewerDesc& desc, ViewerContent content, vk::Context& context, Renderer& renderer);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // One iteration of the loop. Returns false once the window was asked to close. While the
    // window is minimized (0 × 0) it renders nothing and blocks on events instead of spinning.
    bool frame();
    // Runs frames until the window closes, or `maxFrames` have been rendered (0: no limit).
    void run(uint32_t maxFrames = 0);

    // --- Actions (UI controls, keys, drops and tests use these) ---
    // Enables or disables a pass by name from the next frame on (the render-graph panel's checkbox).
    void setPassEnabled(const std::string& pass, bool enabled);
    bool passEnabled(const std::string& pass) const;
    // Loads a dropped file: .gltf/.glb replaces the scene (`sceneIndex`: which of the file's
    // scenes; the scene list reloads with it), .hdr/.exr the environment (the IBL precompute runs
    // in the next frame). Errors are shown in the UI, not thrown. Returns success.
    bool openFile(const std::filesystem::path& path, std::optional<uint32_t> sceneIndex = std::nullopt);
    // Saves the next rendered frame (UI included) as PNG.
    void requestScreenshot(const std::filesystem::path& path);
    void frameScene();   // F: frame the scene from the current direction, at the current field of view
    void resetCamera();  // R: the initial view
    void setVsync(bool vsync);
    bool vsync() const;
    // The environment panel's buttons: the built-in sky, no environment, and a fresh precompute of
    // the current one (with RenderSettings::iblQuality) in the next frame.
    void useProceduralSky();
    void useNoEnvironment();
    void recomputeIbl();
    // The material inspector's selection; pickMaterial selects the material of the mesh under
    // window position `pixel` (returns false if no mesh is there).
    void selectMaterial(uint32_t material) { mSelectedMaterial = material; }
    // The scene's KHR_materials_variants variant (nullopt: the default materials): re-poses the
    // scene and has the renderer upload it again at the next frame.
    void selectVariant(std::optional<uint32_t> variant);
    std::optional<uint32_t> variant() const { return mVariant; }
    uint32_t selectedMaterial() const { return mSelectedMaterial; }
    bool pickMaterial(const glm::vec2& pixel);
    // The animation panel's controls: which of the scene's animations play (a new pose, same
    // time), pause (space), speed, looping, and the playback time (the slider scrubs it).
    void setPlayingAnimations(std::vector<uint32_t> animations);
    void setAnimationTime(double seconds);
    double animationTime() const { return mAnimationTime; }
    bool& animationPaused() { return mAnimationPaused; }
    float& animationSpeed() { return mAnimationSpeed; }
    bool& animationLoop() { return mAnimationLoop; }
    const pose::ScenePose& pose() const { return *mPose; }
    // Writes the last frame's graph (with the latest measured GPU times) as JSON or Graphviz dot.
    bool exportGraph(const std::filesystem::path& path, bool json);
    // Testing hook: treat the window as minimized (a window system without a window manager, such
    // as Xvfb, ignores iconify requests). Same code path as a real 0 × 0 framebuffer.
    void simulateMinimized(bool minimized) { mSimulatedMinimized = minimized; }

    // --- State (panels and tests read it) ---
    Window& window() { return *mWindow; }
    vk::Context& context() { return *mContext; }
    Renderer& renderer() { return *mRenderer; }
    RenderSettings& settings() { return mSettings; }
    scene::OrbitCamera& camera() { return mCamera; }
    OrbitSpeeds& speeds() { return mSpeeds; }
    const scene::Scene& scene() const { return mScene; }
    const assets::Environment* environment() const { return mEnvironment.get(); }
    uint64_t framesRendered() const { return mFramesRendered; }
    // Frames skipped because the window was minimized.
    uint64_t framesSkipped() const { return mFramesSkipped; }
    uint32_t swapchainRecreations() const;
    VkExtent2D swapchainExtent() const;
    // The last screenshot written ("" if none) and the last status or error line.
    const std::string& lastScreenshot() const { return mLastScreenshot; }
    const std::string& status() const { return mStatus; }
    double cpuFrameMs() const { return mCpuFrameMs; }
    // Wall time between consecutive rendered frames, every frame so far (frames in flight: the
    // throughput, not one frame's latency).
    const std::vector<double>& frameTimesMs() const { return mFrameTimes; }
    // Runs the calibration pass (passes/diagnostics/calibration_pass.h) at the window's size and
    // returns its submit+wait time: the yardstick for the frame times on this machine. Waits for
    // the GPU.
    double calibrationMs();
    // Hot reload: the watcher (its errors are shown in the UI) and the time from the last reloaded
    // file's save to the first frame drawn with it having completed on the GPU (negative: none yet).
    const ShaderHotReload& hotReload() const { return *mHotReload; }
    double lastReloadLatencyMs() const { return mReloadLatencyMs; }
    // The ibl-report tables the environment panel offers, and the one it shows: the user's
    // (--ibl-report) if given, else the one measured on the environment loaded (chosen again when
    // the environment changes; kept when none was measured on it).
    const std::vector<IblReportTable>& iblReports() const { return mIblReports; }
    int& selectedIblReport() { return mSelectedIblReport; }
    // What the last frame drew behind the scene: "the sky (FILE NAME)", "the background colour", or
    // "nothing (transparent, shown black)".
    std::string behindScene() const;
    // The panels' windows as the last frame laid them out, and their layout (empty without UI).
    const std::vector<UiWindow>& uiWindows() const { return mUiWindows; }
    const PanelLayout& panelLayout() const { return mLayout; }

private:
    void handleInput();
    void drawUi();  // viewer_ui.cpp
    // The ImGui window for one column of panels or the frame stats, its record in mUiWindows.
    void recordUiWindow(const char* name);
    // Chooses the ibl-report table for the environment now loaded (selectedIblReport()).
    void environmentChanged();
    bool ensureSwapchain(VkExtent2D extent);
    void setStatus(std::string line, bool error = false);
    // Width / height of the part of the window between the panel columns (the whole window without UI).
    float visibleAspect() const;
    // `camera` with framing resolved over the whole of the playing animations (the viewer plays
    // them: render/camera_framing.h at pose::animationTimes, clamped), from its orbit's direction or
    // the scene's default one.
    CameraSettings framedWhilePlaying(const CameraSettings& camera) const;
    // The settings of the next frame: the scene, environment and camera of the viewer.
    RenderSettings frameSettings(VkExtent2D extent) const;

    // Start-up order; destruction runs in reverse.
    std::unique_ptr<Window> mWindow;
    vk::Context* mContext = nullptr;  // the caller's
    std::unique_ptr<vk::Swapchain> mSwapchain;
    Renderer* mRenderer = nullptr;    // the caller's
    std::unique_ptr<ImGuiContextOwner> mImGui;
    std::unique_ptr<ui::ImGuiPass> mImGuiPass;
    std::unique_ptr<ShaderHotReload> mHotReload;
    std::optional<std::chrono::system_clock::time_point> mReloadSaved;  // a reload waiting for its first frame
    double mReloadLatencyMs = -1.0;

    bool mUi = true;
    PanelLayout mLayout;        // where the panels are (the last UI frame's)
    float mFontSize = 13.0f;    // the UI font's size in pixels (Dear ImGui's default font until the first UI frame)
    std::vector<UiWindow> mUiWindows;
    bool mUserIblReport = false;  // --ibl-report gave the first table
    std::set<options::Panel> mOpenPanels;
    bool mRecreate = false;
    bool mSimulatedMinimized = false;
    scene::Scene mScene;
    std::optional<uint32_t> mVariant;
    // The scene's animations as they play: advanced by the wall-clock time between frames, looping.
    std::unique_ptr<pose::ScenePose> mPose;
    double mAnimationTime = 0.0;
    std::chrono::steady_clock::time_point mAnimationClock;
    bool mAnimationPaused = false;
    float mAnimationSpeed = 1.0f;
    bool mAnimationLoop = true;
    std::unique_ptr<assets::Environment> mEnvironment;
    RenderSettings mSettings;
    scene::OrbitCamera mCamera;
    scene::OrbitCamera mInitialCamera;
    OrbitSpeeds mSpeeds;
    std::optional<glm::vec2> mLastCursor;
    std::optional<std::filesystem::path> mScreenshot;
    std::string mLastScreenshot;
    std::string mStatus;
    bool mStatusIsError = false;
    uint64_t mFramesRendered = 0;
    uint64_t mFramesSkipped = 0;
    double mCpuFrameMs = 0.0;
    std::vector<double> mFrameTimes;
    uint32_t mSelectedMaterial = 0;
    std::vector<IblReportTable> mIblReports;
    int mSelectedIblReport = 0;
    std::optional<glm::vec2> mPressedAt;  // where the left button went down (a click picks)
    std::chrono::steady_clock::time_point mLastFrame;
};

}  // namespace candela::ui
