#include "render_page.h"

#include "core/errors.h"

#include <cstdio>

namespace candela::app {
namespace {

namespace fs = std::filesystem;

// Thumbnails shown per scene (each variant, or the first frames of a sequence); every output is
// linked.
constexpr size_t kThumbnails = 3;

reports::PageRow sceneRow(const SceneReport& s, const fs::path& page) {
    reports::PageRow row;
    row.name = s.input.path;
    row.status = !s.ok ? reports::RowStatus::Failed
                 : !s.warnings.empty() || s.validationMessages > 0 ? reports::RowStatus::Warning
                                                                   : reports::RowStatus::Ok;
    row.error = s.error;
    row.warnings = s.warnings;
    if (s.validationMessages > 0) row.warnings.push_back(std::to_string(s.validationMessages) + " validation messages");
    row.notes = s.notes;
    if (!s.extensions.empty()) {
        std::string line = "extensions:";
        for (const std::string& e : s.extensions) line += " " + e;
        row.notes.push_back(line);
    }
    for (size_t i = 0; i < s.outputs.size(); ++i) {
        const fs::path file = s.outputs[i].file;
        row.links.push_back({file.filename().string(), reports::pathFromPage(file, page)});
        if (i >= kThumbnails) continue;
        const bool shown = file.extension() == ".png";  // browsers show no EXR or PFM
        row.images.push_back({s.outputs[i].label, shown ? reports::pathFromPage(file, page) : fs::path(),
                              shown ? "" : file.extension().string() + ": no preview"});
    }
    if (!s.ok && s.outputs.empty()) row.images.push_back({"render", {}, "not rendered"});
    if (!s.frameMs.empty()) {
        double frame = 0.0;
        for (double ms : s.frameMs) frame += ms;
        row.numbers["frame ms"] = frame / double(s.frameMs.size());
        row.numbers["triangles"] = double(s.triangles);
        uint64_t textureBytes = 0;
        for (const TextureReport& t : s.textures) textureBytes += t.deviceBytes;
        row.numbers["texture MiB"] = double(textureBytes) / double(1 << 20);
        row.numbers["upload ms"] = s.uploadMs;
    }
    row.numbers["load ms"] = s.loadMs;
    return row;
}

}  // namespace

reports::HtmlPage renderPage(const RunReport& report, const fs::path& page) {
    reports::HtmlPage out;
    const size_t failed = report.failed();
    out.title = "candela render: " + std::to_string(report.scenes.size()) + " scene" + (report.scenes.size() == 1 ? "" : "s");
    std::string counts = std::to_string(report.scenes.size() - failed) + " rendered, " + std::to_string(failed) + " failed";
    if (report.shard.count > 1)
        counts += "; shard " + std::to_string(report.shard.index) + "/" + std::to_string(report.shard.count) + " of " +
                  std::to_string(report.scenesListed) + " scenes listed";
    out.summary.push_back(counts);
    out.summary.push_back(report.version + " on " + report.device + "; environment: " + report.environment + "; " +
                          std::to_string(report.width) + "x" + std::to_string(report.height));
    const double perScene = report.scenes.empty() ? 0.0 : (report.totalMs - report.startupMs) / double(report.scenes.size());
    out.summary.push_back("total " + formatNumber("%.2f s", report.totalMs / 1000.0) + " (" + formatNumber("%.0f ms", perScene) +
                          " a scene after start-up); environment precomputed " + std::to_string(report.precomputes) +
                          (report.precomputes == 1 ? " time" : " times") +
                          (report.precomputeMs >= 0.0 ? " (" + formatNumber("%.0f ms", report.precomputeMs) + ")" : ""));
    out.summary.push_back("peak memory: host " + formatBytes(report.peakHostBytes) + " resident, device " +
                          formatBytes(report.peakDeviceBytes) + " in use");
    out.columns = {{"frame ms", 1}, {"load ms", 1}, {"upload ms", 1}, {"triangles", 0}, {"texture MiB", 1}};
    out.errorColumn = "frame ms";
    for (const SceneReport& s : report.scenes) out.rows.push_back(sceneRow(s, page));
    return out;
}

}  // namespace candela::app
