// `candela view`: the interactive viewer (ui::Viewer), or with --frames N [--screenshot FILE] a
// scripted run that renders N frames, saves the last and exits.

#include "commands.h"
#include "session.h"
#include "assets/image_file.h"
#include "core/errors.h"
#include "scene/material_variants.h"
#include "statistics.h"
#include "ui/viewer.h"

#include <cstdio>

namespace candela::app {

namespace {

// The warm-up of a scripted run of `frames` frames: the first frames include the IBL precompute
// and pipeline creation, so the summary leaves them out.
size_t warmUpFrames(size_t frames) { return std::min<size_t>(5, frames / 2); }

// What the renderer counted of CPU/GPU overlap, at one moment of a run.
struct OverlapCounts {
    vk::FrameRingStats ring;
    uint64_t completionWaits = 0;
    static OverlapCounts of(const Renderer& renderer) { return {renderer.frameRingStats(), renderer.completionWaits()}; }
};

// After a scripted run: the median frame time after warm-up as a ratio to calibration passes run
// around the measurement, and how much the CPU's recording overlapped the GPU's work over those
// frames (`from` and `to`: the counts at the end of warm-up and of the last frame).
void printFrameSummary(ui::Viewer& viewer, const ViewOptions& options, const OverlapCounts& from,
                       const OverlapCounts& to) {
    const std::vector<double>& times = viewer.frameTimesMs();
    const size_t warmUp = warmUpFrames(times.size());
    if (times.size() <= warmUp) return;
    std::vector<double> calibration;
    for (int i = 0; i < 3; ++i) calibration.push_back(viewer.calibrationMs());
    const double frame = median(std::vector<double>(times.begin() + long(warmUp), times.end()));
    const double yardstick = median(calibration);
    const VkExtent2D extent = viewer.swapchainExtent();
    std::printf("viewer %ux%u, UI %s, %s: median frame %.1f ms over %zu frames (after %zu warm-up); calibration %.1f ms; "
                "frame = %.2fx calibration\n",
                extent.width, extent.height, options.ui ? "on" : "off", viewer.vsync() ? "vsync" : "no vsync", frame,
                times.size() - warmUp, warmUp, yardstick, frame / yardstick);
    const uint64_t submits = to.ring.submits - from.ring.submits;
    double measuredMs = 0.0;
    for (size_t i = warmUp; i < times.size(); ++i) measuredMs += times[i];
    if (submits == 0 || measuredMs <= 0.0) return;
    const double blockedMs = to.ring.blockedMs - from.ring.blockedMs;
    const uint64_t overlapped = to.ring.overlappedSubmits - from.ring.overlappedSubmits;
    std::printf("overlap after warm-up: %llu of %llu frames submitted while the GPU still ran an earlier one (%.0f%%); "
                "CPU blocked on fences %.1f ms per frame (%.0f%% of the frame time, %llu blocking waits); "
                "%llu waits for the frame just submitted\n",
                (unsigned long long)overlapped, (unsigned long long)submits, 100.0 * double(overlapped) / double(submits),
                blockedMs / double(times.size() - warmUp), 100.0 * blockedMs / measuredMs,
                (unsigned long long)(to.ring.blockingWaits - from.ring.blockingWaits),
                (unsigned long long)(to.completionWaits - from.completionWaits));
}

}  // namespace

int runView(const ViewOptions& options) {
    if (!options.screenshot.empty()) {
        if (assets::imageFileFormat(options.screenshot) != assets::ImageFileFormat::Png)
            throw UserError("--screenshot " + options.screenshot + ": screenshots are PNG files");
        assets::checkWritable(options.screenshot);
    }
    ui::ViewerContent content;
    content.scene = loadScene(options);
    if (!options.variant.empty()) content.variant = scene::variantIndex(content.scene, options.variant);
    Session session(options.common, options.env);
    content.environment = session.takeEnvironment();
    // The viewer owns the scene and environment from now on and points each frame's settings at
    // them itself.
    content.settings = renderSettings(options, content.scene, content.environment.get());
    content.settings.tonemap.dither = true;  // 8-bit display: no banding in dark gradients
    content.animations = options.animations;
    content.time = options.time;

    ui::ViewerDesc desc;
    desc.window = {.title = "Candela — " + (options.scene.empty() ? std::string("sphere grid") : options.scene),
                   .width = options.width,
                   .height = options.height};
    desc.vsync = options.vsync;
    desc.ui = options.ui;
    desc.shaderDir = options.shaderDir;
    desc.iblReport = options.iblReport;
    desc.openPanels = options.panels;
    // The window system before the device: the device's queue must present to its windows.
    const ui::WindowSystem windowSystem;
    windowSystem.addTo(session.contextDesc());
    session.start(ui::Viewer::kRendererOptions);
    ui::Viewer viewer(desc, std::move(content), session.context(), session.renderer());
    if (options.frames > 0) {
        // frame() also returns true for frames not rendered (minimized window): count rendered ones.
        while (viewer.framesRendered() < warmUpFrames(options.frames) && viewer.frame()) {
        }
        const OverlapCounts warm = OverlapCounts::of(viewer.renderer());
        while (viewer.framesRendered() + 1 < options.frames && viewer.frame()) {
        }
        if (!options.screenshot.empty()) viewer.requestScreenshot(options.screenshot);
        while (viewer.framesRendered() < options.frames && viewer.frame()) {
        }
        const OverlapCounts last = OverlapCounts::of(viewer.renderer());
        viewer.renderer().waitIdle();
        printFrameSummary(viewer, options, warm, last);
    } else {
        viewer.run();
    }
    if (!options.screenshot.empty()) {
        if (viewer.lastScreenshot().empty()) throw UserError("--screenshot " + options.screenshot + ": " + viewer.status());
        std::printf("wrote %s after %llu frames\n", options.screenshot.c_str(),
                    static_cast<unsigned long long>(viewer.framesRendered()));
    }
    return session.exitCode(0);
}

}  // namespace candela::app
