// Step "order": a stable topological sort of the surviving passes, plus the cycle report that
// validate raises when no order exists.

#include "graph/compile_steps.h"

#include <algorithm>
#include <functional>
#include <queue>

namespace candela::graph::detail {

std::vector<uint32_t> sortPasses(const std::vector<std::vector<PassEdge>>& predecessors,
                                 const std::vector<bool>& include) {
    const size_t passCount = predecessors.size();
    std::vector<uint32_t> pending(passCount, 0);
    std::vector<std::vector<uint32_t>> successors(passCount);
    for (uint32_t p = 0; p < passCount; ++p) {
        if (!include[p]) continue;
        for (const PassEdge& edge : predecessors[p]) {
            if (!include[edge.pass]) continue;
            ++pending[p];
            successors[edge.pass].push_back(p);
        }
    }
    // A min-heap on the declaration index keeps the order stable and deterministic.
    std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> ready;
    for (uint32_t p = 0; p < passCount; ++p)
        if (include[p] && pending[p] == 0) ready.push(p);
    std::vector<uint32_t> sorted;
    while (!ready.empty()) {
        const uint32_t p = ready.top();
        ready.pop();
        sorted.push_back(p);
        for (uint32_t next : successors[p])
            if (--pending[next] == 0) ready.push(next);
    }
    return sorted;
}

void throwCycleError(const GraphDecl& decl, const std::vector<std::vector<PassEdge>>& predecessors,
                     const std::vector<uint32_t>& sorted) {
    // Every pass Kahn left out has a left-out predecessor, so walking predecessors must loop.
    std::vector<bool> left(predecessors.size(), true);
    for (uint32_t p : sorted) left[p] = false;
    const auto start = static_cast<uint32_t>(std::find(left.begin(), left.end(), true) - left.begin());

    std::vector<uint32_t> path{start};     // path[i + 1] runs before path[i]
    std::vector<uint32_t> via;             // via[i]: resource of the edge path[i + 1] → path[i]
    std::vector<uint32_t> position(predecessors.size(), kInvalidIndex);
    position[start] = 0;
    PassEdge closing;
    for (;;) {
        const auto& edges = predecessors[path.back()];
        const auto edge = std::find_if(edges.begin(), edges.end(),
                                       [&](const PassEdge& e) { return left[e.pass]; });
        if (position[edge->pass] != kInvalidIndex) {
            closing = *edge;
            break;
        }
        position[edge->pass] = static_cast<uint32_t>(path.size());
        path.push_back(edge->pass);
        via.push_back(edge->resource);
    }

    // Forward order: closing.pass → path.back() → ... → path[k] == closing.pass.
    const uint32_t k = position[closing.pass];
    std::vector<uint32_t> cycle{closing.pass};
    std::vector<uint32_t> resources{closing.resource};
    for (size_t i = path.size() - 1; i > k; --i) {
        cycle.push_back(path[i]);
        resources.push_back(via[i - 1]);
    }
    // cycle lists each pass once; resources[i] labels the edge leaving cycle[i].
    // Start at the lowest pass index so the message does not depend on where the walk began.
    const auto first = std::min_element(cycle.begin(), cycle.end()) - cycle.begin();
    std::rotate(cycle.begin(), cycle.begin() + first, cycle.end());
    std::rotate(resources.begin(), resources.begin() + first, resources.end());

    std::string message = "cycle between passes ";
    for (uint32_t p : cycle) message += quotedName(decl.passes[p].name) + " -> ";
    message += quotedName(decl.passes[cycle.front()].name) + " (via ";
    std::vector<uint32_t> named;
    for (uint32_t r : resources) {
        if (std::find(named.begin(), named.end(), r) != named.end()) continue;
        message += (named.empty() ? "" : ", ") + quotedName(decl.resources[r].name);
        named.push_back(r);
    }
    throw GraphError(message + ")");
}

void orderPasses(const GraphAnalysis& analysis, CompiledGraph& compiled) {
    const size_t passCount = compiled.passes.size();
    std::vector<bool> kept(passCount);
    for (uint32_t p = 0; p < passCount; ++p) kept[p] = compiled.passes[p].cullReason == CullReason::None;

    // Constraints through culled passes still bind the kept ones (a kept reader of v0 must run
    // before a kept writer of v2 even when the writer of v1 was culled): walk through culled passes.
    std::vector<std::vector<PassEdge>> keptPredecessors(passCount);
    std::vector<uint32_t> visitedBy(passCount, kInvalidIndex);
    for (uint32_t p = 0; p < passCount; ++p) {
        if (!kept[p]) continue;
        std::vector<PassEdge> stack(analysis.predecessors[p].begin(), analysis.predecessors[p].end());
        while (!stack.empty()) {
            const PassEdge edge = stack.back();
            stack.pop_back();
            if (visitedBy[edge.pass] == p) continue;
            visitedBy[edge.pass] = p;
            if (kept[edge.pass]) {
                keptPredecessors[p].push_back(edge);
                continue;
            }
            for (const PassEdge& next : analysis.predecessors[edge.pass])
                stack.push_back({next.pass, edge.resource});
        }
    }
    compiled.order = sortPasses(keptPredecessors, kept);
    compiled.steps.emplace_back("order");
}

}  // namespace candela::graph::detail
