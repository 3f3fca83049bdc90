#pragma once
// RenderGraph: the frame's passes, declared with a setup lambda (what they create, read and write)
// and an execute lambda (the commands they record). Built anew every frame; cheap to build.
//
//   RenderGraph graph;
//   TextureId target = graph.importTexture("target", desc, initial, final);
//   struct PatternData { TextureId hdr; };
//   auto& pattern = graph.addPass<PatternData>("pattern", PassType::Compute,
//       [&](PassBuilder& b, PatternData& d) {
//           d.hdr = b.write(b.createTexture("hdr", hdrDesc), Usage::StorageWrite, WriteMode::Discard);
//       },
//       [=](const PatternData& d, PassContext& ctx) { /* bind, dispatch */ });
//   graph.addPass<EncodeData>("encode", PassType::Graphics,
//       [&](PassBuilder& b, EncodeData& d) {
//           d.hdr = b.read(pattern.hdr, Usage::Sampled);
//           d.out = b.writeColor(target, std::nullopt);
//       }, ...);
//   const CompiledGraph& compiled = graph.compile();
//
// Ownership: the graph owns pass data and callbacks. It never owns Vulkan objects; imported
// resources belong to the caller, transients to the executor's TransientPool.

#include "graph/compiled_graph.h"
#include "graph/graph_decl.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace candela::graph {

class PassContext;  // graph_executor.h: command buffer and resolved Vulkan handles
class RenderGraph;

// Handed to a pass's setup lambda; records what the pass creates, reads and writes.
class PassBuilder {
public:
    // Creates a transient resource (version 0, no contents). The graph allocates it only if a
    // surviving pass uses it, possibly sharing memory with transients whose lifetimes do not overlap.
    TextureId createTexture(std::string name, const TextureDesc& desc);
    BufferId createBuffer(std::string name, const BufferDesc& desc);

    // Declares a read of exactly this version. Returns the same handle.
    TextureId read(TextureId texture, Usage usage, VkPipelineStageFlags2 stageOverride = 0);
    BufferId read(BufferId buffer, Usage usage, VkPipelineStageFlags2 stageOverride = 0);
    // Declares a read through a sampler by the pass's shaders: in a graphics pass by the fragment
    // shader (sample from a vertex shader with read(texture, Usage::Sampled, stages)), in a compute
    // pass by the compute shader. Returns the same handle.
    TextureId sample(TextureId texture);

    // The description of a resource declared so far (e.g. the format of a target, to choose a
    // pipeline variant). Throws GraphError for an invalid handle.
    const TextureDesc& desc(TextureId texture) const;
    const BufferDesc& desc(BufferId buffer) const;

    // Declares a write that consumes `handle` and produces the returned new version.
    TextureId write(TextureId texture, Usage usage, WriteMode mode = WriteMode::Preserve,
                    VkPipelineStageFlags2 stageOverride = 0);
    BufferId write(BufferId buffer, Usage usage, WriteMode mode = WriteMode::Preserve,
                   VkPipelineStageFlags2 stageOverride = 0);

    // Colour/depth attachments of a graphics pass, in declaration order. With a clear value the
    // previous contents are discarded and cleared; without, they are loaded (preserved).
    TextureId writeColor(TextureId texture, std::optional<VkClearColorValue> clear);
    // A colour attachment drawn over (loaded), which keeps the pass alive when the producer of
    // `texture` does not run: the attachment is then cleared to `fallback`. For overlays, such as
    // the UI, that must stay visible whatever else is switched off.
    TextureId drawOver(TextureId texture, VkClearColorValue fallback);
    TextureId writeDepth(TextureId texture, std::optional<float> clearDepth);
    // Resolves the multisampled colour attachment `multisampled` (the version this pass's
    // writeColor returned) into the single-sample `target` of the same size and format when the
    // pass ends rendering (a render-pass resolve: the average of the samples). Returns target's
    // new version. The resolve replaces all of target; it counts as preserving when the colour
    // write does (a pass drawing over an image resolves over its earlier resolve), so switching
    // such a pass off bypasses it. The graph skips a resolve whose result no later pass reads
    // (PassInfo::unreadWrites). Throws GraphError for any other pairing.
    TextureId resolve(TextureId multisampled, TextureId target);

