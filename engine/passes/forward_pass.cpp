#include "passes/forward_pass.h"

#include "graph/graph_executor.h"
#include "shared/brdf.h"
#include "shared/scene_data.h"
#include "scene/frustum.h"
#include "scene/mesh_lod.h"

#include <algorithm>
#include <cstdio>
#include <tuple>
#include <stdexcept>

namespace candela::passes {

using namespace graph;

namespace {

// The layer names of `layers` (scene::MaterialLayer bits), "+"-separated.
std::string plusLayerNames(uint32_t layers) {
    std::string out;
    for (std::string_view name : scene::layerNames(layers)) (out += "+") += name;
    return out;
}

// Whether material `m` is drawn by the layered program.
bool layered(const scene::Material& m) { return !m.unlit && m.layers() != 0; }

// The level of detail `draw` is drawn at from `view` on a target `height` pixels tall: the coarsest
// of its chain whose error covers at most `maxPixels` (its full detail without a chain).
scene::LodLevel levelOf(const scene::Scene& scene, const scene::Draw& draw, const scene::ViewSetup& view, uint32_t height,
                        float maxPixels) {
    if (draw.lod < 0 || !(maxPixels > 0.0f)) return {draw.firstIndex, draw.indexCount, 0.0f};
    float scale = scene::maxScale(draw.world);
    if (draw.instanceCount > 0) {
        float instanceScale = 0.0f;
        for (uint32_t i = 0; i < draw.instanceCount; ++i)
            instanceScale = std::max(instanceScale, scene::maxScale(scene.instances[draw.firstInstance + i]));
        scale *= instanceScale;
    }
    const scene::LodChain& chain = scene.lodChains[size_t(draw.lod)];
    return chain.levels[scene::selectLod(chain, scale, scene::pixelsPerUnit(view, height, draw.bounds), maxPixels)];
}

std::string formatPixels(float pixels) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(pixels));
    return text;
}

}  // namespace

std::string ForwardPass::Variant::name() const {
    std::string out = unlit ? "unlit" : model == ShadingModel::BlinnPhong ? "blinn-phong"
                                    : model == ShadingModel::PbrSchlickGgx ? "pbr-schlick-ggx"
                                                                           : "pbr";
    if (normalMap) out += "+normal-map";
    if (!unlit && !lights) out += "+no-lights";
    if (alphaMask) out += "+alpha-mask";
    if (blend) out += "+blend";
    if (ibl && !unlit) out += std::string("+ibl-") + (irradianceSh ? "sh9" : "cube") + (multiscatter ? "" : "-single-scatter") +
               (referenceSamples ? "-reference" + std::to_string(referenceSamples) : "");
    out += plusLayerNames(layers);
    if (specularAa && !unlit) out += "+specular-aa";
    if (samples > 1) out += "+msaa" + std::to_string(samples);
    if (alphaToCoverage) out += "+alpha-to-coverage";
    if (debugView != DebugView::None) out += std::string("+debug-") + debugViewName(debugView);
    return out;
}

ForwardPass::ForwardPass(vk::Context& context) : mContext(context), mIblSet(context), mLayerSet(context) {}

const vk::Pipeline& ForwardPass::pipeline(const Variant& v) {
    return mPipelines.get(mContext, v, [&] {
        // The ground truth of `ibl-report` (referenceSamples) is a program of its own, for core materials.
        if (v.referenceSamples && v.layers) throw std::logic_error("ForwardPass: the ground truth integrates core materials only");
        return v.layers ? vk::Pipeline::graphics(mContext, "forward_layers.vert", "forward_layers.frag", desc(v))
                        : vk::Pipeline::graphics(mContext, "forward.vert",
                                                 v.referenceSamples ? "forward_reference.frag" : "forward.frag", desc(v));
    });
}

