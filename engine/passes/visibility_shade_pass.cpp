#include "passes/visibility_shade_pass.h"

#include "executor/graph_executor.h"
#include "passes/clear_pass.h"
#include "passes/compute.h"
#include "passes/forward_blocks.h"
#include "passes/material_set.h"
#include "vk/context.h"

#include <algorithm>

#include <stdexcept>

namespace candela::passes {

using namespace graph;

namespace {
constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
const char* shaderOf(bool layered, bool msaa) {
    if (msaa) return layered ? "visibility_shade_layers_msaa.comp" : "visibility_shade_msaa.comp";
    return layered ? "visibility_shade_layers.comp" : "visibility_shade.comp";
}

// `constants` with the tile size (the workgroup size) appended at its constant ids.
std::vector<uint32_t> withTileSize(std::vector<uint32_t> constants, glm::uvec2 tile) {
    constants.resize(std::max<size_t>(constants.size(), CANDELA_VISIBILITY_TILE_Y_ID + 1), 0);
    constants[CANDELA_VISIBILITY_TILE_X_ID] = tile.x;
    constants[CANDELA_VISIBILITY_TILE_Y_ID] = tile.y;
    return constants;
}
}  // namespace

VisibilityShadePass::VisibilityShadePass(vk::Context& context)
    : mContext(context), mTile(visibilityTileSize(context.properties().deviceType)), mIblSet(context), mLayerSet(context),
      mNearest(vk::createSampler(context, vk::kNearestSampler)) {}

const vk::Program& VisibilityShadePass::program(bool layered) {
    std::optional<vk::Program>& p = layered ? mLayeredProgram : mCoreProgram;
    if (!p || p->stale()) p.emplace(mContext, std::vector<std::string_view>{shaderOf(layered, false)});
    return *p;
}

const vk::Pipeline& VisibilityShadePass::pipeline(const ShadeKey& key) {
    if (key.variant.referenceSamples) throw std::logic_error("VisibilityShadePass: the ground truth is drawn by the forward path");
    return mPipelines.get(mContext, key, [&] {
        std::vector<uint32_t> constants = specializationConstants(key.variant);
        constants.resize(std::max<size_t>(constants.size(), 19), 0);
        constants[13] = key.deformed;  // kDeformed, kCoreTextures, kLayerTextures, kDistinct, kSamples (visibility/shade.glsl)
        constants[14] = key.coreSlots;
        constants[15] = key.layerSlots;
        constants[17] = key.distinct;
        constants[18] = key.variant.samples;
        return vk::Pipeline::compute(mContext, shaderOf(key.variant.layers != 0, key.variant.samples > 1),
                                     withTileSize(std::move(constants), mTile));
    });
}

void VisibilityShadePass::setScene(const scene::GpuScene& scene, const MaterialKeys& keys, const TextureSets& sets) {
    mScene = &scene;
    mTextureSets = &sets;
    mSets = std::make_unique<vk::DescriptorAllocator>(mContext, 4);
    const vk::Program& core = program(false);
    const size_t count = sets.firstMaterial.size();
    std::vector<bool> coreUse(count, false), layeredUse(count, false);
    for (uint32_t material = 0; material < sets.ofMaterial.size(); ++material)
        (keys[material].layers ? layeredUse : coreUse)[sets.ofMaterial[material]] = true;
    mSceneSet = vk::DescriptorWriter(core, 0)
                    .buffer(ForwardBlock<shading::LightData>::name, scene.lightBuffer())
                    .buffer(ForwardBlock<shading::DrawData>::name, scene.drawBuffer())
                    .buffer(ForwardBlock<shading::MaterialData>::name, scene.materialBuffer())
                    .commit(mContext, *mSets);
    mCoreMaterialSets.assign(count, VK_NULL_HANDLE);
    mLayeredMaterialSets.assign(count, VK_NULL_HANDLE);
    for (uint32_t set = 0; set < count; ++set) {
        // Any material of the texture set has its textures.
        const uint32_t material = sets.firstMaterial[set];
        for (const bool layered : {false, true})
            if ((layered ? layeredUse : coreUse)[set])
                (layered ? mLayeredMaterialSets : mCoreMaterialSets)[set] =
                    writeMaterialSet(mContext, *mSets, program(layered), scene, material,
                                    layered ? scene.materialLayerBuffer() : VK_NULL_HANDLE);
    }
}

TextureId VisibilityShadePass::add(RenderGraph& graph, const Inputs& in) {
    const ForwardPass::FrameInputs& frame = *in.frame;
    struct Dispatch {
        const vk::Pipeline* pipeline;
        bool layered;
        VkDescriptorSet materialSet;  // set 1: the list's textures
        uint32_t textureSet;
    };
    std::vector<Dispatch> dispatches;
    bool anyLayered = false;
    // The tile lists in order: the shading lists, then with MSAA theirs for each further distinct
    // triangle of a pixel (after every first one is stored).
    const size_t lists = in.tables->lists.size();
    for (size_t i = 0; i < in.extent.lists.x; ++i) {
        const ShadingList& list = in.tables->lists[i % lists];
        const bool layered = list.variant.layers != 0;
        const ShadeKey key{.variant = list.variant,
                           .coreSlots = mTextureSets->coreSlots[list.textureSet],
                           .layerSlots = mTextureSets->layerSlots[list.textureSet],
                           .deformed = frame.deformed.valid(),
                           .distinct = static_cast<uint32_t>(i / lists)};
        dispatches.push_back({&pipeline(key), layered,
                              (layered ? mLayeredMaterialSets : mCoreMaterialSets).at(list.textureSet), list.textureSet});
        anyLayered = anyLayered || layered;
    }
    const TextureId cleared = addClearPass(graph, "visibility_clear", "hdr",
                                           {.width = in.extent.extent.x, .height = in.extent.extent.y, .format = kHdrFormat});
    struct Data {
        TextureId visibility, hdr;
        BufferId lists, arguments, draws, frame, posedDraws, posedLights, posedMaterials, posedMaterialLayers, deformed;
        IblHandles ibl;
        LayerMaps layers;
    };
    const Data& data = graph.addPass<Data>(
        "visibility_shade", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            d.visibility = builder.read(in.visibility, Usage::Sampled);
            d.lists = builder.read(in.tiles.lists, Usage::StorageRead);
            d.arguments = builder.read(in.tiles.arguments, Usage::Indirect);
            d.draws = builder.read(in.draws, Usage::StorageRead);
            d.frame = builder.read(in.frameData, Usage::StorageRead);
            d.ibl = ForwardIblSet::declare(builder, frame.ibl ? &*frame.ibl : nullptr, kCompute);
            if (anyLayered) d.layers = ForwardLayerSet::declare(builder, &frame.layerMaps);
            if (frame.posedDraws.valid()) d.posedDraws = builder.read(frame.posedDraws, Usage::StorageRead);
            if (frame.posedLights.valid()) d.posedLights = builder.read(frame.posedLights, Usage::StorageRead);
            if (frame.posedMaterials.valid()) d.posedMaterials = builder.read(frame.posedMaterials, Usage::StorageRead);
            if (frame.posedMaterialLayers.valid() && anyLayered)
                d.posedMaterialLayers = builder.read(frame.posedMaterialLayers, Usage::StorageRead);
            if (frame.deformed.valid()) d.deformed = builder.read(frame.deformed, Usage::StorageRead);
            d.hdr = builder.write(cleared, Usage::StorageWrite);
        },
        [dispatches = std::move(dispatches), push = frame.push, core = &program(false),
         layeredProgram = anyLayered ? &program(true) : nullptr, textureSets = mTextureSets, scene = mScene,
         staticSceneSet = mSceneSet, iblSets = &mIblSet, layerSets = &mLayerSet,
         nearest = mNearest.get()](const Data& d, PassContext& ctx) {
            VkCommandBuffer cmd = ctx.cmd();
            const VkImageView visibilityView = ctx.view(d.visibility);
            const VkImageView hdrView = ctx.view(d.hdr);
            // Sets 0 (posed draws, lights and materials: this frame's buffers), 2 and 4 are the same
            // for every variant.
            const VkDescriptorSet sceneSet =
                !d.posedDraws.valid() && !d.posedLights.valid() && !d.posedMaterials.valid()
                    ? staticSceneSet
                    : vk::DescriptorWriter(*core, 0)
                          .buffer(ForwardBlock<shading::LightData>::name,
                                  d.posedLights.valid() ? ctx.buffer(d.posedLights) : scene->lightBuffer())
                          .buffer(ForwardBlock<shading::DrawData>::name,
                                  d.posedDraws.valid() ? ctx.buffer(d.posedDraws) : scene->drawBuffer())
                          .buffer(ForwardBlock<shading::MaterialData>::name,
                                  d.posedMaterials.valid() ? ctx.buffer(d.posedMaterials) : scene->materialBuffer())
                          .commit(ctx.context(), ctx.descriptors());
            // Posed layer data: the layered texture sets' sets 1 name this frame's buffer.
            std::vector<VkDescriptorSet> posedLayeredSets(d.posedMaterialLayers.valid() ? textureSets->firstMaterial.size() : 0,
                                                          VK_NULL_HANDLE);
            const auto materialSet = [&](const Dispatch& dispatch) {
                if (!dispatch.layered || posedLayeredSets.empty()) return dispatch.materialSet;
                VkDescriptorSet& set = posedLayeredSets[dispatch.textureSet];
                if (set == VK_NULL_HANDLE)
                    set = writeMaterialSet(ctx.context(), ctx.descriptors(), *layeredProgram, *scene,
                                          textureSets->firstMaterial[dispatch.textureSet], ctx.buffer(d.posedMaterialLayers));
                return set;
            };
            const VkDescriptorSet iblSet = iblSets->write(ctx, *core, d.ibl);
            const VkBuffer vertices = scene->vertexBuffer();
            const VkDescriptorSet visibilitySet =
                vk::DescriptorWriter(*core, 4)
                    .image("visibility", visibilityView, ctx.layout(d.visibility), nearest)
                    .image("shaded", hdrView, ctx.layout(d.hdr))
                    .buffer("Vertices", vertices)
                    .buffer("DeformedVertices", d.deformed.valid() ? ctx.buffer(d.deformed) : vertices)
                    .buffer("Indices", scene->indexBuffer())
                    .buffer("VisibilityDraws", ctx.buffer(d.draws))
                    .buffer("TileLists", ctx.buffer(d.lists))
                    .buffer("Frame", ctx.buffer(d.frame))
                    .commit(ctx.context(), ctx.descriptors());
            const VkBuffer arguments = ctx.buffer(d.arguments);
            // Successive dispatches write the image (disjoint pixels, which synchronization
            // validation cannot tell apart): a barrier between them.
            const auto writeToWrite = [&] {
                vk::memoryBarrier(cmd, kCompute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, kCompute,
                                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            };
            shading::ForwardPush constants = push;
            for (uint32_t v = 0; v < dispatches.size(); ++v) {
                const vk::Pipeline& p = *dispatches[v].pipeline;
                p.bind(cmd);
                const VkDescriptorSet sets[] = {sceneSet, materialSet(dispatches[v]), iblSet};
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout(), 0, 3, sets, 0, nullptr);
                if (dispatches[v].layered) {
                    const VkDescriptorSet layerSet = layerSets->write(ctx, p.program(), d.layers);
                    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout(), 3, 1, &layerSet, 0, nullptr);
                }
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout(), 4, 1, &visibilitySet, 0, nullptr);
                constants.counts.z = v;
                p.pushConstants(cmd, &constants, sizeof(constants));
                if (v > 0) writeToWrite();
                vkCmdDispatchIndirect(cmd, arguments, VkDeviceSize(v) * sizeof(VkDispatchIndirectCommand));
            }
        });
    return data.hdr;
}

}  // namespace candela::passes
