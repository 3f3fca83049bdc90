#include "passes/forward_pass.h"

#include "executor/graph_executor.h"
#include "passes/forward_blocks.h"
#include "passes/material_set.h"
#include "shared/brdf.h"
#include "shared/scene_data.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace candela::passes {

using namespace graph;

namespace {

// `specializeLayers`: the layered program is specialized to the variant's layers at load
// (DeviceChoices::specializeLayeredProgram).
vk::GraphicsPipelineDesc pipelineDesc(const ForwardVariant& v, bool specializeLayers) {
    vk::GraphicsPipelineDesc out{
        .colorFormats = {passes::kHdrFormat},
        .depthFormat = passes::kDepthFormat,
        .depthTest = true,
        .depthWrite = !v.blend,
        .depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL,
        .blend = v.blend ? vk::BlendMode::Premultiplied : vk::BlendMode::None,
        .samples = v.samples,
        .alphaToCoverage = v.alphaToCoverage,
        .dynamicCullMode = true,
        .specialization = specializationConstants(v),
        .vertexBindings = {{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}},
        .vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
                             {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)},
                             {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, tangent)},
                             {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv0)},
                             {4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv1)},
                             {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, color)}}};
    // Where the generic layered program exceeds the device's per-stage limits, it is specialized to
    // the variant's layers (kLayers, constant 10) at load: its material set (1) and layer maps (3)
    // declare only what those layers read (docs/device-layer.md); sets 0 and 2 keep every binding,
    // shared by all variants.
    if (v.layers && specializeLayers) {
        out.frozenConstants = {10};
        out.specializedSets = {1, 3};
    }
    return out;
}

