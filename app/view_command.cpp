// `candela view`: the interactive viewer (ui::Viewer), or with --frames N [--screenshot FILE] a
// scripted run that renders N frames, saves the last and exits.

#include "commands.h"
#include "assets/image_file.h"
#include "core/errors.h"
#include "core/log.h"
#include "scene/material_variants.h"
#include "statistics.h"
#include "ui/viewer.h"

#include <cstdio>

namespace candela::app {

namespace {

// After a scripted run: the median frame time after warm-up (the first frames include the IBL
// precompute and pipeline creation) as a ratio to calibration passes run around the measurement.
void printFrameSummary(ui::Viewer& viewer, const RenderOptions& options) {
    const std::vector<double>& times = viewer.frameTimesMs();
    const size_t warmUp = std::min<size_t>(5, times.size() / 2);
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
}

}  // namespace

int runView(const RenderOptions& options) {
    if (!options.screenshot.empty()) {
        if (io::imageFileFormat(options.screenshot) != io::ImageFileFormat::Png)
            throw UserError("--screenshot " + options.screenshot + ": screenshots are PNG files");
        io::checkWritable(options.screenshot);
    }
    ui::ViewerContent content;
    content.scene = loadScene(options);
    if (!options.variant.empty()) content.variant = scene::variantIndex(content.scene, options.variant);
    if (std::optional<scene::Environment> env = loadEnvironment(options.env))
        content.environment = std::make_unique<scene::Environment>(std::move(*env));
    // The viewer owns the scene and environment from now on and points each frame's settings at
    // them itself.
    content.settings = renderSettings(options, content.scene, content.environment.get());
    content.settings.tonemap.dither = true;  // 8-bit display: no banding in dark gradients
    content.animations = options.animations;
    content.time = options.time;

    ui::ViewerDesc desc;
    desc.context = contextDesc(options.common);
    desc.window = {.title = "Candela — " + (options.scene.empty() ? std::string("sphere grid") : options.scene),
                   .width = options.width,
                   .height = options.height};
    desc.vsync = options.vsync;
    desc.ui = options.ui;
    desc.shaderDir = options.shaderDir;
    desc.iblReport = options.iblReport;
    desc.openPanels = options.panels;
    ui::Viewer viewer(desc, std::move(content));
    if (options.frames > 0) {
        // frame() also returns true for frames not rendered (minimized window): count rendered ones.
        while (viewer.framesRendered() + 1 < options.frames && viewer.frame()) {
        }
        if (!options.screenshot.empty()) viewer.requestScreenshot(options.screenshot);
        while (viewer.framesRendered() < options.frames && viewer.frame()) {
        }
        viewer.renderer().waitIdle();
        printFrameSummary(viewer, options);
    } else {
        viewer.run();
    }
    if (!options.screenshot.empty()) {
        if (viewer.lastScreenshot().empty()) throw UserError("--screenshot " + options.screenshot + ": " + viewer.status());
        std::printf("wrote %s after %llu frames\n", options.screenshot.c_str(),
                    static_cast<unsigned long long>(viewer.framesRendered()));
    }
    if (viewer.context().validationMessageCount() > 0) {
        log::error(std::to_string(viewer.context().validationMessageCount()) + " validation messages");
        return 3;
    }
    return 0;
}

}  // namespace candela::app
