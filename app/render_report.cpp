#include "render_report.h"

#include "graph/graph_export.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

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
    out["status"] = s.resumed ? "complete" : s.ok ? "ok" : "failed";
    if (!s.ok) {
        out["error"] = s.error;
        out["exitCode"] = s.exitCode;
    }
    out["loadMs"] = ms(s.loadMs);
    out["loadWaitMs"] = ms(s.loadWaitMs);
    out["imageDecodeMs"] = ms(s.imageDecodeMs);
    out["imageDecodeWaitMs"] = ms(s.imageDecodeWaitMs);
    out["decompressionMs"] = ms(s.decompressionMs);
    out["geometryMs"] = ms(s.geometryMs);
    out["parseMs"] = ms(s.parseMs);
    out["lodMs"] = ms(s.lodMs);
    out["uploadMs"] = ms(s.uploadMs);
    out["pipelines"] = s.pipelines;
    out["pipelineMs"] = ms(s.pipelineMs);
    out["frameMs"] = msList(s.frameMs);
    out["gpuMs"] = msList(s.gpuMs);
    out["readbackMs"] = msList(s.readbackMs);
    out["encodeMs"] = msList(s.encodeMs);
    out["triangles"] = s.triangles;
    out["draws"] = s.draws;
    const SceneReport::Work& w = s.work;
    out["work"] = {{"drawsSubmitted", w.drawsSubmitted},
                   {"culledDraws", w.culledDraws},
                   {"coarserDraws", w.coarserDraws},
                   {"trianglesSubmitted", w.trianglesSubmitted},
                   {"pipelineBinds", w.pipelineBinds},
                   {"descriptorBinds", w.descriptorBinds},
                   {"passes", w.passes},
                   {"texelsDecoded", w.texelsDecoded},
                   {"simplifiedMeshes", w.simplifiedMeshes},
                   {"iblPrecomputes", w.iblPrecomputes},
                   {"pipelinesCreated", w.pipelinesCreated}};
    Json textures = Json::array();
    uint64_t encoded = 0, device = 0;
    for (const TextureReport& t : s.textures) {
        textures.push_back({{"name", t.name},
                            {"format", t.format},
                            {"width", t.width},
                            {"height", t.height},
                            {"encodedBytes", t.encodedBytes},
                            {"deviceBytes", t.deviceBytes}});
        encoded += t.encodedBytes;
        device += t.deviceBytes;
    }
    out["textureEncodedBytes"] = encoded;
    out["textureDeviceBytes"] = device;
    out["textures"] = textures;
    out["extensions"] = s.extensions;
    out["variants"] = s.variants;
    out["warnings"] = s.warnings;
    out["notes"] = s.notes;
    out["validationMessages"] = s.validationMessages;
    Json outputs = Json::array();
    for (const SceneReport::Output& o : s.outputs) outputs.push_back(o.file);
    out["outputs"] = outputs;
    out["hostBytes"] = s.hostBytes;
    out["deviceBytes"] = s.deviceBytes;
    out["retainedHostBytes"] = s.retainedHostBytes;
    out["retainedDeviceBytes"] = s.retainedDeviceBytes;
    return out;
}

}  // namespace

size_t RunReport::failed() const {
    return size_t(std::count_if(scenes.begin(), scenes.end(), [](const SceneReport& s) { return !s.ok; }));
}

namespace {

std::string millis(double value) {
    char text[32];
    std::snprintf(text, sizeof text, value < 10.0 ? "%.1f ms" : "%.0f ms", value);
    return text;
}

double sum(const std::vector<double>& values) {
    double total = 0.0;
    for (double v : values) total += v;
    return total;
}

}  // namespace

std::string sceneTimeLine(const SceneReport& s) {
    return "time to image, " + s.input.name + ": parse " + millis(s.parseMs) + ", texture decode " + millis(s.imageDecodeMs) +
           " (the rest of the load waited " + millis(s.imageDecodeWaitMs) + " for it), Draco/meshopt " +
           millis(s.decompressionMs) + ", geometry " + millis(s.geometryMs - s.lodMs) +
           " (waited for the load " + millis(s.loadWaitMs) + "), levels of detail " + millis(s.lodMs) + ", upload " +
           millis(s.uploadMs) + ", " + std::to_string(s.frameMs.size()) + (s.frameMs.size() == 1 ? " frame " : " frames ") +
           millis(sum(s.frameMs)) + " (of it read-back " + millis(sum(s.readbackMs)) + "; " + std::to_string(s.pipelines) +
           " pipelines created, " + millis(s.pipelineMs) + " of the driver compiling their shaders), encoding and writing " +
           millis(sum(s.encodeMs));
}

std::string runTimeLine(const RunReport& r) {
    return "time to image, the run: process start " + (r.processStartMs >= 0.0 ? millis(r.processStartMs) : std::string("unknown")) +
           ", environment " + millis(r.environmentMs) + ", device " + millis(r.deviceMs) + " (start-up " + millis(r.startupMs) +
           "), environment precompute " + (r.precomputeMs >= 0.0 ? millis(r.precomputeMs) + " (in the first frame)" : std::string("none")) +
           ", total " + millis(r.totalMs);
}

std::string reportJson(const RunReport& r) {
    Json out;
    out["candela"] = r.version;
    out["device"] = r.device;
    out["environment"] = r.environment;
    out["width"] = r.width;
    out["height"] = r.height;
    out["shard"] = {{"index", r.shard.index}, {"count", r.shard.count}};
    out["scenesListed"] = r.scenesListed;
    out["scenesRendered"] = r.scenes.size() - r.failed();
    out["scenesFailed"] = r.failed();
    out["totalMs"] = ms(r.totalMs);
    out["processStartMs"] = ms(r.processStartMs);
    out["startupMs"] = ms(r.startupMs);
    out["environmentMs"] = ms(r.environmentMs);
    out["deviceMs"] = ms(r.deviceMs);
    out["precomputeMs"] = ms(r.precomputeMs);
    out["precomputes"] = r.precomputes;
    out["peakHostBytes"] = r.peakHostBytes;
    out["peakDeviceBytes"] = r.peakDeviceBytes;
    out["peakDeviceMemoryBytes"] = r.peakDeviceMemoryBytes;
    if (r.gpuMsUnreliable) out["gpuMsUnreliable"] = graph::kUnreliableGpuTimes;
    Json scenes = Json::array();
    for (const SceneReport& s : r.scenes) scenes.push_back(sceneJson(s));
    out["scenes"] = scenes;
    return out.dump(2) + "\n";
}

}  // namespace candela::app
