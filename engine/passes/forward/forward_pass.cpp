#include "passes/forward/forward_pass.h"

#include "executor/graph_executor.h"
#include "passes/drawing/draw_recorder.h"
#include "passes/drawing/scene_bindings.h"
#include "shared/brdf.h"
#include "shared/specialization_ids.h"
#include "shared/scene_data.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace candela::passes {

using namespace graph;

namespace {

// `specializeLayers`: the layered program is specialized to the variant's layers at load
// (DeviceChoices::specializeLayeredProgram).
vk::GraphicsPipelineDesc pipelineDesc(const ShadingVariant& v, bool specializeLayers) {
    vk::GraphicsPipelineDesc out{
        .colorFormats = {passes::kHdrFormat},
        .depthFormat = passes::kDepthFormat,
        .topology = primitiveTopology(v.topology),
        .depthTest = true,
        .depthWrite = !v.blend,
        .depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL,
        .blend = v.blend ? vk::BlendMode::Premultiplied : vk::BlendMode::None,
        .samples = v.samples,
        .alphaToCoverage = v.alphaToCoverage,
        .dynamicCullMode = true,
        .specialization = specializationConstants(v),
        .vertexBindings = sceneVertexBindings(),
        .vertexAttributes = sceneVertexAttributes()};
    // Where the generic layered program exceeds the device's per-stage limits, it is specialized to
    // the variant's layers (CANDELA_SPEC_LAYERS) at load: its material set (1) and layer maps (3)
    // declare only what those layers read (docs/device-layer.md); sets 0 and 2 keep every binding,
    // shared by all variants.
    if (v.layers && specializeLayers) {
        out.frozenConstants = {CANDELA_SPEC_LAYERS};
        out.specializedSets = {1, 3};
    }
    return out;
}

// Builds variant `v`'s pipeline: what a worker runs, so it holds only the context and the variant.
vk::Pipeline buildPipeline(vk::Context& context, const ShadingVariant& v) {
    // The ground truth of `ibl-report` (referenceSamples) is a program of its own, for core materials.
    if (v.referenceSamples && v.layers) throw std::logic_error("ForwardPass: the ground truth integrates core materials only");
    return v.layers ? vk::Pipeline::graphics(context, "forward_layers.vert", "forward_layers.frag",
                                             pipelineDesc(v, context.choices().specializeLayeredProgram))
                    : vk::Pipeline::graphics(context, "forward.vert", v.referenceSamples ? "forward_reference.frag" : "forward.frag",
                                             pipelineDesc(v, false));
}

}  // namespace

ForwardPass::ForwardPass(vk::Context& context)
    : mContext(context), mWorkers(WorkerPool::defaultThreads()), mIblSet(context), mLayerSet(context) {}

const vk::Pipeline& ForwardPass::pipeline(const ShadingVariant& v) {
    return mPipelines.get(mContext, v, [&] { return buildPipeline(mContext, v); });
}

void ForwardPass::queue(const MaterialKeys& keys, const FrameVariant& frame, WorkerPool::Priority priority) {
    for (const MaterialKey& key : keys.keys) {
        const ShadingVariant v = shadingVariant(key, frame);
        mPipelines.prepare(mWorkers, v, [context = &mContext, v] { return buildPipeline(*context, v); }, priority);
    }
}

bool ForwardPass::prepare(const FrameVariant& frame) {
    if (mPrepared == frame) return false;
    mPrepared = mLastFrame = frame;
    queue(*mKeys, frame, WorkerPool::Priority::Soon);
    return true;
}

void ForwardPass::prepareAhead(const MaterialKeys& keys, const std::optional<FrameVariant>& first, bool lights, uint32_t lightTypes) {
    if (!mLastFrame && !first) return;
    FrameVariant frame = mLastFrame ? *mLastFrame : *first;
    frame.lights = lights;
    frame.lightTypes = lightTypes;
    queue(keys, frame, WorkerPool::Priority::Soon);
}

void ForwardPass::prepareDebugViews(const FrameVariant& frame) {
    FrameVariant base = frame;
    base.debugView = options::DebugView::None;
    if (mPreparedViews == base) return;
    mPreparedViews = base;
    // The shaded image first: the view a debug view is most often switched back to.
    queue(*mKeys, base, WorkerPool::Priority::Background);
    for (options::DebugView view : options::allDebugViews()) {
        FrameVariant f = base;
        f.debugView = view;
        queue(*mKeys, f, WorkerPool::Priority::Background);
    }
}

const vk::Program& ForwardPass::coreProgram() {
    // Rebuilt when a shader was replaced (hot reload), like the pipelines: the user's parameters
    // follow the new reflection. Replacements keep the layouts (shader_library.h), so sets
    // written with the old one stay valid.
    if (!mCoreProgram || mCoreProgram->stale()) mCoreProgram.emplace(mContext, std::vector<std::string_view>{"forward.vert", "forward.frag"});
    return *mCoreProgram;
}

