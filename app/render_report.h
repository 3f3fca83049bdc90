#pragma once
// What one `candela render` run did, scene by scene: the data behind its summary lines, its JSON
// report (--report) and its HTML page (--html). Filled by the render command.

#include "scene_batch.h"

#include <cstdint>
#include <string>
#include <vector>

namespace candela::app {

struct TextureReport {
    std::string name;           // the glTF image's name or URI
    std::string format;         // "PNG", "JPEG", "WebP", "KTX2 UASTC", …; "" when made in memory
    uint32_t width = 0, height = 0;
    uint64_t encodedBytes = 0;  // of the file it was decoded from
    uint64_t deviceBytes = 0;   // on the device, mips (and a normal-map copy) included
};

struct SceneReport {
    SceneInput input;
    bool ok = false;
    bool resumed = false;  // --resume: its outputs were complete already; not rendered
    std::string error;  // the one-line message of a failed scene
    int exitCode = 0;   // what a run of this scene alone would have exited with
    double loadMs = 0.0;    // reading and decoding the file (on the loading thread), of which:
    double imageDecodeMs = 0.0;     // decoding the images (PNG, JPEG, WebP, KTX2)
    double decompressionMs = 0.0;   // Draco and meshopt geometry
    double geometryMs = 0.0;        // preparing the geometry (optimized orders, levels of detail)
    double loadWaitMs = 0.0;  // how long rendering waited for the load; the rest overlapped the previous scene
    double uploadMs = 0.0;  // to device memory, waited for
    std::vector<double> frameMs;  // per image written: render, wait and read back (CPU wall time)
    std::vector<double> gpuMs;    // per image written: the GPU time of its passes
    uint64_t triangles = 0;       // of the scene's draws (full detail)
    uint32_t draws = 0;
    std::vector<TextureReport> textures;
    std::vector<std::string> extensions;  // the file's extensionsUsed
    std::vector<std::string> variants;    // the KHR_materials_variants drawn ("" for the default materials)
    std::vector<std::string> warnings;    // the loader's and the renderer's
    std::vector<std::string> notes;
    struct Output {
        std::string file;
        std::string label;  // what it shows: "render", the variant, "frame 3", "blue, frame 3"
    };
    std::vector<Output> outputs;  // the files written
    uint32_t validationMessages = 0;      // --validate
    uint64_t hostBytes = 0;    // resident host memory when its images were written
    uint64_t deviceBytes = 0;  // device memory in use by resources then
    // What stayed once the scene was released (its host and device memory freed): flat over a
    // run when nothing is kept from one scene to the next. Host: the resident size after the
    // freed heap was returned to the system (the next scene's load runs meanwhile: noise).
    uint64_t retainedHostBytes = 0;
    uint64_t retainedDeviceBytes = 0;
};

struct RunReport {
    std::string version;       // "candela 0.3.0"
    std::string device;        // the chosen device's name
    std::string environment;   // what lit the scenes
    uint32_t width = 0, height = 0;
    Shard shard;
    size_t scenesListed = 0;   // before --shard took this machine's share
    double totalMs = 0.0;      // the whole run, device creation included
    double startupMs = 0.0;    // device creation and environment loading
    double precomputeMs = -1.0;  // the environment's precompute (negative: none)
    uint32_t precomputes = 0;    // how often the environment was precomputed (1 with an environment)
    uint64_t peakHostBytes = 0;    // the largest SceneReport::hostBytes
    uint64_t peakDeviceBytes = 0;  // the largest SceneReport::deviceBytes
    uint64_t peakDeviceMemoryBytes = 0;  // the most device memory held then (the allocator's blocks)
    bool gpuMsUnreliable = false;  // SceneReport::gpuMs miss deferred work (a CPU device: graph::GraphTimings)
    std::vector<SceneReport> scenes;

    size_t failed() const;
};

// The report as JSON (fields described in docs/pipelines.md).
std::string reportJson(const RunReport& report);

}  // namespace candela::app
