// compileGraph() and its two smallest steps: validate (with the dependency analysis every later
// step reads) and lifetimes.

#include "graph/compile_steps.h"

#include <algorithm>

namespace candela::graph {

using detail::GraphAnalysis;
using detail::PassEdge;
using detail::quotedName;

const char* cullReasonName(CullReason reason) {
    switch (reason) {
    case CullReason::None: return "None";
    case CullReason::Disabled: return "Disabled";
    case CullReason::LostInput: return "LostInput";
    case CullReason::NoOutput: return "NoOutput";
    }
    return "Unknown";
}

CompiledGraph compileGraph(const GraphDecl& decl, const CompileOptions& options) {
    CompiledGraph compiled;
    const GraphAnalysis analysis = detail::validateGraph(decl, compiled);
    detail::cullPasses(decl, analysis, compiled);
    detail::orderPasses(analysis, compiled);
    detail::findUnreadWrites(decl, compiled);
    detail::computeLifetimes(decl, compiled);
    detail::planAttachments(decl, compiled);
    detail::planAliasing(decl, options, compiled);
    detail::planBarriers(decl, compiled);
    return compiled;
}

namespace detail {

namespace {

// Adds `edge` unless it points at the pass itself or the predecessor is already listed.
void addEdge(std::vector<PassEdge>& edges, uint32_t self, PassEdge edge) {
    if (edge.pass == kInvalidIndex || edge.pass == self) return;
    const bool known = std::any_of(edges.begin(), edges.end(),
                                   [&](const PassEdge& e) { return e.pass == edge.pass; });
    if (!known) edges.push_back(edge);
}

bool isAttachment(Usage usage) {
    return usage == Usage::ColorAttachment || usage == Usage::DepthAttachment || usage == Usage::DepthRead;
}

// Multisampled images are attachments, or read sample by sample through a sampler (texelFetch of a
// sampler2DMS: the visibility path's classification and shading); a pass's attachments share one
// sample count; a resolve names a multisampled colour attachment the pass writes. Precondition:
// indices checked.
void checkMultisampling(const GraphDecl& decl, const PassDecl& pass) {
    uint32_t samples = 0;
    for (const auto* list : {&pass.reads, &pass.writes})
        for (const AccessDecl& access : *list) {
            const ResourceDecl& resource = decl.resources[access.resource];
            const uint32_t count = resource.texture.samples;
            if (resource.kind != ResourceKind::Texture) continue;
            if (count > 1 && !isAttachment(access.usage) && access.usage != Usage::Sampled)
                throw GraphError("pass " + quotedName(pass.name) + " uses multisampled " + quotedName(resource.name) + " as " +
                                 usageName(access.usage) +
                                 ": a multisampled image is an attachment or sampled (resolve it to use it otherwise)");
            if (!isAttachment(access.usage)) continue;
            if (samples != 0 && count != samples)
                throw GraphError("pass " + quotedName(pass.name) + " draws into attachments of " + std::to_string(samples) +
                                 " and " + std::to_string(count) + " samples (" + quotedName(resource.name) + ")");
            samples = count;
        }
    for (const AccessDecl& access : pass.writes) {
        if (access.usage != Usage::ResolveAttachment) continue;
        const bool drawn = std::any_of(pass.writes.begin(), pass.writes.end(), [&](const AccessDecl& a) {
            return a.usage == Usage::ColorAttachment && a.resource == access.resolveSource &&
                   decl.resources[a.resource].texture.samples > 1;
        });
        if (!drawn)
            throw GraphError("pass " + quotedName(pass.name) + " resolves into " + quotedName(decl.resources[access.resource].name) +
                             " from no multisampled colour attachment it writes");
    }
}

// Index ranges, usage direction and version 0 writes: the checks that need no producer table.
void checkAccesses(const GraphDecl& decl) {
    for (const PassDecl& pass : decl.passes) {
        for (const AccessDecl& access : pass.reads) {
            if (access.resource >= decl.resources.size())
                throw GraphError("pass " + quotedName(pass.name) + " reads resource index " +
                                 std::to_string(access.resource) + ", which does not exist");
            if (usageWrites(access.usage))
                throw GraphError("pass " + quotedName(pass.name) + " reads " +
                                 quotedName(decl.resources[access.resource].name) + " with writing usage " +
                                 usageName(access.usage));
        }
        for (const AccessDecl& access : pass.writes) {
            if (access.resource >= decl.resources.size())
                throw GraphError("pass " + quotedName(pass.name) + " writes resource index " +
                                 std::to_string(access.resource) + ", which does not exist");
            const std::string& resource = decl.resources[access.resource].name;
            if (!usageWrites(access.usage))
                throw GraphError("pass " + quotedName(pass.name) + " writes " + quotedName(resource) +
                                 " with read-only usage " + usageName(access.usage));
            if (access.version == 0)
                throw GraphError("pass " + quotedName(pass.name) + " writes " + quotedName(resource) +
                                 " (version 0): a write produces a version > 0");
        }
        checkMultisampling(decl, pass);
    }
}

}  // namespace

GraphAnalysis validateGraph(const GraphDecl& decl, CompiledGraph& compiled) {
    checkAccesses(decl);
    const size_t passCount = decl.passes.size();
    GraphAnalysis analysis;

    // Size version tables by the highest version named: a hand-built GraphDecl may leave versionCount stale.
    std::vector<uint32_t> versions(decl.resources.size(), 1);
    for (const PassDecl& pass : decl.passes) {
        for (const auto* list : {&pass.reads, &pass.writes})
            for (const AccessDecl& access : *list)
                versions[access.resource] = std::max(versions[access.resource], access.version + 1);
    }
    analysis.producers.resize(decl.resources.size());
    analysis.readers.resize(decl.resources.size());
    for (size_t r = 0; r < decl.resources.size(); ++r) {
        analysis.producers[r].assign(versions[r], kInvalidIndex);
        analysis.readers[r].resize(versions[r]);
    }

    for (uint32_t p = 0; p < passCount; ++p) {
        for (const AccessDecl& access : decl.passes[p].writes) {
            uint32_t& producer = analysis.producers[access.resource][access.version];
            if (producer != kInvalidIndex && producer != p)
                throw GraphError("passes " + quotedName(decl.passes[producer].name) + " and " +
                                 quotedName(decl.passes[p].name) + " both write " +
                                 quotedName(decl.resources[access.resource].name) + " (version " +
                                 std::to_string(access.version) + ")");
            producer = p;
        }
        for (const AccessDecl& access : decl.passes[p].reads)
            analysis.readers[access.resource][access.version].push_back(p);
    }

    analysis.dependencies.resize(passCount);
    analysis.predecessors.resize(passCount);
    for (uint32_t p = 0; p < passCount; ++p) {
        const PassDecl& pass = decl.passes[p];
        std::vector<PassEdge>& dependencies = analysis.dependencies[p];
        std::vector<PassEdge>& predecessors = analysis.predecessors[p];
        for (const AccessDecl& access : pass.reads) {
            const ResourceDecl& resource = decl.resources[access.resource];
            const uint32_t producer = analysis.producers[access.resource][access.version];
            // Version 0 of an import holds valid contents; anything else needs a producer.
            if (producer == kInvalidIndex && !(access.version == 0 && resource.imported))
                throw GraphError("pass " + quotedName(pass.name) + " reads " + quotedName(resource.name) +
                                 " (version " + std::to_string(access.version) +
                                 "), which no pass writes");
            addEdge(dependencies, p, {producer, access.resource});
        }
        for (const AccessDecl& access : pass.writes) {
            const uint32_t previous = analysis.producers[access.resource][access.version - 1];
            if (access.mode == WriteMode::Preserve) addEdge(dependencies, p, {previous, access.resource});
        }
        for (const PassEdge& edge : dependencies) addEdge(predecessors, p, edge);
        for (const AccessDecl& access : pass.writes) {
            // WAW: the previous version's producer first; WAR: its readers must see it before it changes.
            addEdge(predecessors, p,
                    {analysis.producers[access.resource][access.version - 1], access.resource});
            for (uint32_t reader : analysis.readers[access.resource][access.version - 1])
                addEdge(predecessors, p, {reader, access.resource});
        }
    }

    analysis.topological = sortPasses(analysis.predecessors, std::vector<bool>(passCount, true));
    if (analysis.topological.size() != passCount)
        throwCycleError(decl, analysis.predecessors, analysis.topological);

    compiled.passes.resize(passCount);
    for (uint32_t p = 0; p < passCount; ++p) compiled.passes[p].pass = p;
    compiled.steps.emplace_back("validate");
    return analysis;
}

void computeLifetimes(const GraphDecl& decl, CompiledGraph& compiled) {
    compiled.lifetimes.assign(decl.resources.size(), Lifetime{});
    for (uint32_t i = 0; i < compiled.order.size(); ++i) {
        const PassDecl& pass = decl.passes[compiled.order[i]];
        for (const auto* list : {&pass.reads, &pass.writes}) {
            for (const AccessDecl& access : *list) {
                Lifetime& lifetime = compiled.lifetimes[access.resource];
                // Passes are visited in execution order, so the first touch is the first use.
                if (!lifetime.used()) lifetime.first = i;
                lifetime.last = i;
            }
        }
    }
    // Exported resources are read after the graph: keep them alive to its end.
    for (size_t r = 0; r < decl.resources.size(); ++r) {
        Lifetime& lifetime = compiled.lifetimes[r];
        if (decl.resources[r].exported && lifetime.used())
            lifetime.last = static_cast<uint32_t>(compiled.order.size() - 1);
    }
    compiled.steps.emplace_back("lifetimes");
}

}  // namespace detail

}  // namespace candela::graph
