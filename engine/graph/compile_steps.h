#pragma once
// Internal to candela_graph: the compile steps run by compileGraph() (compiled_graph.h), in order
// validate → cull → order → unread writes → lifetimes → attachments → aliasing → barriers, and the
// dependency analysis they share.
// Each step is a free function that fills its part of CompiledGraph and appends its name to
// CompiledGraph::steps. Not installed and not used outside engine/graph.

#include "graph/compiled_graph.h"

#include <string>
#include <vector>

namespace candela::graph::detail {

// Every write access bit of synchronization2 that the graph can produce or receive from outside.
inline constexpr VkAccessFlags2 kWriteAccessMask =
    VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;

// "'name'", for error messages and cull details.
inline std::string quotedName(const std::string& name) { return "'" + name + "'"; }

// An edge of the pass graph, stored with the later pass: `pass` must run first because of `resource`.
struct PassEdge {
    uint32_t pass = kInvalidIndex;
    uint32_t resource = kInvalidIndex;
};

// Who produces and reads each version of each resource and what each pass waits for.
// Built by validateGraph; read by the later steps.
struct GraphAnalysis {
    std::vector<std::vector<uint32_t>> producers;             // [resource][version] → pass or kInvalidIndex
    std::vector<std::vector<std::vector<uint32_t>>> readers;  // [resource][version] → reading passes
    std::vector<std::vector<PassEdge>> dependencies;  // [pass] producers whose contents the pass needs
    std::vector<std::vector<PassEdge>> predecessors;  // [pass] dependencies + WAW and WAR edges, one per pass
    std::vector<uint32_t> topological;                // every declared pass, predecessors first
};

// Step "validate" (compile_graph.cpp): checks indices, producers and acyclicity, builds the analysis
// and initialises compiled.passes. Throws GraphError naming the pass(es) and resource.
GraphAnalysis validateGraph(const GraphDecl& decl, CompiledGraph& compiled);

// Step "cull" (cull_passes.cpp): sets PassInfo::cullReason/cullDetail of every pass.
void cullPasses(const GraphDecl& decl, const GraphAnalysis& analysis, CompiledGraph& compiled);

// Step "order" (order_passes.cpp): fills compiled.order with the surviving passes.
void orderPasses(const GraphAnalysis& analysis, CompiledGraph& compiled);

// Step "unread writes" (find_unread_writes.cpp): fills PassInfo::unreadWrites from compiled.order.
void findUnreadWrites(const GraphDecl& decl, CompiledGraph& compiled);

// Step "lifetimes" (compile_graph.cpp): fills compiled.lifetimes from compiled.order.
void computeLifetimes(const GraphDecl& decl, CompiledGraph& compiled);

// Step "attachments" (plan_attachments.cpp): fills PassInfo::attachments of the running passes and
// compiled.transientAttachments, from compiled.order, unreadWrites, clearedLostInputs and lifetimes.
void planAttachments(const GraphDecl& decl, CompiledGraph& compiled);

// Step "aliasing" (plan_aliasing.cpp): places used transients in heaps; fills placements, heaps and
// the byte counts.
void planAliasing(const GraphDecl& decl, const CompileOptions& options, CompiledGraph& compiled);

// Step "barriers" (plan_barriers.cpp): fills barriers, finalBarriers and finalStates.
void planBarriers(const GraphDecl& decl, CompiledGraph& compiled);

// Kahn's algorithm over the passes p with include[p]; among ready passes the lowest declaration
// index goes first. `predecessors` must hold at most one edge per (pass, predecessor) pair.
// Returns fewer passes than included when the edges contain a cycle.
std::vector<uint32_t> sortPasses(const std::vector<std::vector<PassEdge>>& predecessors,
                                 const std::vector<bool>& include);

// Throws the GraphError describing one cycle among the passes that `sorted` (the partial result of
// sortPasses over all passes) left out: "cycle between passes 'a' -> 'b' -> 'a' (via 'tex')".
[[noreturn]] void throwCycleError(const GraphDecl& decl,
                                  const std::vector<std::vector<PassEdge>>& predecessors,
                                  const std::vector<uint32_t>& sorted);

}  // namespace candela::graph::detail