    // Keeps the pass alive even if no output depends on it.
    void sideEffect();
    // Marks the pass as one that cannot be switched off, `why` saying what switching it off would
    // leave undefined (PassDecl::cannotBeDisabled). For a pass whose writes preserve what came
    // before (so that the cull step would bypass it) but whose consumers read what only it writes.
    void cannotBeDisabled(std::string why);

private:
    friend class RenderGraph;
    PassBuilder(RenderGraph& graph, uint32_t pass) : mGraph(graph), mPass(pass) {}
    RenderGraph& mGraph;
    uint32_t mPass;
};

using ExecuteFn = std::function<void(PassContext&)>;

class RenderGraph {
public:
    RenderGraph() = default;
    RenderGraph(const RenderGraph&) = delete;
    RenderGraph& operator=(const RenderGraph&) = delete;

    // Adds a pass. `setup(PassBuilder&, Data&)` runs immediately; `execute(const Data&,
    // PassContext&)` runs at execution time if the pass survives compilation.
    // Returns the pass's data (stable address) so later passes can read its handles.
    template <class Data, class Setup, class Execute>
    const Data& addPass(std::string name, PassType type, Setup&& setup, Execute&& execute) {
        auto data = std::make_shared<Data>();
        const uint32_t index = beginPass(std::move(name), type);
        PassBuilder builder(*this, index);
        setup(builder, *data);
        mCallbacks[index] = [data, exec = std::forward<Execute>(execute)](PassContext& ctx) {
            exec(*data, ctx);
        };
        mPassData[index] = data;
        return *data;
    }

    // Imports a persistent resource whose version 0 holds valid contents in `initial` state.
    // If `final` is given, the graph transitions it there after the last pass.
    TextureId importTexture(std::string name, const TextureDesc& desc, const ResourceState& initial,
                            std::optional<ResourceState> final = std::nullopt);
    BufferId importBuffer(std::string name, const BufferDesc& desc, const ResourceState& initial,
                          std::optional<ResourceState> final = std::nullopt);

    // Creates a transient outside any pass (e.g. a target several passes write in turn). Same
    // rules as PassBuilder::createTexture: allocated only if a surviving pass uses it.
    TextureId createTexture(std::string name, const TextureDesc& desc);
    BufferId createBuffer(std::string name, const BufferDesc& desc);

    // Marks a transient as an output: its writers are kept and it lives to the end of the graph.
    void exportTexture(TextureId texture, std::optional<ResourceState> final = std::nullopt);
    void exportBuffer(BufferId buffer, std::optional<ResourceState> final = std::nullopt);

    // Runtime toggle, applied at the next compile(). Throws GraphError for an unknown pass name.
    void setPassEnabled(std::string_view name, bool enabled);

    // Compiles the declared graph (see compileGraph). The result stays valid until the next
    // compile() or until the graph is destroyed.
    const CompiledGraph& compile(const CompileOptions& options = {});

    const GraphDecl& declaration() const { return mDecl; }
    const CompiledGraph& compiled() const { return mCompiled; }
    bool isCompiled() const { return mIsCompiled; }
    const ExecuteFn& callback(uint32_t pass) const { return mCallbacks[pass]; }
    std::optional<uint32_t> findPass(std::string_view name) const;
    std::optional<uint32_t> findResource(std::string_view name) const;

private:
    friend class PassBuilder;
    uint32_t beginPass(std::string name, PassType type);
    uint32_t addResource(ResourceDecl resource);
    AccessDecl& addRead(uint32_t pass, ResourceKind kind, uint32_t index, uint32_t version, Usage usage,
                        VkPipelineStageFlags2 stageOverride);
    AccessDecl& addWrite(uint32_t pass, ResourceKind kind, uint32_t index, uint32_t version, Usage usage,
                         WriteMode mode, VkPipelineStageFlags2 stageOverride);

    GraphDecl mDecl;
    std::vector<ExecuteFn> mCallbacks;
    std::vector<std::shared_ptr<void>> mPassData;
    CompiledGraph mCompiled;
    bool mIsCompiled = false;
};

}  // namespace candela::graph
