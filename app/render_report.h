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
    double imageDecodeMs = 0.0;     // decoding the images (PNG, JPEG, WebP, KTX2): its wall time,
    double imageDecodeWaitMs = 0.0; //   of which the rest of the load waited this (it ran beside the meshes)
    double decompressionMs = 0.0;   // Draco and meshopt geometry
    double geometryMs = 0.0;        // preparing the geometry (optimized orders, levels of detail)
    double loadWaitMs = 0.0;  // how long rendering waited for the load; the rest overlapped the device's start or the previous scene
    double parseMs = 0.0;   // of loadMs, the rest: reading and parsing the file, converting its data
    double lodMs = 0.0;     // building its levels of detail before its frames (the cost model's choice)
    double uploadMs = 0.0;  // to device memory, waited for
    uint64_t pipelines = 0;     // pipelines created during its frames,
    double pipelineMs = 0.0;    // and the time that took, summed over threads (lavapipe's shader JIT)
    std::vector<double> frameMs;  // per image written: render, wait and read back (CPU wall time)
    std::vector<double> gpuMs;    // per image written: the GPU time of its passes
    std::vector<double> readbackMs;  // per image written: of frameMs, copying the pixels to the host
    std::vector<double> encodeMs;    // per image written: encoding and writing its files
    uint64_t triangles = 0;       // of the scene's draws (full detail)
    uint32_t draws = 0;
    // The work its images asked of the renderer, in deterministic counts (the times above vary):
    // the last image's draws, triangles, levels, state changes and scheduled passes; the texels
    // decoded from the file; the meshes given levels of detail; the environment precomputes its
    // frames ran (0: the maps were kept, or loaded from the cache). Pinned for the default views by
    // tests/cli/work_counters_test.cpp.
    struct Work {
        uint32_t drawsSubmitted = 0, culledDraws = 0, coarserDraws = 0;
        uint64_t trianglesSubmitted = 0;
        uint32_t pipelineBinds = 0, descriptorBinds = 0;
        std::vector<std::string> passes;
        uint64_t texelsDecoded = 0;
        uint64_t simplifiedMeshes = 0;
        uint32_t iblPrecomputes = 0;
        // Pipelines created for the scene's frames (as `pipelines`); of one scene per run, a count
        // that does not vary (in a batch, those compiled ahead for a scene may land in the one before).
        uint64_t pipelinesCreated = 0;
    } work;
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
    double processStartMs = -1.0;  // from the process's creation to the render command (negative: unknown)
    double startupMs = 0.0;    // device creation and environment loading, side by side (Session::loadWhileStarting):
    double environmentMs = 0.0;  //   reading (or making) the environment, and its maps (after the device)
    double deviceMs = 0.0;       //   starting the device and the renderer
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

// The time-to-image profile in words (--verbose): where a scene's time went, from its file to its
// files written, e.g. "time to image, Duck: parse 4 ms, texture decode 12 ms, …"; and the run's
// own part, from the process's creation to the first scene.
std::string sceneTimeLine(const SceneReport& scene);
std::string runTimeLine(const RunReport& report);

}  // namespace candela::app
