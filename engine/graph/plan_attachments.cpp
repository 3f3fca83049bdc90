// Step "attachments": how each running pass begins and ends rendering on its colour and depth
// attachments (load and store operations, PassInfo::attachments), and which transients never
// leave the one render pass that uses them (CompiledGraph::transientAttachments).
//
// Load: a declared clear, or the clearIfLost value when the attachment's producer does not run,
// clears; a discarding write does not care; a preserving write loads what an earlier running pass
// wrote (or an import's contents) — with nothing written before, there is nothing to load and it
// does not care either. A depth test (DepthRead) loads. Store: what the unread-writes step found
// read later is stored, other writes are not (don't care); a DepthRead stores nothing (none).
//
// A transient attachment is used by exactly one running pass, which neither loads nor stores it,
// and is declared (by any pass, culled or not: one image serves every frame of that graph) only as
// a colour or depth attachment. Anything stored by one pass and loaded by another — the forward
// pass's multisampled colour and depth that the skybox draws over and tests against — is not:
// tile-based GPUs keep a lazily allocated (Apple: memoryless) attachment in tile memory alone and
// drop it when the render pass ends.

#include "graph/compile_steps.h"

#include <algorithm>

namespace candela::graph {

const char* loadOpName(LoadOp op) {
    switch (op) {
    case LoadOp::Load: return "load";
    case LoadOp::Clear: return "clear";
    case LoadOp::DontCare: return "dont-care";
    }
    return "unknown";
}

const char* storeOpName(StoreOp op) {
    switch (op) {
    case StoreOp::Store: return "store";
    case StoreOp::DontCare: return "dont-care";
    case StoreOp::None: return "none";
    }
    return "unknown";
}

namespace detail {

namespace {

bool isDrawnAttachment(Usage usage) { return usage == Usage::ColorAttachment || usage == Usage::DepthAttachment; }

// Whether any of the first `count` passes of compiled.order writes `resource`.
bool writtenBefore(const GraphDecl& decl, const CompiledGraph& compiled, size_t count, uint32_t resource) {
    for (size_t i = 0; i < count; ++i) {
        const std::vector<AccessDecl>& writes = decl.passes[compiled.order[i]].writes;
        if (std::any_of(writes.begin(), writes.end(), [&](const AccessDecl& w) { return w.resource == resource; }))
            return true;
    }
    return false;
}

// The operations of attachment write `write` of the pass at position `position` of the order.
AttachmentOps writeOps(const GraphDecl& decl, const CompiledGraph& compiled, size_t position, const AccessDecl& write) {
    const PassInfo& info = compiled.passes[compiled.order[position]];
    AttachmentOps ops{.resource = write.resource,
                      .load = LoadOp::DontCare,
                      .store = info.writeUnread(write.resource) ? StoreOp::DontCare : StoreOp::Store};
    const bool lost = std::find(info.clearedLostInputs.begin(), info.clearedLostInputs.end(), write.resource) !=
                      info.clearedLostInputs.end();
    if (write.clear) {
        ops.load = LoadOp::Clear;
        ops.clear = *write.clear;
    } else if (lost && write.clearIfLost) {
        ops.load = LoadOp::Clear;
        ops.clear = *write.clearIfLost;
    } else if (write.mode == WriteMode::Preserve &&
               (decl.resources[write.resource].imported || writtenBefore(decl, compiled, position, write.resource))) {
        ops.load = LoadOp::Load;
    }
    return ops;
}

// Whether every access any declared pass makes of `resource` is a colour or depth attachment
// access (so its image needs no usage but attachment usage).
bool declaredAsAttachmentOnly(const GraphDecl& decl, uint32_t resource) {
    for (const PassDecl& pass : decl.passes)
        for (const auto* list : {&pass.reads, &pass.writes})
            for (const AccessDecl& access : *list)
                if (access.resource == resource && !isDrawnAttachment(access.usage) && access.usage != Usage::DepthRead)
                    return false;
    return true;
}

}  // namespace

void planAttachments(const GraphDecl& decl, CompiledGraph& compiled) {
    for (size_t i = 0; i < compiled.order.size(); ++i) {
        const PassDecl& pass = decl.passes[compiled.order[i]];
        PassInfo& info = compiled.passes[compiled.order[i]];
        info.attachments.clear();
        for (const AccessDecl& write : pass.writes)
            if (isDrawnAttachment(write.usage)) info.attachments.push_back(writeOps(decl, compiled, i, write));
        for (const AccessDecl& read : pass.reads)
            if (read.usage == Usage::DepthRead)
                info.attachments.push_back({.resource = read.resource, .load = LoadOp::Load, .store = StoreOp::None});
    }

    compiled.transientAttachments.assign(decl.resources.size(), false);
    for (uint32_t r = 0; r < decl.resources.size(); ++r) {
        const ResourceDecl& resource = decl.resources[r];
        const Lifetime& lifetime = compiled.lifetimes[r];
        if (resource.kind != ResourceKind::Texture || resource.imported || resource.exported || !lifetime.used() ||
            lifetime.first != lifetime.last || !declaredAsAttachmentOnly(decl, r))
            continue;
        // Its one running pass: every access it makes (the attachment-only declaration above leaves
        // only attachment accesses) neither loads nor stores.
        const PassDecl& pass = decl.passes[compiled.order[lifetime.first]];
        const PassInfo& info = compiled.passes[compiled.order[lifetime.first]];
        bool insidePass = true;
        for (const auto* list : {&pass.reads, &pass.writes})
            for (const AccessDecl& access : *list) {
                if (access.resource != r) continue;
                const AttachmentOps* ops = info.attachmentOps(r);
                insidePass = insidePass && ops && ops->load != LoadOp::Load && ops->store != StoreOp::Store;
            }
        compiled.transientAttachments[r] = insidePass;
    }
    compiled.steps.emplace_back("attachments");
}

}  // namespace detail

}  // namespace candela::graph
