#pragma once
// The declared graph as plain data: what RenderGraph's setup phase records and what compile()
// consumes. Unit tests may build a GraphDecl directly (including malformed ones: cycles, reads of
// versions nobody writes) to exercise the compile steps.

#include "graph/graph_types.h"

#include <optional>
#include <string>
#include <vector>

namespace candela::graph {

struct ResourceDecl {
    std::string name;
    ResourceKind kind = ResourceKind::Texture;
    TextureDesc texture;  // kind == Texture
    BufferDesc buffer;    // kind == Buffer
    // Imported resources live outside the graph (persistent): never aliased, their contents at
    // version 0 are valid, and every pass writing them is an output of the graph.
    bool imported = false;
    // Exported transients are outputs too (their writers are kept) and live to the end of the graph.
    bool exported = false;
    ResourceState initialState;               // imported only: how it was last used before the graph
    std::optional<ResourceState> finalState;  // imported/exported: state required after the graph
    uint32_t versionCount = 1;                // versions handed out so far (v0 exists on creation)
};

// One access of a pass to one version of a resource.
// Reads name the version read. Writes name the version they produce (> 0); they consume the
// version before it (contents kept if mode == Preserve, ordering only if Discard).
struct AccessDecl {
    uint32_t resource = kInvalidIndex;
    uint32_t version = 0;
    Usage usage = Usage::Sampled;
    VkPipelineStageFlags2 stageOverride = 0;  // 0: derived from the pass type
    WriteMode mode = WriteMode::Preserve;     // writes only
    // Attachments only: clear value applied when the pass begins rendering (mode must be Discard).
    std::optional<VkClearValue> clear;
    // Preserving attachment writes only: when the pass that should produce the consumed version
    // does not run, clear to this value instead of culling this pass (overlays such as the UI).
    std::optional<VkClearValue> clearIfLost;
    // ResolveAttachment writes only: the multisampled colour attachment of the same pass whose
    // samples are averaged into this image when the pass ends rendering.
    uint32_t resolveSource = kInvalidIndex;
};

struct PassDecl {
    std::string name;
    PassType type = PassType::Graphics;
    bool sideEffect = false;  // kept even when no output depends on it (e.g. readback to host)
    bool enabled = true;      // runtime toggle; disabled passes are culled like unused ones
    // Non-empty: the pass cannot be switched off, and why (PassBuilder::cannotBeDisabled): the
    // frame's callers refuse to disable it (render/frame_runner.cpp, the viewer's graph panel).
    std::string cannotBeDisabled;
    std::vector<AccessDecl> reads;
    std::vector<AccessDecl> writes;
};

struct GraphDecl {
    std::vector<ResourceDecl> resources;
    std::vector<PassDecl> passes;
};

// How one pass uses one resource: every access it declared to it merged into one state (stages
// and accesses or-ed; differing layouts fall back to GENERAL, since one layout must serve every use
// within the pass). The barrier planner waits for and transitions into exactly this state, and
// PassContext reports its layout to the pass. Precondition: `pass` declares an access to `resource`.
ResourceState passAccessState(const GraphDecl& decl, const PassDecl& pass, uint32_t resource);

// The access through which pass `pass` may use (kind, index, version): a read of that version, or
// the write that produces it. Throws GraphError naming the pass and the resource and listing what
// the pass declared when there is none: a pass may touch only what its setup declared, since an
// undeclared access gets no barrier.
const AccessDecl& declaredAccess(const GraphDecl& decl, uint32_t pass, ResourceKind kind, uint32_t index,
                                 uint32_t version);

}  // namespace candela::graph
