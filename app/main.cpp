// The `candela` executable: parses the command line and runs a subcommand. Every error reaches the
// user as one line on stderr and a non-zero exit code.

#include "cli.h"
#include "core/check.h"
#include "core/log.h"
#include "graph/graph_export.h"
#include "io/image_file.h"
#include "renderer.h"
#include "vk/context.h"
#include "vk/device_select.h"

#include <cstdio>
#include <fstream>
#include <iostream>

namespace candela::app {
namespace {

vk::ContextDesc contextDesc(const CommonOptions& common) {
    log::setVerbose(common.verbose);
    return {.validation = common.validate, .deviceSelector = common.device};
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw UserError(path + ": cannot write");
}

int runRender(const RenderOptions& options) {
    const io::ImageFileFormat format = io::imageFileFormat(options.out);
    io::checkWritable(options.out);
    for (const std::string& path : {options.graphDot, options.graphJson})
        if (!path.empty()) io::checkWritable(path);

    vk::Context context(contextDesc(options.common));
    Renderer renderer(context);
    const RenderSettings settings{.width = options.width,
                                  .height = options.height,
                                  .floatOutput = io::isFloatFormat(format),
                                  .disabledPasses = options.disabledPasses};
    renderer.validateSettings(settings);
    const CapturedFrame frame = renderer.capture(settings);

    switch (format) {
        case io::ImageFileFormat::Png: io::writePng(options.out, frame.width, frame.height, frame.rgba8); break;
        case io::ImageFileFormat::Exr: io::writeExr(options.out, frame.width, frame.height, frame.rgba32f); break;
        case io::ImageFileFormat::Pfm: io::writePfm(options.out, frame.width, frame.height, frame.rgba32f); break;
    }
    const graph::RenderGraph& graph = renderer.lastGraph();
    if (!options.graphDot.empty())
        writeText(options.graphDot, graph::exportDot(graph.declaration(), graph.compiled(), &frame.timings));
    if (!options.graphJson.empty())
        writeText(options.graphJson, graph::exportJson(graph.declaration(), graph.compiled(), &frame.timings));

    std::printf("wrote %s (%ux%u): submit+wait %.2f ms, readback %.2f ms", options.out.c_str(), frame.width,
                frame.height, frame.submitWaitMs, frame.readbackMs);
    const graph::GraphDecl& decl = graph.declaration();
    for (uint32_t pass : graph.compiled().order)
        if (frame.timings.gpuMs.size() > pass && frame.timings.gpuMs[pass] >= 0.0)
            std::printf("; %s %.2f ms GPU", decl.passes[pass].name.c_str(), frame.timings.gpuMs[pass]);
    std::printf("\n");
    if (context.validationMessageCount() > 0) {
        log::error(std::to_string(context.validationMessageCount()) + " validation messages");
        return 3;
    }
    return 0;
}

std::string apiVersion(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

int runInfo(const InfoOptions& options) {
    vk::Context context(contextDesc(options.common));
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
    std::printf("  features enabled:");
    for (const std::string& f : r.enabledFeatures) std::printf(" %s", f.c_str());
    std::printf("\n  layers enabled:");
    if (r.enabledLayers.empty()) std::printf(" (none)");
    for (const std::string& l : r.enabledLayers) std::printf(" %s", l.c_str());
    std::printf("\n");
    return 0;
}

}  // namespace
}  // namespace candela::app

int main(int argc, char** argv) {
    using namespace candela;
    try {
        const app::Command command = app::parseCommandLine(std::vector<std::string>(argv + 1, argv + argc));
        switch (command.kind) {
            case app::Command::Kind::Help: std::fputs(app::usageText().c_str(), stdout); return 0;
            case app::Command::Kind::Render: return app::runRender(command.render);
            case app::Command::Kind::Info: return app::runInfo(command.info);
        }
    } catch (const UserError& e) {
        log::error(e.what());
        return 2;
    } catch (const std::exception& e) {
        log::error(e.what());
        return 1;
    }
    return 1;
}