// Builds variant `v`'s pipeline: what a worker runs, so it holds only the context and the variant.
vk::Pipeline buildPipeline(vk::Context& context, const ForwardVariant& v) {
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

const vk::Pipeline& ForwardPass::pipeline(const ForwardVariant& v) {
    return mPipelines.get(mContext, v, [&] { return buildPipeline(mContext, v); });
}

void ForwardPass::queue(const FrameVariant& frame, WorkerPool::Priority priority) {
    for (const MaterialKey& key : mKeys->keys) {
        const ForwardVariant v = forwardVariant(key, frame);
        mPipelines.prepare(mWorkers, v, [context = &mContext, v] { return buildPipeline(*context, v); }, priority);
    }
}

bool ForwardPass::prepare(const FrameVariant& frame) {
    if (mPrepared == frame) return false;
    mPrepared = frame;
    queue(frame, WorkerPool::Priority::Soon);
    return true;
}

void ForwardPass::prepareDebugViews(const FrameVariant& frame) {
    FrameVariant base = frame;
    base.debugView = DebugView::None;
    if (mPreparedViews == base) return;
    mPreparedViews = base;
    // The shaded image first: the view a debug view is most often switched back to.
    queue(base, WorkerPool::Priority::Background);
    for (DebugView view : allDebugViews()) {
        FrameVariant f = base;
        f.debugView = view;
        queue(f, WorkerPool::Priority::Background);
    }
}

const vk::Program& ForwardPass::coreProgram() {
    // Rebuilt when a shader was replaced (hot reload), like the pipelines: the user's parameters
    // follow the new reflection. Replacements keep the layouts (shader_library.h), so sets
    // written with the old one stay valid.
    if (!mCoreProgram || mCoreProgram->stale()) mCoreProgram.emplace(mContext, std::vector<std::string_view>{"forward.vert", "forward.frag"});
    return *mCoreProgram;
}

const shader::ShaderReflection* ForwardPass::layeredReflection() {
    if (!mKeys) return nullptr;
    for (const MaterialKey& key : mKeys->keys)
        if (key.layers) return &pipeline(ForwardVariant{.layers = key.layers}).program().reflection();
    return nullptr;
}

void ForwardPass::setScene(const scene::GpuScene& gpuScene, const MaterialKeys& keys) {
    mScene = &gpuScene;
    mKeys = &keys;
    mPrepared.reset();  // other keys: their variants are not queued yet
    mPreparedViews.reset();
    mSets = std::make_unique<vk::DescriptorAllocator>(mContext);
    mMaterialSets.clear();
    // Every core variant has the set layouts of the core program, so sets written with it fit them
    // all (and no core pipeline is compiled for them here). A layered material's set follows the
    // layered program of its layers (specialized to them where the device's limits need it), read
    // from the pipeline of those layers.
    const vk::Program& core = coreProgram();
    const size_t materials = gpuScene.scene().materials.size();
    std::vector<const vk::Program*> programs(materials, &core);  // each material set's layout
    for (uint32_t material = 0; material < materials; ++material)
        if (const uint32_t layers = keys[material].layers) programs[material] = &pipeline(ForwardVariant{.layers = layers}).program();
    // One pool for the scene's sets: the scene set and a material set per material.
    vk::DescriptorCounts total = vk::DescriptorCounts::ofSet(core, 0);
    for (const vk::Program* program : programs) total += vk::DescriptorCounts::ofSet(*program, 1);
    mSets->reserve(total);
    mSceneSet = vk::DescriptorWriter(core, 0)
                    .buffer(ForwardBlock<shading::LightData>::name, gpuScene.lightBuffer())
                    .buffer(ForwardBlock<shading::DrawData>::name, gpuScene.drawBuffer())
                    .buffer(ForwardBlock<shading::MaterialData>::name, gpuScene.materialBuffer())
                    .commit(mContext, *mSets);
    // A layered material's set follows the layered program's layout: its core textures, then
    // every material's layer parameters and its own layer textures.
    for (uint32_t material = 0; material < materials; ++material)
        mMaterialSets.push_back(writeMaterialSet(mContext, *mSets, *programs[material], gpuScene, material,
                                                 keys[material].layers ? gpuScene.materialLayerBuffer() : VK_NULL_HANDLE));
}

ForwardPass::FrameInputs ForwardPass::frameInputs(const FrameDesc& desc) {
    FrameInputs out;
    uint32_t lightTypes = 0;
    for (const shading::LightData& light : mScene->lights()) lightTypes |= 1u << static_cast<uint32_t>(light.directionType.w);
    out.variant = {.model = desc.model,
                   .lights = mScene->lightCount() > 0,
                   .lightTypes = lightTypes,
                   .ibl = desc.ibl != nullptr,
                   .irradianceSh = !desc.ibl || desc.ibl->irradianceSh,
                   .multiscatter = !desc.ibl || desc.ibl->multiscatter,
                   .referenceSamples = desc.ibl ? desc.ibl->referenceSamples : 0,
                   .debugView = desc.debugView,
                   .specularAa = desc.shading.specularAntiAliasing,
                   .samples = desc.samples,
                   .alphaToCoverage = desc.samples > 1 && mContext.alphaToOne()};
    out.push.viewProjection = desc.view.viewProjection;
    out.push.eye = glm::vec4(desc.view.eye, 1.0f);
    out.push.counts = glm::uvec4(mScene->lightCount(), 0, 0, 0);
    if (desc.ibl) {
        out.push.ibl = desc.ibl->params;
        out.ibl = desc.ibl->maps;
    }
    if (desc.parameters) desc.parameters->apply("forward", "Push", reflection().pushConstants.members, out.push);
    if (desc.layerMaps) out.layerMaps = *desc.layerMaps;
    if (desc.posed) {
        out.posedDraws = desc.posed->data;
        out.posedLights = desc.posed->lights;
        out.posedMaterials = desc.posed->materials;
        out.posedMaterialLayers = desc.posed->materialLayers;
    }
    if (desc.deformed) {
        out.deformed = desc.deformed->vertices;
        out.vertexOffset = desc.deformed->vertexOffset;
    }
    return out;
}

DrawTarget ForwardPass::addOpaque(RenderGraph& graph, const DrawTargetSize& size, const DrawList& list,
                                  const FrameInputs& frame, DrawStats* recorded) {
    // Without transmissive draws the blended ones follow the opaque ones here (the transmissive
    // range between them is then empty); with them, forward_transmission draws them.
    const bool transmission = !list.empty(DrawRange::Transmissive);
    return addDrawPass(graph, "forward", list.ranges(DrawRange::Opaque, transmission ? DrawRange::Masked : DrawRange::Blended),
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

DrawTarget ForwardPass::addBlended(RenderGraph& graph, const DrawTarget& target, const DrawList& list, const FrameInputs& frame,
                                   DrawStats* recorded) {
    if (list.empty(DrawRange::Blended) || !list.empty(DrawRange::Transmissive))
        throw std::logic_error("ForwardPass::addBlended: the draw list needs blended draws and no transmissive ones");
    return addDrawPass(graph, "forward_blended", list.range(DrawRange::Blended), frame, recorded,
                       [&](PassBuilder& builder) { return drawInto(builder, target, false, DepthUse::Test); });
}

std::vector<std::string> ForwardPass::describe(const DrawList& list, const FrameInputs& frame,
                                               const DrawSelection& selection) const {
    std::vector<std::string> out;
    const scene::Scene& scene = mScene->scene();
    // Draws per material key, then per variant name (keys of one frame may share a variant).
    std::vector<uint32_t> perKey(mKeys->keys.size(), 0);
    for (const DrawListItem& item : list.items) ++perKey[item.key];
    std::map<std::string, uint32_t> variantCounts;
    for (uint32_t key = 0; key < perKey.size(); ++key)
        if (perKey[key]) variantCounts[forwardVariant(mKeys->keys[key], frame.variant).name()] += perKey[key];
    std::string used = "forward: " + std::to_string(list.draws) + " draws" +
                       (list.instances ? " (" + std::to_string(list.instances) + " instances in instanced draws)" : std::string()) +
                       "; variants:";
    for (const auto& [name, count] : variantCounts) used += " " + name + " ×" + std::to_string(count);
    out.push_back(used);
    out.push_back(describeSelection(list, selection));
    if (frame.posedDraws.valid())
        out.push_back("animated: draw matrices of this frame's pose, written by the CPU into a per-frame buffer" +
                      (list.hiddenDraws ? " (" + std::to_string(list.hiddenDraws) + " draws hidden or scaled to nothing, not drawn)"
                                        : std::string()));
    else if (list.hiddenDraws)
        out.push_back("left out: " + std::to_string(list.hiddenDraws) + " draws of hidden nodes (KHR_node_visibility)");
    if (mScene->lightCount() == 0) out.emplace_back("left out: light loop (no punctual lights)");
    if (std::none_of(scene.materials.begin(), scene.materials.end(), [](const scene::Material& m) { return m.normal.present(); }))
        out.emplace_back("left out: normal mapping / TBN work (no material has a normal texture)");
    if (std::none_of(scene.materials.begin(), scene.materials.end(), [](const scene::Material& m) { return m.unlit; }))
        out.emplace_back("left out: unlit variant (no KHR_materials_unlit material)");
    bool anyLayered = false;
    for (uint32_t material = 0; material < scene.materials.size(); ++material) {
        const uint32_t layers = (*mKeys)[material].layers;
        if (!layers) continue;
        anyLayered = true;
        out.push_back("material '" + scene.materials[material].name + "' pays for layers: " + plusLayerNames(layers).substr(1) +
                      " (the layered forward program)");
    }
    if (!anyLayered)
        out.emplace_back("left out: material layers (no material uses a KHR_materials_* layer; core forward program only)");
    return out;
}

DrawTarget ForwardPass::addDrawPass(RenderGraph& graph, std::string name, std::span<const DrawListItem> items,
                                    const FrameInputs& frame, DrawStats* stats,
                                    const std::function<DrawTarget(PassBuilder&)>& targets) {
    struct Data {
        DrawTarget targets;
        IblHandles ibl;     // as declared: resolved in execute
        LayerMaps layers;   // as declared
        BufferId draws;     // the posed draw data, when animated
        BufferId lights;    // the posed light data, when a light is animated
        BufferId materials, materialLayers;  // the posed material (layer) data, when a material is animated
        BufferId deformed;  // the deformed vertices, when some draw is deformed
    };
    // Each material key's pipeline in this frame, resolved once per key.
    std::vector<const vk::Pipeline*> pipelines(mKeys->keys.size(), nullptr);
    std::vector<Recorded> recordedItems;
    recordedItems.reserve(items.size());
    bool anyLayered = false;  // set 3 (the layer maps) is written when a layered draw is in the pass
    for (const DrawListItem& item : items) {
        const MaterialKey& key = mKeys->keys[item.key];
        if (!pipelines[item.key]) pipelines[item.key] = &pipeline(forwardVariant(key, frame.variant));
        anyLayered = anyLayered || key.layers != 0;
        recordedItems.push_back({.pipeline = pipelines[item.key],
                                 .item = item,
                                 .vertexOffset = frame.vertexOffset.empty() ? kRestVertices : frame.vertexOffset[item.draw],
                                 .layered = key.layers != 0});
    }
    const scene::GpuScene* gpuScene = mScene;
    const std::vector<VkDescriptorSet>* materialSets = &mMaterialSets;
    const ForwardIblSet* iblSets = &mIblSet;
    // Every variant of the frame shares the layouts of sets 0 and 2: the core program's, or in a
    // ground-truth frame its own program's (which adds its inputs to set 2).
    const vk::Program* program = frame.variant.referenceSamples
                                     ? &pipeline(ForwardVariant{.referenceSamples = frame.variant.referenceSamples}).program()
                                     : &coreProgram();
    const ForwardLayerSet* layerSets = &mLayerSet;
    const Data& data = graph.addPass<Data>(
        std::move(name), PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            d.targets = targets(builder);
            d.ibl = ForwardIblSet::declare(builder, frame.ibl ? &*frame.ibl : nullptr);
            if (anyLayered) d.layers = ForwardLayerSet::declare(builder, &frame.layerMaps);
            if (frame.posedDraws.valid())
                d.draws = builder.read(frame.posedDraws, Usage::StorageRead,
                                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            if (frame.posedLights.valid())
                d.lights = builder.read(frame.posedLights, Usage::StorageRead, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            // Material data: texture transforms in the vertex stage, the rest in the fragment stage.
            if (frame.posedMaterials.valid())
                d.materials = builder.read(frame.posedMaterials, Usage::StorageRead,
                                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            if (frame.posedMaterialLayers.valid() && anyLayered)
                d.materialLayers = builder.read(frame.posedMaterialLayers, Usage::StorageRead,
                                                VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            if (frame.deformed.valid()) d.deformed = builder.read(frame.deformed, Usage::Vertex);
        },
        [items = std::move(recordedItems), frameConstants = frame.push, gpuScene, staticSceneSet = mSceneSet, materialSets, iblSets,
         layerSets, program, stats](const Data& d, PassContext& ctx) {
            DrawStats unused;
            DrawStats* counts = stats ? stats : &unused;
            shading::ForwardPush constants = frameConstants;
            const VkDescriptorSet iblSet = iblSets->write(ctx, *program, d.ibl);
            // Set 3 of each layered variant in the pass (each specialized to its layers' maps).
            std::vector<std::pair<const vk::Pipeline*, VkDescriptorSet>> layerSetsWritten;
            const auto layerSetOf = [&](const vk::Pipeline& pipeline) {
                for (const auto& [p, set] : layerSetsWritten)
                    if (p == &pipeline) return set;
                return layerSetsWritten.emplace_back(&pipeline, layerSets->write(ctx, pipeline.program(), d.layers)).second;
            };
            // A pose: set 0 names this frame's draw, light and material buffers where it has them.
            const VkDescriptorSet sceneSet =
                !d.draws.valid() && !d.lights.valid() && !d.materials.valid()
                    ? staticSceneSet
                    : vk::DescriptorWriter(*program, 0)
                          .buffer(ForwardBlock<shading::LightData>::name, d.lights.valid() ? ctx.buffer(d.lights) : gpuScene->lightBuffer())
                          .buffer(ForwardBlock<shading::DrawData>::name, d.draws.valid() ? ctx.buffer(d.draws) : gpuScene->drawBuffer())
                          .buffer(ForwardBlock<shading::MaterialData>::name,
                                  d.materials.valid() ? ctx.buffer(d.materials) : gpuScene->materialBuffer())
                          .commit(ctx.context(), ctx.descriptors());
            // Posed layer data: the layered materials' sets 1 name this frame's buffer (written at
            // their first draw in the pass).
            std::vector<VkDescriptorSet> posedMaterialSets(d.materialLayers.valid() ? materialSets->size() : 0, VK_NULL_HANDLE);
            const auto materialSet = [&](const Recorded& r) {
                if (!r.layered || posedMaterialSets.empty()) return (*materialSets)[r.item.material];
                VkDescriptorSet& set = posedMaterialSets[r.item.material];
                if (set == VK_NULL_HANDLE)
                    set = writeMaterialSet(ctx.context(), ctx.descriptors(), r.pipeline->program(), *gpuScene, r.item.material,
                                           ctx.buffer(d.materialLayers));
                return set;
            };
            VkCommandBuffer cmd = ctx.cmd();
            ctx.beginRendering();
            if (items.empty()) {  // e.g. only transmissive draws: the pass just clears
                ctx.endRendering();
                return;
            }
            const VkDeviceSize offset = 0;
            const VkBuffer rest = gpuScene->vertexBuffer();
            const VkBuffer deformedVertices = d.deformed.valid() ? ctx.buffer(d.deformed) : VK_NULL_HANDLE;
            VkBuffer boundVertices = rest;
            vkCmdBindVertexBuffers(cmd, 0, 1, &rest, &offset);
            vkCmdBindIndexBuffer(cmd, gpuScene->indexBuffer(), 0, VK_INDEX_TYPE_UINT32);
            counts->bufferBinds += 2;
            // State is set only where it changes: the draws come sorted by pipeline and material.
            const vk::Pipeline* bound = nullptr;
            uint32_t boundMaterial = UINT32_MAX;
            std::optional<VkCullModeFlags> cullMode;
            std::optional<VkFrontFace> frontFace;
            const auto bindSet = [&](uint32_t set, const VkDescriptorSet& descriptors) {
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound->layout(), set, 1, &descriptors, 0, nullptr);
                ++counts->descriptorBinds;
            };
            for (const Recorded& r : items) {
                const DrawListItem& item = r.item;
                if (r.pipeline != bound) {
                    bound = r.pipeline;
                    bound->bind(cmd);
                    ++counts->pipelineBinds;
                    // Core and layered programs differ from set 1 on: rebind every set after a switch.
                    bindSet(0, sceneSet);
                    bindSet(2, iblSet);
                    if (r.layered && bound->program().setCount() > 3) bindSet(3, layerSetOf(*bound));
                    boundMaterial = UINT32_MAX;
                }
                if (item.material != boundMaterial) {
                    boundMaterial = item.material;
                    bindSet(1, materialSet(r));
                }
                if (const VkCullModeFlags wanted = item.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT; cullMode != wanted) {
                    cullMode = wanted;
                    vkCmdSetCullMode(cmd, wanted);
                    ++counts->dynamicStates;
                }
                // glTF fronts are counter-clockwise; a mirroring transform turns them clockwise.
                if (const VkFrontFace wanted = item.flipWinding ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
                    frontFace != wanted) {
                    frontFace = wanted;
                    vkCmdSetFrontFace(cmd, wanted);
                    ++counts->dynamicStates;
                }
                constants.counts.y = item.drawData;
                bound->pushConstants(cmd, &constants, sizeof(constants));
                const bool restVertices = r.vertexOffset == kRestVertices;
                if (const VkBuffer wanted = restVertices ? rest : deformedVertices; wanted != boundVertices) {
                    boundVertices = wanted;
                    vkCmdBindVertexBuffers(cmd, 0, 1, &boundVertices, &offset);
                    ++counts->bufferBinds;
                }
                vkCmdDrawIndexed(cmd, item.indexCount, item.instances, item.firstIndex, restVertices ? 0 : r.vertexOffset, 0);
            }
            ctx.endRendering();
        });
    return data.targets;
}

}  // namespace candela::passes
