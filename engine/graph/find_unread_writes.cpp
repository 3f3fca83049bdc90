// Step "unread writes": which results of a running pass nothing after it reads. What the graph
// does with them: attachments not stored, resolves not done (PassInfo::unreadWrites).
//
// The passes run one after another, so the contents a pass leaves in a resource are read exactly
// when the next running pass that touches the resource reads it or draws over it (a preserving
// write). A discarding write, and a resolve, which replaces the whole image, end them unread.
// Outputs (imported and exported resources) are read after the graph.

#include "graph/compile_steps.h"


namespace candela::graph::detail {

namespace {

enum class NextUse { None, Reads, Replaces };

// How pass `pass` next touches `resource`: reads its contents (a read, or a preserving write other
// than a resolve), replaces them, or not at all.
NextUse useBy(const PassDecl& pass, uint32_t resource) {
    NextUse use = NextUse::None;
    for (const AccessDecl& access : pass.reads)
        if (access.resource == resource) return NextUse::Reads;
    for (const AccessDecl& access : pass.writes) {
        if (access.resource != resource) continue;
        if (access.mode == WriteMode::Preserve && access.usage != Usage::ResolveAttachment) return NextUse::Reads;
        use = NextUse::Replaces;
    }
    return use;
}

}  // namespace

void findUnreadWrites(const GraphDecl& decl, CompiledGraph& compiled) {
    for (size_t i = 0; i < compiled.order.size(); ++i) {
        PassInfo& info = compiled.passes[compiled.order[i]];
        for (const AccessDecl& write : decl.passes[compiled.order[i]].writes) {
            const ResourceDecl& resource = decl.resources[write.resource];
            if (resource.imported || resource.exported) continue;
            NextUse next = NextUse::None;
            for (size_t j = i + 1; j < compiled.order.size() && next == NextUse::None; ++j)
                next = useBy(decl.passes[compiled.order[j]], write.resource);
            if (next != NextUse::Reads && !info.writeUnread(write.resource)) info.unreadWrites.push_back(write.resource);
        }
    }
    compiled.steps.emplace_back("unread writes");
}

}  // namespace candela::graph::detail