const vk::Program& ForwardPass::layeredProgram(uint32_t layers) {
    auto it = mLayeredPrograms.find(layers);
    if (it == mLayeredPrograms.end() || it->second.stale()) {
        const vk::GraphicsPipelineDesc desc =
            pipelineDesc(ShadingVariant{.layers = layers}, mContext.choices().specializeLayeredProgram);
        it = mLayeredPrograms
                 .insert_or_assign(layers, vk::Program(mContext, {"forward_layers.vert", "forward_layers.frag"},
                                                       vk::programSpecialization(desc)))
                 .first;
    }
    return it->second;
}

const shader::ShaderReflection* ForwardPass::layeredReflection() {
    if (!mKeys) return nullptr;
    for (const MaterialKey& key : mKeys->keys)
        if (key.layers) return &layeredProgram(key.layers).reflection();
    return nullptr;
}

void ForwardPass::setScene(const gpu_scene::GpuScene& gpuScene, const MaterialKeys& keys) {
    mScene = &gpuScene;
    mKeys = &keys;
    mPrepared.reset();  // other keys: their variants are not queued yet
    mPreparedViews.reset();
    mSets = std::make_unique<vk::DescriptorAllocator>(mContext);
    mMaterialSets.clear();
    // Every core variant has the set layouts of the core program, so sets written with it fit them
    // all (and no core pipeline is compiled for them here). A layered material's set follows the
    // layered program of its layers (specialized to them where the device's limits need it:
    // layeredProgram, which compiles no pipeline).
    const vk::Program& core = coreProgram();
    const size_t materials = gpuScene.scene().materials.size();
    std::vector<const vk::Program*> programs(materials, &core);  // each material set's layout
    for (uint32_t material = 0; material < materials; ++material)
        if (const uint32_t layers = keys[material].layers) programs[material] = &layeredProgram(layers);
    // One pool for the scene's sets: the scene set and a material set per material.
    vk::DescriptorCounts total = vk::DescriptorCounts::ofSet(core, 0);
    for (const vk::Program* program : programs) total += vk::DescriptorCounts::ofSet(*program, 1);
    mSets->reserve(total);
    mSceneSet = writeSceneSet(mContext, *mSets, core, sceneBuffersOf(gpuScene));
    // A layered material's set follows the layered program's layout: its core textures, then
    // every material's layer parameters and its own layer textures.
    for (uint32_t material = 0; material < materials; ++material)
        mMaterialSets.push_back(writeMaterialSet(mContext, *mSets, *programs[material], gpuScene, material,
                                                 keys[material].layers ? gpuScene.materialLayerBuffer() : VK_NULL_HANDLE));
}

DrawTarget ForwardPass::addOpaque(RenderGraph& graph, const DrawTargetSize& size, const DrawList& list,
                                  const FrameInputs& frame, DrawStats* recorded) {
    // Without transmissive draws the blended ones follow the opaque ones here (the transmissive
    // range between them is then empty); with them, forward_transmission draws them.
    const bool transmission = !list.empty(DrawRange::Transmissive);
    return addDrawPass(graph, "forward", list.ranges(DrawRange::Opaque, transmission ? DrawRange::PointsAndLines : DrawRange::Blended),
                       frame, recorded, [&](PassBuilder& builder) {
                           return drawInto(builder, createDrawTarget(builder, size), true, DepthUse::Clear);
                       });
}

DrawTarget ForwardPass::addTransmissive(RenderGraph& graph, const DrawTarget& opaque, TextureId background,
                                        const DrawList& list, const FrameInputs& frame, DrawStats* recorded) {
    if (list.empty(DrawRange::Transmissive))
        throw std::logic_error("ForwardPass::addTransmissive: the draw list has no transmissive draw");
    FrameInputs inputs = frame;
    inputs.layerMaps.transmission = background;
    const std::vector<DrawListItem> items = list.backToFront(DrawRange::Transmissive, DrawRange::Blended);
    return addDrawPass(graph, "forward_transmission", items, inputs, recorded,
                       [&](PassBuilder& builder) { return drawInto(builder, opaque, false, DepthUse::Write); });
}

DrawTarget ForwardPass::addPointsAndLines(RenderGraph& graph, const DrawTarget& target, const DrawList& list,
                                         const FrameInputs& frame, DrawStats* recorded) {
    if (list.empty(DrawRange::PointsAndLines))
        throw std::logic_error("ForwardPass::addPointsAndLines: the draw list has no point or line draw");
    return addDrawPass(graph, "forward_points_lines", list.range(DrawRange::PointsAndLines), frame, recorded,
                       [&](PassBuilder& builder) { return drawInto(builder, target, false, DepthUse::Write); });
}

