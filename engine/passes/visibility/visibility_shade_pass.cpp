#include "passes/visibility/visibility_shade_pass.h"

#include "executor/graph_executor.h"
#include "passes/visibility/clear_pass.h"
#include "passes/recording/compute.h"
#include "passes/drawing/scene_bindings.h"
#include "shared/specialization_ids.h"
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
        for (const auto& [id, value] : {std::pair{CANDELA_SPEC_DEFORMED, uint32_t(key.deformed)},
                                        std::pair{CANDELA_SPEC_CORE_TEXTURES, key.coreSlots},
                                        std::pair{CANDELA_SPEC_LAYER_TEXTURES, key.layerSlots},
                                        std::pair{CANDELA_SPEC_DISTINCT, key.distinct},
                                        std::pair{CANDELA_SPEC_SAMPLES, key.variant.samples},
                                        std::pair{CANDELA_SPEC_TILE_X, mTile.x},
                                        std::pair{CANDELA_SPEC_TILE_Y, mTile.y}})
            shader::setSpecialization(constants, id, value);
        return vk::Pipeline::compute(mContext, shaderOf(key.variant.layers != 0, key.variant.samples > 1), constants);
    });
}

void VisibilityShadePass::setScene(const gpu_scene::GpuScene& scene, const MaterialKeys& keys, const TextureSets& sets) {
    mScene = &scene;
    mTextureSets = &sets;
    mSets = std::make_unique<vk::DescriptorAllocator>(mContext, 4);
    const vk::Program& core = program(false);
    const size_t count = sets.firstMaterial.size();
    std::vector<bool> coreUse(count, false), layeredUse(count, false);
    for (uint32_t material = 0; material < sets.ofMaterial.size(); ++material)
        (keys[material].layers ? layeredUse : coreUse)[sets.ofMaterial[material]] = true;
    mSceneSet = writeSceneSet(mContext, *mSets, core, sceneBuffersOf(scene));
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
    const FrameInputs& frame = *in.frame;
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
        BufferId lists, arguments, draws, frame;
        DeclaredFrameBuffers buffers;
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
            d.ibl = IblSet::declare(builder, frame.ibl ? &*frame.ibl : nullptr, kCompute);
            if (anyLayered) d.layers = LayerMapSet::declare(builder, &frame.layerMaps);
            d.buffers = declareFrameReads(builder, frame, {.materialLayers = anyLayered, .deformedUsage = Usage::StorageRead});
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
            const VkDescriptorSet sceneSet = frameSceneSet(ctx, *core, *scene, d.buffers.posed, staticSceneSet);
            // Posed layer data: the layered texture sets' sets 1 name this frame's buffer.
            PosedMaterialSets posedSets(ctx, *scene, d.buffers.posed.materialLayers, textureSets->firstMaterial.size());
            const auto materialSet = [&](const Dispatch& dispatch) {
                if (!dispatch.layered) return dispatch.materialSet;
                return posedSets.get(dispatch.textureSet, true, *layeredProgram,
                                     textureSets->firstMaterial[dispatch.textureSet], dispatch.materialSet);
            };
            const VkDescriptorSet iblSet = iblSets->write(ctx, *core, d.ibl);
            const VkBuffer vertices = scene->vertexBuffer();
            const VkDescriptorSet visibilitySet =
                vk::DescriptorWriter(*core, 4)
                    .image("visibility", visibilityView, ctx.layout(d.visibility), nearest)
                    .image("shaded", hdrView, ctx.layout(d.hdr))
                    .buffer("Vertices", vertices)
                    .buffer("DeformedVertices", d.buffers.deformed.valid() ? ctx.buffer(d.buffers.deformed) : vertices)
                    .buffer("Indices", scene->indexBuffer())
                    .buffer("VisibilityDraws", ctx.buffer(d.draws))
                    .buffer("TileLists", ctx.buffer(d.lists))
                    .buffer("Frame", ctx.buffer(d.frame))
                    .commit(ctx.context(), ctx.descriptors());
            const VkBuffer arguments = ctx.buffer(d.arguments);
            // Successive dispatches write the image, and at several samples those of a pixel's
            // second and later distinct IDs add to what an earlier one wrote (imageLoad): a barrier
            // between them that makes the writes visible to reads and writes alike. With writes
            // alone in its destination scope the validation layer (1.3.239) reported nothing, and an
            // NVIDIA GPU read stale values at a few edge pixels (a still scene's frames differed;
            // tools/gpu-check.sh's repeated frames).
            const auto writeToReadWrite = [&] {
                vk::memoryBarrier(cmd, kCompute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, kCompute,
                                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            };
            shading::FramePush constants = push;
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
                if (v > 0) writeToReadWrite();
                vkCmdDispatchIndirect(cmd, arguments, VkDeviceSize(v) * sizeof(VkDispatchIndirectCommand));
            }
        });
    return data.hdr;
}

}  // namespace candela::passes