vk::GraphicsPipelineDesc ForwardPass::desc(const Variant& v) {
    vk::GraphicsPipelineDesc out{
        .colorFormats = {kHdrFormat},
        .depthFormat = kDepthFormat,
        .depthTest = true,
        .depthWrite = !v.blend,
        .depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL,
        .blend = v.blend ? vk::BlendMode::Premultiplied : vk::BlendMode::None,
        .samples = v.samples,
        .alphaToCoverage = v.alphaToCoverage,
        .dynamicCullMode = true,
        .specialization = {v.normalMap, v.lights, v.unlit, v.alphaMask, static_cast<uint32_t>(v.model), v.ibl,
                           v.irradianceSh, v.multiscatter, v.referenceSamples, static_cast<uint32_t>(v.debugView)},
        .vertexBindings = {{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}},
        .vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
                             {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)},
                             {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, tangent)},
                             {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv0)},
                             {4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv1)},
                             {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, color)}}};
    // Only the layered program has kLayers (constant 10; 0 for the core program, which ignores it).
    out.specialization.push_back(v.layers);
    out.specialization.push_back(v.specularAa);
    out.specialization.push_back(v.alphaToCoverage);
    return out;
}

ForwardPass::Variant ForwardPass::variantOf(const scene::Draw& draw, ShadingModel model, const Ibl* ibl,
                                            DebugView debugView, const ShadingOptions& shading, uint32_t samples) const {
    const scene::Material& m = mScene->scene().materials[draw.material];
    Variant v;
    v.unlit = m.unlit;
    v.normalMap = !m.unlit && m.normal.present();
    v.lights = !m.unlit && mScene->lightCount() > 0;
    v.alphaMask = m.alphaMode == scene::AlphaMode::Mask;
    v.blend = m.alphaMode == scene::AlphaMode::Blend;
    v.model = m.unlit ? ShadingModel::Pbr : model;
    v.ibl = !m.unlit && ibl;
    v.irradianceSh = !v.ibl || ibl->irradianceSh;
    v.multiscatter = !v.ibl || ibl->multiscatter;
    v.referenceSamples = v.ibl ? ibl->referenceSamples : 0;
    v.debugView = debugView;
    v.layers = layered(m) ? m.layers() : 0;
    v.specularAa = !m.unlit && shading.specularAntiAliasing;
    v.samples = samples;
    v.alphaToCoverage = v.alphaMask && samples > 1 && mContext.alphaToOne();
    return v;
}

const shader::ShaderReflection* ForwardPass::layeredReflection() {
    if (!mScene) return nullptr;
    for (const scene::Material& m : mScene->scene().materials)
        if (layered(m)) return &pipeline(Variant{.layers = m.layers()}).program().reflection();
    return nullptr;
}

void ForwardPass::setScene(const scene::GpuScene& gpuScene) {
    mScene = &gpuScene;
    mSets = std::make_unique<vk::DescriptorAllocator>(mContext);
    mMaterialSets.clear();
    // Every variant has the same set layouts, so sets written for one pipeline fit them all.
    const vk::Pipeline& any = pipeline(Variant{});
    mSceneSet = vk::DescriptorWriter(any.program(), 0)
                    .buffer("Lights", gpuScene.lightBuffer())
                    .buffer("Draws", gpuScene.drawBuffer())
                    .buffer("Materials", gpuScene.materialBuffer())
                    .commit(mContext, *mSets);
    for (uint32_t material = 0; material < gpuScene.scene().materials.size(); ++material) {
        // A layered material's set follows the layered program's layout: its core textures, then
        // every material's layer parameters and its own layer textures.
        const scene::Material& m = gpuScene.scene().materials[material];
        const vk::Program& program = layered(m) ? pipeline(Variant{.layers = m.layers()}).program() : any.program();
        vk::DescriptorWriter writer(program, 1);
        for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) {
            const scene::GpuScene::Binding b = gpuScene.texture(material, slot);
            writer.image(scene::kCoreTextureSlots[slot].sampler, b.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, b.sampler);
        }
        if (layered(m)) {
            writer.buffer("MaterialLayers", gpuScene.materialLayerBuffer());
            for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) {
                const scene::GpuScene::Binding b = gpuScene.layerTexture(material, slot);
                writer.image(scene::kLayerTextureSlots[slot].sampler, b.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, b.sampler);
            }
        }
        mMaterialSets.push_back(writer.commit(mContext, *mSets));
    }
}

// Whether a draw of material `m` is drawn after the opaque image exists (it reads what lies behind).
static bool transmissive(const scene::Material& m) { return layered(m) && (m.layers() & scene::kLayerTransmission); }

