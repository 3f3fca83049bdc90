// What one pass declared about one resource: the merged state the barrier planner and the pass
// context agree on, and the check that a pass uses only what it declared.

#include "graph/compile_steps.h"

#include <string>

namespace candela::graph {

using detail::quotedName;

namespace {

AccessSync syncOf(const GraphDecl& decl, const PassDecl& pass, const AccessDecl& access) {
    const ResourceDecl& resource = decl.resources[access.resource];
    return accessSync(access.usage, pass.type, resource.kind, access.stageOverride,
                      resource.kind == ResourceKind::Texture && isDepthFormat(resource.texture.format));
}

std::string describe(const GraphDecl& decl, const AccessDecl& access) {
    return quotedName(decl.resources[access.resource].name) + " v" + std::to_string(access.version) + " (" +
           usageName(access.usage) + ")";
}

}  // namespace

ResourceState passAccessState(const GraphDecl& decl, const PassDecl& pass, uint32_t resource) {
    ResourceState state;
    bool first = true;
    for (const auto* list : {&pass.reads, &pass.writes})
        for (const AccessDecl& access : *list) {
            if (access.resource != resource) continue;
            const AccessSync sync = syncOf(decl, pass, access);
            if (first) state.layout = sync.layout;
            else if (state.layout != sync.layout) state.layout = VK_IMAGE_LAYOUT_GENERAL;
            first = false;
            state.stages |= sync.stages;
            state.access |= sync.access;
        }
    return state;
}

const AccessDecl& declaredAccess(const GraphDecl& decl, uint32_t pass, ResourceKind kind, uint32_t index,
                                 uint32_t version) {
    const PassDecl& p = decl.passes.at(pass);
    for (const auto* list : {&p.reads, &p.writes})
        for (const AccessDecl& access : *list)
            if (access.resource == index && access.version == version && decl.resources[index].kind == kind)
                return access;
    const std::string kindName = kind == ResourceKind::Texture ? "texture" : "buffer";
    std::string name = "an invalid " + kindName + " handle";
    if (index < decl.resources.size()) name = quotedName(decl.resources[index].name) + " v" + std::to_string(version);
    std::string declared;
    for (const AccessDecl& access : p.reads) declared += (declared.empty() ? "reads " : ", reads ") + describe(decl, access);
    for (const AccessDecl& access : p.writes) declared += (declared.empty() ? "writes " : ", writes ") + describe(decl, access);
    throw GraphError("pass " + quotedName(p.name) + " uses " + name + ", which its setup did not declare (it declared: " +
                     (declared.empty() ? std::string("nothing") : declared) + ")");
}

}  // namespace candela::graph