DrawTarget ForwardPass::addBlended(RenderGraph& graph, const DrawTarget& target, const DrawList& list, const FrameInputs& frame,
                                   DrawStats* recorded) {
    if (list.empty(DrawRange::Blended) || !list.empty(DrawRange::Transmissive))
        throw std::logic_error("ForwardPass::addBlended: the draw list needs blended draws and no transmissive ones");
    return addDrawPass(graph, "forward_blended", list.range(DrawRange::Blended), frame, recorded,
                       [&](PassBuilder& builder) { return drawInto(builder, target, false, DepthUse::Test); });
}

DrawTarget ForwardPass::addDrawPass(RenderGraph& graph, std::string name, std::span<const DrawListItem> items,
                                    const FrameInputs& frame, DrawStats* stats,
                                    const std::function<DrawTarget(PassBuilder&)>& targets) {
    struct Data {
        DrawTarget targets;
        IblHandles ibl;    // as declared: resolved in execute
        LayerMaps layers;  // as declared
        DeclaredFrameBuffers buffers;
    };
    // Each material key's pipeline in this frame, resolved once per key.
    std::vector<const vk::Pipeline*> pipelines(mKeys->keys.size(), nullptr);
    std::vector<DrawCall> draws;
    draws.reserve(items.size());
    bool anyLayered = false;  // set 3 (the layer maps) is written when a layered draw is in the pass
    for (const DrawListItem& item : items) {
        const MaterialKey& key = mKeys->keys[item.key];
        if (!pipelines[item.key]) pipelines[item.key] = &pipeline(shadingVariant(key, frame.variant));
        anyLayered = anyLayered || key.layers != 0;
        draws.push_back({.pipeline = pipelines[item.key],
                         .item = item,
                         .vertexOffset = frame.vertexOffsetOf(item.draw),
                         .materialSet = mMaterialSets[item.material],
                         .layered = key.layers != 0});
    }
    // Every variant of the frame shares the layouts of sets 0 and 2: the core program's, or in a
    // ground-truth frame its own program's (which adds its inputs to set 2).
    const vk::Program* program = frame.variant.referenceSamples
                                     ? &pipeline(ShadingVariant{.referenceSamples = frame.variant.referenceSamples}).program()
                                     : &coreProgram();
    constexpr VkPipelineStageFlags2 kVertexAndFragment = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    const Data& data = graph.addPass<Data>(
        std::move(name), PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            d.targets = targets(builder);
            d.ibl = IblSet::declare(builder, frame.ibl ? &*frame.ibl : nullptr);
            if (anyLayered) d.layers = LayerMapSet::declare(builder, &frame.layerMaps);
            // Draw and material data: transforms in the vertex stage, the rest in the fragment stage.
            d.buffers = declareFrameReads(builder, frame,
                                          {.materialLayers = anyLayered,
                                           .sceneStages = kVertexAndFragment,
                                           .lightStages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT});
        },
        [draws = std::move(draws), push = frame.push, gpuScene = mScene, sceneSet = mSceneSet, materialSets = mMaterialSets.size(),
         iblSets = &mIblSet, layerSets = &mLayerSet, program, stats](const Data& d, PassContext& ctx) {
            const VkDescriptorSet set0 = frameSceneSet(ctx, *program, *gpuScene, d.buffers.posed, sceneSet);
            const VkDescriptorSet iblSet = iblSets->write(ctx, *program, d.ibl);
            // Set 3 of each layered variant in the pass (each specialized to its layers' maps).
            std::vector<std::pair<const vk::Pipeline*, VkDescriptorSet>> layerSetsWritten;
            const auto layerSetOf = [&](const vk::Pipeline& pipeline) {
                for (const auto& [p, set] : layerSetsWritten)
                    if (p == &pipeline) return set;
                return layerSetsWritten.emplace_back(&pipeline, layerSets->write(ctx, pipeline.program(), d.layers)).second;
            };
            PosedMaterialSets posedSets(ctx, *gpuScene, d.buffers.posed.materialLayers, materialSets);
            recordDraws(
                ctx, draws, *gpuScene, deformedBuffer(ctx, d.buffers), push, stats,
                [&](const vk::Pipeline& bound, const DrawCall& draw, DrawStats& counts) {
                    bindGraphicsSet(ctx.cmd(), bound, 0, set0, counts);
                    bindGraphicsSet(ctx.cmd(), bound, 2, iblSet, counts);
                    if (draw.layered && bound.program().setCount() > 3) bindGraphicsSet(ctx.cmd(), bound, 3, layerSetOf(bound), counts);
                },
                [&](const DrawCall& draw) {
                    return posedSets.get(draw.item.material, draw.layered, draw.pipeline->program(), draw.item.material,
                                         draw.materialSet);
                });
        });
    return data.targets;
}

}  // namespace candela::passes
