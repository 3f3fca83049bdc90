#pragma once
// Runs a test's render graph on the device and reads results back: importBuffer() adds a
// host-visible buffer as an output of the graph (final state: host read); run() compiles the
// graph, realizes its transients, executes it in a frame slot and waits; read() returns the bytes.

#include "executor/graph_executor.h"
#include "passes/post/readback_pass.h"
#include "vk/buffer.h"
#include "vk/frame.h"

#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace candela::test {

class GraphRunner {
public:
    explicit GraphRunner(vk::Context& context) : mContext(context), mFrames(context, 1), mTransients(context) {}

    graph::BufferId readbackBuffer(graph::RenderGraph& graph, const std::string& name, VkDeviceSize bytes) {
        auto buffer = std::make_unique<vk::Buffer>(mContext, vk::BufferDesc{.size = bytes,
                                                                            .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                                            .memory = vk::MemoryUsage::Readback,
                                                                            .name = name.c_str()});
        const graph::BufferId id = graph.importBuffer(name, {.size = bytes}, graph::ResourceState{}, passes::hostReadState());
        mImports.bind(id, buffer->handle());
        mBuffers.emplace_back(id, std::move(buffer));
        return id;
    }

    // Binds an imported resource of the test's own (an input buffer it filled).
    void bind(graph::BufferId id, VkBuffer buffer) { mImports.bind(id, buffer); }

    void run(graph::RenderGraph& graph) {
        graph.compile({.memoryRequirements = graph::deviceMemoryRequirements(mContext, graph.declaration())});
        vk::FrameSlot& slot = mFrames.begin();
        mTransients.realize(graph.declaration(), graph.compiled());
        graph::executeGraph({.context = mContext,
                             .graph = graph,
                             .imports = mImports,
                             .transients = mTransients,
                             .cmd = slot.cmd,
                             .descriptors = *slot.descriptors});
        mFrames.submit();
        mFrames.waitCurrent();
    }

    // The bytes of a readback buffer after run().
    template <class T>
    std::vector<T> read(graph::BufferId id) const {
        for (const auto& [bufferId, buffer] : mBuffers)
            if (bufferId.index == id.index) {
                buffer->invalidate();
                std::vector<T> out(buffer->size() / sizeof(T));
                std::memcpy(out.data(), buffer->mapped(), out.size() * sizeof(T));
                return out;
            }
        return {};
    }

private:
    vk::Context& mContext;
    vk::FrameRing mFrames;
    graph::TransientPool mTransients;
    graph::ImportBindings mImports;
    std::vector<std::pair<graph::BufferId, std::unique_ptr<vk::Buffer>>> mBuffers;
};

}  // namespace candela::test
