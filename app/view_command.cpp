// `candela view`: the interactive viewer (ui::Viewer), or with --frames N [--screenshot FILE] a
// scripted run that renders N frames, saves the last and exits.

#include "commands.h"
#include "core/check.h"
#include "core/log.h"
#include "io/image_file.h"
#include "ui/viewer.h"

#include <cstdio>

namespace candela::app {

int runView(const RenderOptions& options) {
    if (!options.screenshot.empty()) {
        if (io::imageFileFormat(options.screenshot) != io::ImageFileFormat::Png)
            throw UserError("--screenshot " + options.screenshot + ": screenshots are PNG files");
        io::checkWritable(options.screenshot);
    }
    ui::ViewerContent content;
    content.scene = loadScene(options);
    if (std::optional<scene::Environment> env = loadEnvironment(options))
        content.environment = std::make_unique<scene::Environment>(std::move(*env));
    // The viewer owns the scene and environment from now on and points each frame's settings at
    // them itself.
    content.settings = renderSettings(options, content.scene, content.environment.get());
    content.settings.tonemap.dither = true;  // 8-bit display: no banding in dark gradients

    ui::ViewerDesc desc;
    desc.context = contextDesc(options.common);
    desc.window = {.title = "Candela — " + (options.scene.empty() ? std::string("sphere grid") : options.scene),
                   .width = options.width,
                   .height = options.height};
    desc.vsync = options.vsync;
    desc.ui = options.ui;
    desc.shaderDir = options.shaderDir;
    desc.iblReport = options.iblReport;
    desc.openPanels = std::set<std::string>(options.panels.begin(), options.panels.end());
    ui::Viewer viewer(desc, std::move(content));
    if (options.frames > 0) {
        // frame() also returns true for frames not rendered (minimized window): count rendered ones.
        while (viewer.framesRendered() + 1 < options.frames && viewer.frame()) {
        }
        if (!options.screenshot.empty()) viewer.requestScreenshot(options.screenshot);
        while (viewer.framesRendered() < options.frames && viewer.frame()) {
        }
        viewer.renderer().waitIdle();
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
