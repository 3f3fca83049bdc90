#pragma once
// Execution of a compiled RenderGraph on a command buffer: emits the planned sync2 barriers and
// layout transitions, brackets each pass with a debug label and GPU timestamps, and calls the
// pass's execute callback with a PassContext resolving handles to Vulkan objects.

#include "graph/graph_export.h"
#include "graph/render_graph.h"
#include "graph/transient_pool.h"
#include "vk/descriptors.h"
#include "vk/timestamps.h"

#include <unordered_map>
#include <utility>
#include <vector>

namespace candela::graph {

struct ExecuteInputs;
struct ExecutionRecord;

// Vulkan objects behind the graph's imported resources, owned by the caller.
class ImportBindings {
public:
    void bind(TextureId texture, VkImage image, VkImageView view);
    void bind(BufferId buffer, VkBuffer handle);

    struct ImageBinding {
        VkImage image = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
    };
    const ImageBinding* image(uint32_t resource) const;
    VkBuffer buffer(uint32_t resource) const;

private:
    std::unordered_map<uint32_t, ImageBinding> mImages;
    std::unordered_map<uint32_t, VkBuffer> mBuffers;
};

// Everything a pass's execute callback may use. Valid only during the callback.
class PassContext {
public:
    VkCommandBuffer cmd() const { return mCmd; }
    vk::Context& context() const { return *mContext; }
    vk::DescriptorAllocator& descriptors() const { return *mDescriptors; }
    const char* passName() const { return mPass->name.c_str(); }

    VkImage image(TextureId texture) const;
    VkImageView view(TextureId texture) const;
    VkBuffer buffer(BufferId buffer) const;
    const TextureDesc& desc(TextureId texture) const;
    VkExtent2D extent(TextureId texture) const;

    // For an attachment the pass draws over (PassBuilder::drawOver) whose producer did not run:
    // the value to clear it to before drawing; nullopt when its contents are there to load.
    // beginRendering() applies it; passes with their own render pass clear it themselves.
    std::optional<VkClearValue> lostContentsClear(TextureId written) const;

    // Begins dynamic rendering on the pass's declared colour/depth attachments (load op from the
    // declaration: clear, load, or don't-care for discarding writes) and sets viewport and scissor
    // to the first attachment's size.
    void beginRendering() const;
    void endRendering() const;

private:
    friend ExecutionRecord executeGraph(const ExecuteInputs& in);
    uint32_t resolve(uint32_t index, ResourceKind kind) const;

    vk::Context* mContext = nullptr;
    const RenderGraph* mGraph = nullptr;
    const PassDecl* mPass = nullptr;
    const ImportBindings* mImports = nullptr;
    const TransientPool* mTransients = nullptr;
    vk::DescriptorAllocator* mDescriptors = nullptr;
    VkCommandBuffer mCmd = VK_NULL_HANDLE;
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
    // Testing hook: false skips every planned barrier, to prove that synchronization validation
    // catches what the barrier planner prevents.
    bool emitBarriers = true;
};

// Records the compiled graph into `in.cmd`. Throws GraphError if the graph is not compiled or an
// imported resource is not bound.
ExecutionRecord executeGraph(const ExecuteInputs& in);

}  // namespace candela::graph
