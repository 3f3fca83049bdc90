// Step "cull": decides which passes run. First availability (disabled passes and everything that
// needs their results), then reference counting from the outputs over the dependency graph.
//
// Two refinements keep switched-off passes from taking the frame down with them:
//  - A disabled pass that only adds to what it writes (every write preserves) is bypassed: a pass
//    needing its result needs what it would have drawn over instead (switching off the skybox
//    leaves the scene on a black background rather than culling the tonemap).
//  - A write declared with clearIfLost (PassBuilder::drawOver) survives the loss of its input:
//    the attachment is cleared instead (the UI stays up when the tonemap is switched off).

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

bool bypassable(const PassDecl& pass) {
    if (pass.writes.empty()) return false;
    for (const AccessDecl& access : pass.writes)
        if (access.mode != WriteMode::Preserve) return false;
    return true;
}

// The passes that actually provide what a consumer of `edge.pass` needs: the pass itself, or —
// through a bypassed pass — the producers of everything it would have drawn over (none where the
// chain starts at an imported version; all of its writes, as an edge names one resource per pass).
// Precondition: producers visited first.
void providers(const GraphDecl& decl, const GraphAnalysis& analysis, const CompiledGraph& compiled,
               const PassEdge& edge, std::vector<uint32_t>& out) {
    if (!compiled.passes[edge.pass].bypassed) {
        out.push_back(edge.pass);
        return;
    }
    for (const AccessDecl& write : decl.passes[edge.pass].writes) {
        const uint32_t before = analysis.producers[write.resource][write.version - 1];
        if (before != kInvalidIndex) providers(decl, analysis, compiled, {before, write.resource}, out);
    }
}

bool clearsIfLost(const PassDecl& pass, uint32_t resource) {
    for (const AccessDecl& access : pass.writes)
        if (access.resource == resource && access.clearIfLost) return true;
    return false;
}

}  // namespace

void cullPasses(const GraphDecl& decl, const GraphAnalysis& analysis, CompiledGraph& compiled) {
    // Producers come first in topological order, so their verdict is known when a consumer is visited.
    std::vector<uint32_t> provided;
    for (uint32_t p : analysis.topological) {
        PassInfo& info = compiled.passes[p];
        if (!decl.passes[p].enabled) {
            info.cullReason = CullReason::Disabled;
            info.bypassed = bypassable(decl.passes[p]);
            info.cullDetail = info.bypassed ? "disabled (bypassed: later passes read what it would have drawn over)"
                                            : "disabled";
            continue;
        }
        for (const PassEdge& dependency : analysis.dependencies[p]) {
            provided.clear();
            providers(decl, analysis, compiled, dependency, provided);
            for (uint32_t producer : provided) {
                const CullReason producerReason = compiled.passes[producer].cullReason;
                if (!culledUnavailable(producerReason)) continue;
                if (clearsIfLost(decl.passes[p], dependency.resource)) {
                    info.clearedLostInputs.push_back(dependency.resource);
                    continue;
                }
                info.cullReason = CullReason::LostInput;
                info.lostProducer = producer;
                info.cullDetail = "input " + quotedName(decl.resources[dependency.resource].name) +
                                  " lost: its producer " + quotedName(decl.passes[producer].name) +
                                  (producerReason == CullReason::Disabled ? " is disabled"
                                                                          : " was culled (lost input)");
                break;
            }
            if (info.cullReason != CullReason::None) break;
        }
    }

    // Keep every available pass an output depends on, following dependencies backwards (through
    // bypassed passes to what they would have drawn over).
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
            provided.clear();
            providers(decl, analysis, compiled, dependency, provided);
            for (uint32_t producer : provided) {
                if (kept[producer] || compiled.passes[producer].cullReason != CullReason::None) continue;
                kept[producer] = true;
                stack.push_back(producer);
            }
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
