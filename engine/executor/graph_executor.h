#pragma once
// Execution of a compiled RenderGraph on a command buffer: emits the planned sync2 barriers and
// layout transitions, brackets each pass with a debug label and GPU timestamps, and calls the
// pass's execute callback with a PassContext resolving handles to Vulkan objects.

#include "executor/transient_pool.h"
#include "graph/graph_export.h"
#include "graph/render_graph.h"
#include "vk/descriptors.h"
#include "vk/timestamps.h"

#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace candela::graph {

struct ExecuteInputs;
struct ExecutionRecord;

// Vulkan objects behind the graph's imported resources, owned by the caller.
class ImportBindings {
public:
    // `mipViews[m]`: a view of mip m alone (all layers; a 2D array for arrays and cubes), for passes
    // that write or read one mip at a time (PassContext::mipView). May be empty.
    void bind(TextureId texture, VkImage image, VkImageView view, std::vector<VkImageView> mipViews = {});
    void bind(BufferId buffer, VkBuffer handle);

    struct ImageBinding {
        VkImage image = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
        std::vector<VkImageView> mipViews;
    };
    const ImageBinding* image(uint32_t resource) const;
    VkBuffer buffer(uint32_t resource) const;

private:
    std::unordered_map<uint32_t, ImageBinding> mImages;
    std::unordered_map<uint32_t, VkBuffer> mBuffers;
};

// Everything a pass's execute callback may use. Valid only during the callback.
//
// Every resource accessor takes a handle the pass's setup declared (a version it reads, or one
// its writes produce) and throws GraphError naming the pass and the resource for any other: an
// access the graph does not know of gets no barrier, so it is refused rather than left to race.
class PassContext {
public:
    // What the executor runs the pass with. Tests may leave the Vulkan parts null as long as the
    // pass does not use them.
    struct Bindings {
        vk::Context* context = nullptr;
        const ImportBindings* imports = nullptr;
        const TransientPool* transients = nullptr;
        vk::DescriptorAllocator* descriptors = nullptr;
        VkCommandBuffer cmd = VK_NULL_HANDLE;
    };
    // The context of pass `pass` of `graph`, which must be compiled; borrows everything.
    PassContext(const RenderGraph& graph, uint32_t pass, const Bindings& bindings);

    VkCommandBuffer cmd() const { return mBindings.cmd; }
    vk::Context& context() const { return *mBindings.context; }
    vk::DescriptorAllocator& descriptors() const { return *mBindings.descriptors; }
    const char* passName() const { return mPass->name.c_str(); }

    VkImage image(TextureId texture) const;
    // The default view (all mips and layers; a cube view for cube maps).
    VkImageView view(TextureId texture) const;
    // A view of mip `mip` alone, all layers (2D array for arrays and cubes), for storage writes of
    // one mip. Throws GraphError if the texture has no such mip or no view of it: imported textures
    // have the ones bound with them, transients one per mip when they have storage usage.
    VkImageView mipView(TextureId texture, uint32_t mip) const;
    // The layout the texture is in during this pass (what a descriptor of it must name).
    VkImageLayout layout(TextureId texture) const;
    VkBuffer buffer(BufferId buffer) const;
    const TextureDesc& desc(TextureId texture) const;
    const BufferDesc& desc(BufferId buffer) const;
    VkExtent2D extent(TextureId texture) const;

    // For an attachment the pass draws over (PassBuilder::drawOver) whose producer did not run:
    // the value to clear it to before drawing; nullopt when its contents are there to load.
    // beginRendering() applies it; passes with their own render pass clear it themselves.
    std::optional<VkClearValue> lostContentsClear(TextureId written) const;

    // Begins dynamic rendering on the pass's declared colour/depth attachments with the load and
    // store operations the graph planned (PassInfo::attachments: clear, load, or don't-care where
    // nothing was written before; store, or don't-care where no later pass reads the result) and
    // their resolves (PassBuilder::resolve, unless a later pass resolves over them), and sets
    // viewport and scissor to the first attachment's size.
    void beginRendering() const;
    void endRendering() const;

private:
    // The declared access to this handle; throws GraphError if there is none.
    const AccessDecl& declared(ResourceKind kind, uint32_t index, uint32_t version) const;

    const RenderGraph* mGraph;
    uint32_t mPassIndex;
    const PassDecl* mPass;
    Bindings mBindings;
};

// Which timestamp queries bracket which pass in one execution; turned into timings once the
// frame's fence has been waited for.
struct ExecutionRecord {
    std::vector<std::pair<uint32_t, std::pair<uint32_t, uint32_t>>> queries;  // pass → (begin, end)
    uint32_t passCount = 0;
    // Per-pass GPU milliseconds (negative for passes that did not run). Precondition: the frame
    // completed and timestamps.fetch() was called.
    GraphTimings timings(vk::TimestampPool& timestamps) const;
};

struct ExecuteInputs {
    vk::Context& context;
    const RenderGraph& graph;  // compiled
    const ImportBindings& imports;  // every imported resource bound
    const TransientPool& transients;  // realized for this compiled graph
    VkCommandBuffer cmd;
    vk::DescriptorAllocator& descriptors;
    vk::TimestampPool* timestamps = nullptr;  // null: no timings
    // Called after each pass's commands are recorded, with the pass's declared index (serialized
    // timing: the caller submits and waits for what was recorded so far). May be empty.
    std::function<void(uint32_t pass)> afterPass;
    // Testing hook: false skips every planned barrier, to prove that synchronization validation
    // catches what the barrier planner prevents.
    bool emitBarriers = true;
};

// Records the compiled graph into `in.cmd`. Throws GraphError if the graph is not compiled or an
// imported resource is not bound.
ExecutionRecord executeGraph(const ExecuteInputs& in);

}  // namespace candela::graph
