#pragma once
// Export of a compiled graph for people and tools: Graphviz dot and JSON. Both list the passes in
// execution order, the resources with their lifetimes and aliasing (heap, offset, size), the
// barriers, the culled passes with their reasons, and per-pass GPU times when measured (with
// kUnreliableGpuTimes when the device's timestamps miss deferred work).

#include "graph/compiled_graph.h"

#include <string>
#include <vector>

namespace candela::graph {

// Per-pass timings of one execution, indexed like GraphDecl::passes. A negative value means the
// pass did not run or was not measured.
struct GraphTimings {
    std::vector<double> gpuMs;
    // Per declared pass: host wall milliseconds of the pass submitted and waited for alone
    // (RenderSettings::serialPasses; negative for passes that did not run). Empty when the frame
    // ran as one submit. On devices whose timestamps mark when commands are issued rather than
    // when deferred work runs (lavapipe rasterizes at the end of a render pass), only these show
    // where the time goes.
    std::vector<double> serialMs;
    // Whether gpuMs miss work the device runs after a pass's closing timestamp (lavapipe:
    // vk::timestampsMeasurePasses is false). Every output that prints gpuMs then says so, with
    // kUnreliableGpuTimes.
    bool gpuMsUnreliable = false;
};

// Said wherever per-pass GPU times are shown while GraphTimings::gpuMsUnreliable.
inline constexpr const char* kUnreliableGpuTimes =
    "per-pass GPU times are unreliable on lavapipe: its timestamps mark when a pass's commands are "
    "issued, while the work runs later (llvmpipe rasterizes a render pass's draws when it ends), so a pass's "
    "cost shows in another pass or in none; `candela bench` measures each pass submitted alone";

std::string exportDot(const GraphDecl& decl, const CompiledGraph& compiled,
                      const GraphTimings* timings = nullptr);
std::string exportJson(const GraphDecl& decl, const CompiledGraph& compiled,
                       const GraphTimings* timings = nullptr);

}  // namespace candela::graph
