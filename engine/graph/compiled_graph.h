#pragma once
// Result of RenderGraph compilation: which passes run and in what order, why the others were
// culled, transient lifetimes and their memory placement after aliasing, and the barriers to emit.
// Pure data; the executor (graph_executor.h) turns it into Vulkan commands.

#include "graph/graph_decl.h"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace candela::graph {

enum class CullReason : uint8_t {
    None,       // the pass runs
    Disabled,   // switched off at run time
    LostInput,  // reads (or preserves) a version whose producer is disabled or lost its own input
    NoOutput,   // contributes to no imported/exported resource and declares no side effect
};
const char* cullReasonName(CullReason reason);

// How a render pass begins and ends on one of its attachments (PassBuilder::writeColor, writeDepth,
// drawOver, read(…, DepthRead)): what the "attachments" step decided and beginRendering applies.
enum class LoadOp : uint8_t {
    Load,      // the contents an earlier running pass left (or an import's) are read
    Clear,     // cleared to AttachmentOps::clear (declared, or clearIfLost when the input was lost)
    DontCare,  // a discarding write, or a preserving one with nothing before it: undefined contents
};
enum class StoreOp : uint8_t {
    Store,     // a later running pass, or the graph's output, reads what the pass wrote
    DontCare,  // written, but nothing reads it (PassInfo::unreadWrites)
    None,      // read only (DepthRead): the pass does not write it
};
const char* loadOpName(LoadOp op);
const char* storeOpName(StoreOp op);

struct AttachmentOps {
    uint32_t resource = kInvalidIndex;
    LoadOp load = LoadOp::Load;
    StoreOp store = StoreOp::Store;
    VkClearValue clear{};  // load == Clear only
};

struct PassInfo {
    uint32_t pass = kInvalidIndex;  // index into GraphDecl::passes
    CullReason cullReason = CullReason::None;
    std::string cullDetail;         // human-readable, names the resource and pass that caused it
    uint32_t lostProducer = kInvalidIndex;  // LostInput: the unavailable pass whose result it needed
    // A disabled pass whose writes all preserve their contents (it only adds to them): later
    // passes read what it would have drawn over, instead of being culled.
    bool bypassed = false;
    // Resources this pass draws over whose producer does not run: cleared (AccessDecl::clearIfLost).
    std::vector<uint32_t> clearedLostInputs;
    // Resources this pass writes whose result no later running pass reads and which are no output
    // of the graph: an attachment among them is not stored (store op don't-care) and a resolve
    // into one is not done (a later pass resolves over it). Running passes only.
    std::vector<uint32_t> unreadWrites;
    // Whether `resource` is among unreadWrites: what this pass writes into it nothing reads.
    bool writeUnread(uint32_t resource) const {
        return std::find(unreadWrites.begin(), unreadWrites.end(), resource) != unreadWrites.end();
    }
    // Load and store operations of each colour/depth attachment the pass declares (ColorAttachment
    // and DepthAttachment writes, DepthRead reads), in declaration order (writes first). Running
    // passes only. A pass declares at most one attachment access per resource.
    std::vector<AttachmentOps> attachments;
    // The operations on attachment `resource`; null if the pass has no attachment access to it.
    const AttachmentOps* attachmentOps(uint32_t resource) const {
        const auto it = std::find_if(attachments.begin(), attachments.end(),
                                     [&](const AttachmentOps& ops) { return ops.resource == resource; });
        return it == attachments.end() ? nullptr : &*it;
    }
};

// Memory a resource needs, as the device reports it (or a size model in tests).
struct MemoryRequirement {
    VkDeviceSize size = 0;
    VkDeviceSize alignment = 1;
    uint32_t memoryTypeBits = ~0u;
};
// Called with the resource's index in GraphDecl::resources, its declaration and whether the
// "attachments" step found it a transient attachment (CompiledGraph::transientAttachments: the
// image then gets VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT and may live in lazily allocated memory).
using MemoryRequirementsFn =
    std::function<MemoryRequirement(uint32_t resource, const ResourceDecl&, bool transientAttachment)>;

// Default size model: texel size × texels over all mips, layers and samples, 256-byte alignment (tests,
// and anywhere no device is at hand).
MemoryRequirement estimateMemoryRequirement(const ResourceDecl& resource);

// Where a transient lives. Images and buffers never share a heap (no bufferImageGranularity issue).
struct Placement {
    uint32_t heap = kInvalidIndex;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
};

struct Heap {
    ResourceKind kind = ResourceKind::Texture;
    VkDeviceSize size = 0;
    VkDeviceSize alignment = 1;  // max alignment of its residents
    uint32_t memoryTypeBits = ~0u;
    std::vector<uint32_t> residents;  // resource indices, in first-use order
};

struct Lifetime {
    uint32_t first = kInvalidIndex;  // index into CompiledGraph::order of the first pass using it
    uint32_t last = kInvalidIndex;   // ... and of the last one (end of graph for exported)
    bool used() const { return first != kInvalidIndex; }
};

// One barrier on one whole resource. For images src.layout → dst.layout is the transition.
// `aliasedFrom` names the transient whose memory this resource takes over (kInvalidIndex if none):
// src then describes that resource's last use and the old layout is UNDEFINED.
struct Barrier {
    uint32_t resource = kInvalidIndex;
    ResourceState src;
    ResourceState dst;
    uint32_t aliasedFrom = kInvalidIndex;
};

struct CompileOptions {
    MemoryRequirementsFn memoryRequirements;  // empty: estimateMemoryRequirement
    bool aliasing = true;                     // false: every transient gets its own heap
};

struct CompiledGraph {
    std::vector<uint32_t> order;              // pass indices that run, in execution order
    std::vector<PassInfo> passes;             // one per declared pass, indexed like GraphDecl::passes
    std::vector<Lifetime> lifetimes;          // one per declared resource
    // One per resource: a transient used by one running pass only, as colour or depth attachment
    // that the pass neither loads nor stores (load op clear or don't-care, store op don't-care), and
    // declared nowhere but as a colour/depth attachment. Its contents never leave the render pass,
    // so it may be VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT in lazily allocated memory (tile memory
    // alone on tile-based GPUs; Apple's memoryless textures).
    std::vector<bool> transientAttachments;
    std::vector<Placement> placements;        // one per resource; heap == kInvalidIndex if not transient/used
    std::vector<Heap> heaps;
    std::vector<std::vector<Barrier>> barriers;  // barriers[i]: before order[i]
    std::vector<Barrier> finalBarriers;          // after the last pass (imported/exported final states)
    std::vector<ResourceState> finalStates;      // one per resource: state after the graph ran
    VkDeviceSize bytesRequested = 0;             // sum of transient sizes
    VkDeviceSize bytesAllocated = 0;             // sum of heap sizes after aliasing
    std::vector<std::string> steps;              // names of the compile steps, in the order they ran
};

// Runs the compile steps: validate → cull → order → unread writes → lifetimes → attachments →
// aliasing → barriers.
// Throws GraphError (naming the pass and the resource) on cycles, reads of versions nobody
// writes, two passes writing the same version, and invalid handles. Makes no Vulkan calls
// (memoryRequirements is the caller's; the executor passes one that asks the device).
CompiledGraph compileGraph(const GraphDecl& decl, const CompileOptions& options = {});

}  // namespace candela::graph
