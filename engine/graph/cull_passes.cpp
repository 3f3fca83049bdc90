// Step "cull": decides which passes run. First availability (disabled passes and everything that
// needs their results), then reference counting from the outputs over the dependency graph.

#include "graph/compile_steps.h"

namespace candela::graph::detail {

namespace {

bool culledUnavailable(CullReason reason) {
    return reason == CullReason::Disabled || reason == CullReason::LostInput;
}

// Outputs of the graph: passes with a side effect or writing something that outlives the graph.
bool isRoot(const GraphDecl& decl, const PassDecl& pass) {
    if (pass.sideEffect) return true;
    for (const AccessDecl& access : pass.writes) {
        const ResourceDecl& resource = decl.resources[access.resource];
        if (resource.imported || resource.exported) return true;
    }
    return false;
}

}  // namespace

void cullPasses(const GraphDecl& decl, const GraphAnalysis& analysis, CompiledGraph& compiled) {
    // Producers come first in topological order, so their verdict is known when a consumer is visited.
    for (uint32_t p : analysis.topological) {
        PassInfo& info = compiled.passes[p];
        if (!decl.passes[p].enabled) {
            info.cullReason = CullReason::Disabled;
            info.cullDetail = "disabled";
            continue;
        }
        for (const PassEdge& dependency : analysis.dependencies[p]) {
            const CullReason producerReason = compiled.passes[dependency.pass].cullReason;
            if (!culledUnavailable(producerReason)) continue;
            info.cullReason = CullReason::LostInput;
            info.cullDetail = "input " + quoted(decl.resources[dependency.resource].name) +
                              " lost: its producer " + quoted(decl.passes[dependency.pass].name) +
                              (producerReason == CullReason::Disabled ? " is disabled"
                                                                      : " was culled (lost input)");
            break;
        }
    }

    // Keep every available pass an output depends on, following dependencies backwards.
    std::vector<bool> kept(decl.passes.size(), false);
    std::vector<uint32_t> stack;
    for (uint32_t p = 0; p < decl.passes.size(); ++p) {
        if (compiled.passes[p].cullReason == CullReason::None && isRoot(decl, decl.passes[p])) {
            kept[p] = true;
            stack.push_back(p);
        }
    }
    while (!stack.empty()) {
        const uint32_t p = stack.back();
        stack.pop_back();
        for (const PassEdge& dependency : analysis.dependencies[p]) {
            if (kept[dependency.pass]) continue;
            kept[dependency.pass] = true;
            stack.push_back(dependency.pass);
        }
    }
    for (uint32_t p = 0; p < decl.passes.size(); ++p) {
        PassInfo& info = compiled.passes[p];
        if (info.cullReason == CullReason::None && !kept[p]) {
            info.cullReason = CullReason::NoOutput;
            info.cullDetail = "contributes to no output";
        }
    }
    compiled.steps.emplace_back("cull");
}

}  // namespace candela::graph::detail
