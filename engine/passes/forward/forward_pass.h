#pragma once
// Forward pass (graphics): draws ranges of a frame's draw list (passes/drawing/draw_list.h) into an HDR
// target (RGBA16F, alpha = coverage, premultiplied) with a reverse-Z depth buffer. Each draw uses
// the pipeline variant of its material key and the frame's bits (passes/drawing/shading_variant.h).
//
// A frame adds "forward" (addOpaque: the opaque, masked and point-and-line ranges, then the
// blended one sorted back to front) and, when the list has transmissive draws, "forward_transmission"
// (addTransmissive: the transmissive and blended draws back to front over the opaque image, reading
// its copy with mips, TransmissionBackgroundPass). Both take what they draw from their arguments:
// the pass keeps no state between calls. What every draw of the frame shares (push constants, the
// maps and per-frame buffers it reads) is made once per frame (passes/drawing/frame_inputs.h); the
// draws are recorded by the draw recorder (passes/drawing/draw_recorder.h) with the scene's sets
// (passes/drawing/scene_bindings.h), as the visibility raster's are.

#include "graph/render_graph.h"
#include "options/debug_view.h"
#include "passes/drawing/draw_list.h"
#include "options/draw_selection.h"
#include "passes/drawing/draw_target.h"
#include "passes/drawing/frame_inputs.h"
#include "passes/drawing/ibl_set.h"
#include "passes/drawing/layer_map_set.h"
#include "passes/drawing/shading_variant.h"
#include "gpu_scene/gpu_scene.h"
#include "core/worker_pool.h"
#include "vk/descriptors.h"
#include "vk/pipeline_cache.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace candela::passes {

class ForwardPass {
public:
    explicit ForwardPass(vk::Context& context);

    // Binds the scene's buffers and textures into persistent descriptor sets (sets 0 and 1,
    // scene_bindings.h). The scene is uploaded once and changes only while the GPU is idle, so it is
    // no graph resource.
    // Call once per GpuScene; `keys` are its materials' (MaterialKeys::of). Preconditions: the GPU no
    // longer uses the previous scene's sets; `scene` and `keys` outlive their use by this pass.
    void setScene(const gpu_scene::GpuScene& scene, const MaterialKeys& keys);

    // Adds "forward": clears new targets of `size` and draws the list's opaque and masked ranges,
    // then its blended one unless the list has transmissive draws (addTransmissive draws those).
    // State changes recorded are added to `recorded` (if given; it must outlive the recording).
    DrawTarget addOpaque(graph::RenderGraph& graph, const DrawTargetSize& size, const DrawList& list,
                         const FrameInputs& frame, DrawStats* recorded = nullptr);
    // Adds "forward_transmission": the list's transmissive and blended draws back to front over the
    // `opaque` targets (after whatever drew into them since, e.g. the skybox), reading `background`
    // (the opaque image with its mips) behind the transmissive ones. Returns the targets' new
    // versions. Precondition: the list has transmissive draws.
    DrawTarget addTransmissive(graph::RenderGraph& graph, const DrawTarget& opaque, graph::TextureId background,
                               const DrawList& list, const FrameInputs& frame, DrawStats* recorded = nullptr);

    // Adds "forward_points_lines": the list's opaque and masked points and lines over `target` (the
    // visibility path's shaded image and its depth, tested and written). Precondition: the list
    // has such draws.
    DrawTarget addPointsAndLines(graph::RenderGraph& graph, const DrawTarget& target, const DrawList& list, const FrameInputs& frame,
                                 DrawStats* recorded = nullptr);

    // Adds "forward_blended": the list's blended draws, back to front, over `target` (the visibility
    // path's shaded image and its depth, tested but not written). Precondition: the list has blended
    // draws and no transmissive ones (addTransmissive draws both then).
    DrawTarget addBlended(graph::RenderGraph& graph, const DrawTarget& target, const DrawList& list, const FrameInputs& frame,
                          DrawStats* recorded = nullptr);