ForwardPass::Output ForwardPass::add(RenderGraph& graph, const DrawTargetSize& size, const scene::ViewSetup& view,
                                     ShadingModel model, const Ibl* ibl, shader::ParameterRegistry* parameters,
                                     DebugView debugView, const PosedDraws* posed, const DeformedVertices* deformed,
                                     const LayerMaps* layerMaps, const DrawSelection& selection,
                                     const ShadingOptions& shading) {
    const scene::Scene& scene = mScene->scene();
    const std::span<const scene::Draw> draws = posed ? posed->draws : std::span<const scene::Draw>(scene.draws);
    std::vector<DrawItem> opaque, blended, transmitting;
    std::map<std::string, uint32_t> variantCounts;
    uint32_t hidden = 0;
    uint32_t drawData = 0;  // the draw buffer holds one entry per draw, one per instance for instanced ones
    mStats = DrawStats{};
    const scene::Frustum frustum(view.viewProjection);
    for (uint32_t i = 0; i < draws.size(); drawData += std::max(draws[i].instanceCount, 1u), ++i) {
        const scene::Draw& draw = draws[i];
        if (draw.hidden) {
            ++hidden;
            continue;
        }
        const uint32_t instances = std::max(draw.instanceCount, 1u);
        ++mStats.sceneDraws;
        mStats.sceneTriangles += uint64_t(draw.indexCount / 3) * instances;
        if (selection.frustumCulling && !frustum.intersects(draw.bounds)) {
            ++mStats.culledDraws;
            continue;
        }
        const scene::LodLevel level = levelOf(scene, draw, view, size.height, selection.lodErrorPixels);
        mStats.coarserDraws += level.firstIndex != draw.firstIndex;
        ++mStats.submittedDraws;
        mStats.submittedTriangles += uint64_t(level.indexCount / 3) * instances;
        const Variant v = variantOf(draw, model, ibl, debugView, shading, size.samples);
        ++variantCounts[v.name()];
        const glm::vec3 centre = 0.5f * (draw.bounds.min + draw.bounds.max);
        // Debug views show data, not what lies behind: transmissive draws are then drawn with the rest.
        const bool behind = transmissive(scene.materials[draw.material]) && debugView == DebugView::None;
        (behind ? transmitting : v.blend ? blended : opaque)
            .push_back({.pipeline = &pipeline(v), .depth = glm::length(centre - view.eye),
                        .firstIndex = level.firstIndex, .indexCount = level.indexCount, .material = draw.material,
                        .flipWinding = draw.flipWinding, .doubleSided = scene.materials[draw.material].doubleSided,
                        .vertexOffset = deformed ? deformed->vertexOffset[i] : kRestVertices,
                        .drawData = drawData, .instances = instances, .layered = v.layers != 0});
    }
    // Opaque grouped by pipeline, then by material (fewer binds); blended back to front. With
    // transmissive draws, the blended ones follow them (sorted together back to front) in the pass
    // after the opaque image.
    const auto backToFront = [](const DrawItem& a, const DrawItem& b) { return a.depth > b.depth; };
    std::stable_sort(opaque.begin(), opaque.end(), [](const DrawItem& a, const DrawItem& b) {
        return std::tie(a.pipeline, a.material) < std::tie(b.pipeline, b.material);
    });
    std::vector<DrawItem> items = std::move(opaque);
    mBehind.clear();
    if (transmitting.empty()) {
        std::stable_sort(blended.begin(), blended.end(), backToFront);
        items.insert(items.end(), blended.begin(), blended.end());
    } else {
        mBehind = std::move(transmitting);
        mBehind.insert(mBehind.end(), blended.begin(), blended.end());
        std::stable_sort(mBehind.begin(), mBehind.end(), backToFront);
    }

    mExplanation.clear();
    uint32_t instanced = 0;
    for (const scene::Draw& draw : draws) instanced += draw.hidden ? 0 : draw.instanceCount;
    std::string used = "forward: " + std::to_string(draws.size() - hidden) + " draws" +
                       (instanced ? " (" + std::to_string(instanced) + " instances in instanced draws)" : std::string()) +
                       "; variants:";
    for (const auto& [name, count] : variantCounts) used += " " + name + " ×" + std::to_string(count);
    mExplanation.push_back(used);
    mExplanation.push_back(
        "draws: " + std::to_string(mStats.submittedDraws) + " of " + std::to_string(mStats.sceneDraws) + " submitted (" +
        std::to_string(mStats.culledDraws) + " outside the view frustum" +
        (selection.frustumCulling ? "" : ", culling off") + "), " + std::to_string(mStats.submittedTriangles) + " of " +
        std::to_string(mStats.sceneTriangles) + " triangles; " + std::to_string(mStats.coarserDraws) +
        " draws at a coarser level of detail (" +
        (selection.lodErrorPixels > 0.0f ? "error ≤ " + formatPixels(selection.lodErrorPixels) + " px" : std::string("levels of detail off")) + ")");
    if (posed)
        mExplanation.push_back("animated: draw matrices of this frame's pose, written by the CPU into a per-frame buffer" +
                               (hidden ? " (" + std::to_string(hidden) + " draws scaled to nothing, not drawn)" : std::string()));
    if (mScene->lightCount() == 0) mExplanation.emplace_back("left out: light loop (no punctual lights)");
    if (std::none_of(scene.materials.begin(), scene.materials.end(), [](const scene::Material& m) { return m.normal.present(); }))
        mExplanation.emplace_back("left out: normal mapping / TBN work (no material has a normal texture)");
    if (std::none_of(scene.materials.begin(), scene.materials.end(), [](const scene::Material& m) { return m.unlit; }))
        mExplanation.emplace_back("left out: unlit variant (no KHR_materials_unlit material)");
    bool anyLayered = false;
    for (const scene::Material& m : scene.materials) {
        if (!layered(m)) continue;
        anyLayered = true;
        mExplanation.push_back("material '" + m.name + "' pays for layers: " + plusLayerNames(m.layers()).substr(1) +
                               " (the layered forward program)");
    }
    if (!anyLayered)
        mExplanation.emplace_back("left out: material layers (no material uses a KHR_materials_* layer; core forward program only)");

    shading::ForwardPush push{};
    push.viewProjection = view.viewProjection;
    push.eye = glm::vec4(view.eye, 1.0f);
    push.counts = glm::uvec4(mScene->lightCount(), 0, 0, 0);
    if (ibl) push.ibl = ibl->params;
    if (parameters) parameters->apply("forward", "Push", reflection().pushConstants.members, push);
    mFrame = FrameInputs{.push = push,
                         .ibl = ibl ? std::optional<IblHandles>(ibl->maps) : std::nullopt,
                         .layerMaps = layerMaps ? *layerMaps : LayerMaps{},
                         .posedDraws = posed ? posed->data : BufferId{},
                         .posedLights = posed ? posed->lights : BufferId{},
                         .deformed = deformed ? deformed->vertices : BufferId{}};
    return addDrawPass(graph, "forward", std::move(items), [&](PassBuilder& builder) {
        return drawInto(builder, createDrawTarget(builder, size), true, DepthUse::Clear);
    });
}

