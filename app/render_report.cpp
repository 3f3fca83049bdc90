#include "render_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace candela::app {
namespace {

using Json = nlohmann::ordered_json;

// Milliseconds to 3 decimals (microseconds), so that reports diff cleanly.
double ms(double value) { return std::round(value * 1000.0) / 1000.0; }

Json msList(const std::vector<double>& values) {
    Json out = Json::array();
    for (double v : values) out.push_back(ms(v));
    return out;
}

Json sceneJson(const SceneReport& s) {
    Json out;
    out["file"] = s.input.file.generic_string();
    out["name"] = s.input.name;
    out["path"] = s.input.path;
    out["status"] = s.ok ? "ok" : "failed";
    if (!s.ok) {
        out["error"] = s.error;
        out["exit_code"] = s.exitCode;
    }
    out["load_ms"] = ms(s.loadMs);
    out["load_wait_ms"] = ms(s.loadWaitMs);
    out["image_decode_ms"] = ms(s.imageDecodeMs);
    out["decompression_ms"] = ms(s.decompressionMs);
    out["geometry_ms"] = ms(s.geometryMs);
    out["upload_ms"] = ms(s.uploadMs);
    out["frame_ms"] = msList(s.frameMs);
    out["gpu_ms"] = msList(s.gpuMs);
    out["triangles"] = s.triangles;
    out["draws"] = s.draws;
    Json textures = Json::array();
    uint64_t encoded = 0, device = 0;
    for (const TextureReport& t : s.textures) {
        textures.push_back({{"name", t.name},
                            {"format", t.format},
                            {"width", t.width},
                            {"height", t.height},
                            {"encoded_bytes", t.encodedBytes},
                            {"device_bytes", t.deviceBytes}});
        encoded += t.encodedBytes;
        device += t.deviceBytes;
    }
    out["texture_encoded_bytes"] = encoded;
    out["texture_device_bytes"] = device;
    out["textures"] = textures;
    out["extensions"] = s.extensions;
    out["variants"] = s.variants;
    out["warnings"] = s.warnings;
    out["notes"] = s.notes;
    out["validation_messages"] = s.validationMessages;
    Json outputs = Json::array();
    for (const SceneReport::Output& o : s.outputs) outputs.push_back(o.file);
    out["outputs"] = outputs;
    out["host_bytes"] = s.hostBytes;
    out["device_bytes"] = s.deviceBytes;
    out["retained_host_bytes"] = s.retainedHostBytes;
    out["retained_device_bytes"] = s.retainedDeviceBytes;
    return out;
}

}  // namespace

size_t RunReport::failed() const {
    return size_t(std::count_if(scenes.begin(), scenes.end(), [](const SceneReport& s) { return !s.ok; }));
}

std::string reportJson(const RunReport& r) {
    Json out;
    out["candela"] = r.version;
    out["device"] = r.device;
    out["environment"] = r.environment;
    out["width"] = r.width;
    out["height"] = r.height;
    out["shard"] = {{"index", r.shard.index}, {"count", r.shard.count}};
    out["scenes_listed"] = r.scenesListed;
    out["scenes_rendered"] = r.scenes.size() - r.failed();
    out["scenes_failed"] = r.failed();
    out["total_ms"] = ms(r.totalMs);
    out["startup_ms"] = ms(r.startupMs);
    out["precompute_ms"] = ms(r.precomputeMs);
    out["precomputes"] = r.precomputes;
    out["peak_host_bytes"] = r.peakHostBytes;
    out["peak_device_bytes"] = r.peakDeviceBytes;
    out["peak_device_memory_bytes"] = r.peakDeviceMemoryBytes;
    Json scenes = Json::array();
    for (const SceneReport& s : r.scenes) scenes.push_back(sceneJson(s));
    out["scenes"] = scenes;
    return out.dump(2) + "\n";
}

}  // namespace candela::app
