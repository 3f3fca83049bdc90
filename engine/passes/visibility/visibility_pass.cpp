#include "passes/visibility/visibility_pass.h"

#include "executor/graph_executor.h"
#include "passes/drawing/draw_recorder.h"
#include "passes/drawing/scene_bindings.h"
#include "shared/specialization_ids.h"

#include <algorithm>

namespace candela::passes {

using namespace graph;

VisibilityPass::VisibilityPass(vk::Context& context) : mContext(context) {}

const vk::Pipeline& VisibilityPass::pipeline(const Variant& v) {
    return mPipelines.get(mContext, v, [&] {
        vk::GraphicsPipelineDesc desc{.colorFormats = {kVisibilityFormat},
                                      .depthFormat = kDepthFormat,
                                      .depthTest = true,
                                      .depthWrite = true,
                                      .depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL,
                                      .samples = v.samples,
                                      .dynamicCullMode = true,
                                      .vertexBindings = {{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}},
                                      .vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)}}};
        if (v.masked) {
            desc.specialization =
                shader::specializationValues({{CANDELA_SPEC_ALPHA_TO_COVERAGE, v.alphaToCoverage}, {CANDELA_SPEC_SAMPLES, v.samples}});
            desc.vertexAttributes.push_back({3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv0)});
            desc.vertexAttributes.push_back({4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv1)});
            desc.vertexAttributes.push_back({5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, color)});
        }
        return v.masked ? vk::Pipeline::graphics(mContext, "visibility_masked.vert", "visibility_masked.frag", desc)
                        : vk::Pipeline::graphics(mContext, "visibility.vert", "visibility.frag", desc);
    });
}

void VisibilityPass::setScene(const gpu_scene::GpuScene& scene, const TextureSets& sets) {
    mScene = &scene;
    mTextureSets = &sets;
    mSets = std::make_unique<vk::DescriptorAllocator>(mContext, 4);
    const vk::Program& opaque = pipeline({.masked = false}).program();
    const vk::Program& masked = pipeline({.masked = true}).program();
    vk::DescriptorCounts total = vk::DescriptorCounts::ofSet(masked, 1) * static_cast<uint32_t>(sets.firstMaterial.size());
    total += vk::DescriptorCounts::ofSet(opaque, 0);
    total += vk::DescriptorCounts::ofSet(masked, 0);
    mSets->reserve(total);
    mOpaqueSceneSet = writeSceneSet(mContext, *mSets, opaque, sceneBuffersOf(scene));
    mMaskedSceneSet = writeSceneSet(mContext, *mSets, masked, sceneBuffersOf(scene));
    mBaseColorSets.clear();
    for (uint32_t material : sets.firstMaterial) {
        const gpu_scene::GpuScene::Binding b = scene.texture(material, CANDELA_TEX_BASE_COLOR);
        mBaseColorSets.push_back(vk::DescriptorWriter(masked, 1)
                                     .image(scene::kCoreTextureSlots[CANDELA_TEX_BASE_COLOR].sampler, b.view,
                                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, b.sampler)
                                     .commit(mContext, *mSets));
    }
}

VisibilityTargets VisibilityPass::add(RenderGraph& graph, const DrawTargetSize& size, std::span<const DrawListItem> items,
                                      const MaterialKeys& keys, const FrameInputs& frame, DrawStats* stats) {
    std::vector<DrawCall> draws;
    draws.reserve(items.size());
    bool anyMasked = false;
    for (const DrawListItem& item : items) {
        const bool masked = keys.keys[item.key].alphaMask;
        anyMasked = anyMasked || masked;
        // Masked draws bind set 1: the base colour texture of their texture set.
        draws.push_back({.pipeline = &pipeline({.masked = masked, .samples = size.samples, .alphaToCoverage = masked && frame.variant.alphaToCoverage}),
                         .item = item,
                         .vertexOffset = frame.vertexOffsetOf(item.draw),
                         .materialSet = masked ? mBaseColorSets[mTextureSets->ofMaterial[item.material]] : VK_NULL_HANDLE});
    }
    struct Data {
        VisibilityTargets targets;
        DeclaredFrameBuffers buffers;
    };
    const Data& data = graph.addPass<Data>(
        "visibility", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            const TextureDesc desc{.width = size.width, .height = size.height, .format = kVisibilityFormat, .samples = size.samples};
            TextureDesc depth = desc;
            depth.format = kDepthFormat;
            d.targets.visibility = builder.writeColor(builder.createTexture("visibility", desc), VkClearColorValue{});
            d.targets.depth = builder.writeDepth(builder.createTexture("depth", depth), 0.0f);  // reverse-Z: far = 0
            // Masked draws read the alpha factor, cutoff and base colour texture transform.
            d.buffers = declareFrameReads(builder, frame,
                                          {.lights = false,
                                           .materials = anyMasked,
                                           .sceneStages = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT});
        },
        [draws = std::move(draws), push = frame.push, scene = mScene, opaqueSet = mOpaqueSceneSet, maskedSet = mMaskedSceneSet,
         stats](const Data& d, PassContext& ctx) {
            recordDraws(
                ctx, draws, *scene, deformedBuffer(ctx, d.buffers), push, stats,
                [&](const vk::Pipeline& bound, const DrawCall& draw, DrawStats& counts) {
                    const bool masked = draw.materialSet != VK_NULL_HANDLE;  // only masked draws have a set 1
                    const VkDescriptorSet sceneSet = masked ? maskedSet : opaqueSet;
                    bindGraphicsSet(ctx.cmd(), bound, 0, frameSceneSet(ctx, bound.program(), *scene, d.buffers.posed, sceneSet), counts);
                },
                [](const DrawCall& draw) { return draw.materialSet; });
        });
    return data.targets;
}

}  // namespace candela::passes