ForwardPass::Output ForwardPass::addTransmissive(RenderGraph& graph, const Output& opaque, TextureId background) {
    if (mBehind.empty()) throw std::logic_error("ForwardPass::addTransmissive: the last add() has no transmissive draw");
    mFrame.layerMaps.transmission = background;
    const DrawTarget& targets = addDrawPass(graph, "forward_transmission", std::move(mBehind), [&](PassBuilder& builder) {
        return drawInto(builder, opaque, false, DepthUse::Write);
    });
    mBehind.clear();
    return targets;
}

const DrawTarget& ForwardPass::addDrawPass(RenderGraph& graph, std::string name, std::vector<DrawItem> items,
                                           const std::function<DrawTarget(PassBuilder&)>& targets) {
    struct Data {
        DrawTarget targets;
        IblHandles ibl;     // as declared: resolved in execute
        LayerMaps layers;   // as declared
        BufferId draws;     // the posed draw data, when animated
        BufferId lights;    // the posed light data, when a light is animated
        BufferId deformed;  // the deformed vertices, when some draw is deformed
    };
    const FrameInputs& in = mFrame;
    const scene::GpuScene* gpuScene = mScene;
    const std::vector<VkDescriptorSet>* materialSets = &mMaterialSets;
    const ForwardIblSet* iblSets = &mIblSet;
    const vk::Program* program = &pipeline(Variant{}).program();  // every variant shares the set layouts
    // Set 3, of the layered program only: written when a layered draw is in the pass.
    const auto layeredItem = std::find_if(items.begin(), items.end(), [](const DrawItem& item) { return item.layered; });
    const vk::Program* layeredProgram = layeredItem != items.end() ? &layeredItem->pipeline->program() : nullptr;
    const ForwardLayerSet* layerSets = &mLayerSet;
    const Data& data = graph.addPass<Data>(
        std::move(name), PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            d.targets = targets(builder);
            d.ibl = ForwardIblSet::declare(builder, in.ibl ? &*in.ibl : nullptr);
            if (layeredProgram) d.layers = ForwardLayerSet::declare(builder, &in.layerMaps);
            if (in.posedDraws.valid())
                d.draws = builder.read(in.posedDraws, Usage::StorageRead,
                                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            if (in.posedLights.valid())
                d.lights = builder.read(in.posedLights, Usage::StorageRead, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            if (in.deformed.valid()) d.deformed = builder.read(in.deformed, Usage::Vertex);
        },
        [items = std::move(items), frameConstants = in.push, gpuScene, staticSceneSet = mSceneSet, materialSets, iblSets,
         layerSets, program, layeredProgram, stats = &mStats](const Data& d, PassContext& ctx) {
            shading::ForwardPush constants = frameConstants;
            const VkDescriptorSet iblSet = iblSets->write(ctx, *program, d.ibl);
            const VkDescriptorSet layerSet = layeredProgram ? layerSets->write(ctx, *layeredProgram, d.layers) : VK_NULL_HANDLE;
            // Posed draws: set 0 names this frame's draw buffer.
            const VkDescriptorSet sceneSet = !d.draws.valid() ? staticSceneSet
                                             : vk::DescriptorWriter(*program, 0)
                                                   .buffer("Lights", d.lights.valid() ? ctx.buffer(d.lights) : gpuScene->lightBuffer())
                                                   .buffer("Draws", ctx.buffer(d.draws))
                                                   .buffer("Materials", gpuScene->materialBuffer())
                                                   .commit(ctx.context(), ctx.descriptors());
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
            stats->bufferBinds += 2;
            // State is set only where it changes: the draws come sorted by pipeline and material.
            const vk::Pipeline* bound = nullptr;
            uint32_t boundMaterial = UINT32_MAX;
            std::optional<VkCullModeFlags> cullMode;
            std::optional<VkFrontFace> frontFace;
            const auto bindSet = [&](uint32_t set, const VkDescriptorSet& descriptors) {
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound->layout(), set, 1, &descriptors, 0, nullptr);
                ++stats->descriptorBinds;
            };
            for (const DrawItem& item : items) {
                if (item.pipeline != bound) {
                    bound = item.pipeline;
                    bound->bind(cmd);
                    ++stats->pipelineBinds;
                    // Core and layered programs differ from set 1 on: rebind every set after a switch.
                    bindSet(0, sceneSet);
                    bindSet(2, iblSet);
                    if (item.layered) bindSet(3, layerSet);
                    boundMaterial = UINT32_MAX;
                }
                if (item.material != boundMaterial) {
                    boundMaterial = item.material;
                    bindSet(1, (*materialSets)[item.material]);
                }
                if (const VkCullModeFlags wanted = item.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT; cullMode != wanted) {
                    cullMode = wanted;
                    vkCmdSetCullMode(cmd, wanted);
                    ++stats->dynamicStates;
                }
                // glTF fronts are counter-clockwise; a mirroring transform turns them clockwise.
                if (const VkFrontFace wanted = item.flipWinding ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
                    frontFace != wanted) {
                    frontFace = wanted;
                    vkCmdSetFrontFace(cmd, wanted);
                    ++stats->dynamicStates;
                }
                constants.counts.y = item.drawData;
                bound->pushConstants(cmd, &constants, sizeof(constants));
                const bool restVertices = item.vertexOffset == kRestVertices;
                if (const VkBuffer wanted = restVertices ? rest : deformedVertices; wanted != boundVertices) {
                    boundVertices = wanted;
                    vkCmdBindVertexBuffers(cmd, 0, 1, &boundVertices, &offset);
                    ++stats->bufferBinds;
                }
                vkCmdDrawIndexed(cmd, item.indexCount, item.instances, item.firstIndex, restVertices ? 0 : item.vertexOffset, 0);
            }
            ctx.endRendering();
        });
    return data.targets;
}

}  // namespace candela::passes