    // Queues the pipelines of every material key of the scene for a frame of `frame`'s bits on the
    // pass's worker threads (priority Soon), so that the frame's draws find them built or building
    // instead of compiling them one after the other (the draw that needs one first runs it itself
    // if no worker has started it). Cheap when `frame` is the one last prepared; returns whether it
    // was not (something may have been queued). Precondition: a scene is set.
    bool prepare(const FrameVariant& frame);
    // Queues (priority Soon) the pipelines of `keys` — a scene about to be uploaded — for a frame
    // with the bits of the last one prepared, or of `first` before any, and these lights (`lights`:
    // any; `lightTypes`: bit 1 << CANDELA_LIGHT_* of each), so that they compile on the workers
    // while the scene uploads: a batch's next scene is most often drawn like the one before, a first
    // scene as its settings say (FrameBuilder::firstFrameVariant). A frame of other bits queues its
    // own in prepare() and leaves these unused. Nothing before a first frame without `first`.
    void prepareAhead(const MaterialKeys& keys, const std::optional<FrameVariant>& first, bool lights, uint32_t lightTypes);
    // Queues, in the background, the same for every debug view (None included) of `frame`'s other
    // bits, so that a switch of the view finds them built. Cheap when done already for `frame`.
    void prepareDebugViews(const FrameVariant& frame);
    // Waits for every queued pipeline build (benchmarks: a measurement that must not include them).
    void finishBuilds() { mPipelines.finish(); }
    // The workers this pass builds pipelines ahead on, which other passes' ahead builds share
    // (FrameBuilder: TonemapPass::prepare). Lives as long as the pass.
    WorkerPool& workers() { return mWorkers; }
    // Forward variants built so far, and queued builds not yet drawn with (of which finished).
    struct BuildCounts {
        size_t built = 0, queued = 0, queuedFinished = 0;
    };
    BuildCounts buildCounts() const { return {mPipelines.size(), mPipelines.pending(), mPipelines.pendingFinished()}; }

    // The reflection of the forward shaders without layers (every variant shares sets 0 and 2 and
    // the push constants; the layered program adds to set 1).
    const shader::ShaderReflection& reflection() { return coreProgram().reflection(); }
    // The reflection of the layered program (its MaterialLayers buffer), when the current scene
    // has a material with a layer; null otherwise.
    const shader::ShaderReflection* layeredReflection();

    static constexpr VkFormat kHdrFormat = passes::kHdrFormat;
    static constexpr VkFormat kDepthFormat = passes::kDepthFormat;

private:
    // Adds a graphics pass `name` recording `items` in order into the targets `targets` declares,
    // reading `frame`'s inputs. Returns the targets as written.
    DrawTarget addDrawPass(graph::RenderGraph& graph, std::string name, std::span<const DrawListItem> items,
                           const FrameInputs& frame, DrawStats* recorded,
                           const std::function<DrawTarget(graph::PassBuilder&)>& targets);
    const vk::Pipeline& pipeline(const ShadingVariant& variant);
    // The core program (shader modules, layouts, reflection: no pipeline), whose set layouts every
    // core variant shares and whose sets 0 and 2 every layered variant shares.
    const vk::Program& coreProgram();
    // The program of the layered variants of `layers` (what every such variant's pipeline is built
    // with: its set layouts and reflection), made without compiling a pipeline; rebuilt when a shader
    // was replaced.
    const vk::Program& layeredProgram(uint32_t layers);
    // Queues the pipeline of every key of `keys` for `frame` (see prepare).
    void queue(const MaterialKeys& keys, const FrameVariant& frame, WorkerPool::Priority priority);

    vk::Context& mContext;
    WorkerPool mWorkers;  // before mPipelines: outlives the builds it runs
    vk::PipelineCache<ShadingVariant> mPipelines;
    std::optional<FrameVariant> mPrepared, mPreparedViews;  // what prepare/prepareDebugViews last queued for
    std::optional<FrameVariant> mLastFrame;  // what prepare() last queued for, whatever the scene
    std::optional<vk::Program> mCoreProgram;
    std::map<uint32_t, vk::Program> mLayeredPrograms;  // by layer bits
    IblSet mIblSet;
    LayerMapSet mLayerSet;
    const gpu_scene::GpuScene* mScene = nullptr;
    const MaterialKeys* mKeys = nullptr;
    std::unique_ptr<vk::DescriptorAllocator> mSets;
    VkDescriptorSet mSceneSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> mMaterialSets;
};

}  // namespace candela::passes
