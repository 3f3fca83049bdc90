#include "passes/visibility_pass.h"

#include "executor/graph_executor.h"
#include "passes/forward_blocks.h"

#include <algorithm>
#include <optional>

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
            desc.specialization = {v.alphaToCoverage, v.samples};  // kAlphaToCoverage, kSamples
            desc.vertexAttributes.push_back({3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv0)});
            desc.vertexAttributes.push_back({4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv1)});
            desc.vertexAttributes.push_back({5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, color)});
        }
        return v.masked ? vk::Pipeline::graphics(mContext, "visibility_masked.vert", "visibility_masked.frag", desc)
                        : vk::Pipeline::graphics(mContext, "visibility.vert", "visibility.frag", desc);
    });
}

void VisibilityPass::setScene(const scene::GpuScene& scene, const TextureSets& sets) {
    mScene = &scene;
    mTextureSets = &sets;
    mSets = std::make_unique<vk::DescriptorAllocator>(mContext, 4);
    const vk::Program& opaque = pipeline({.masked = false}).program();
    const vk::Program& masked = pipeline({.masked = true}).program();
    vk::DescriptorCounts total = vk::DescriptorCounts::ofSet(masked, 1) * static_cast<uint32_t>(sets.firstMaterial.size());
    total += vk::DescriptorCounts::ofSet(opaque, 0);
    total += vk::DescriptorCounts::ofSet(masked, 0);
    mSets->reserve(total);
    mOpaqueSceneSet = vk::DescriptorWriter(opaque, 0)
                          .buffer(ForwardBlock<shading::DrawData>::name, scene.drawBuffer())
                          .commit(mContext, *mSets);
    mMaskedSceneSet = vk::DescriptorWriter(masked, 0)
                          .buffer(ForwardBlock<shading::DrawData>::name, scene.drawBuffer())
                          .buffer(ForwardBlock<shading::MaterialData>::name, scene.materialBuffer())
                          .commit(mContext, *mSets);
    mBaseColorSets.clear();
    for (uint32_t material : sets.firstMaterial) {
        const scene::GpuScene::Binding b = scene.texture(material, CANDELA_TEX_BASE_COLOR);
        mBaseColorSets.push_back(vk::DescriptorWriter(masked, 1)
                                     .image(scene::kCoreTextureSlots[CANDELA_TEX_BASE_COLOR].sampler, b.view,
                                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, b.sampler)
                                     .commit(mContext, *mSets));
    }
}

VisibilityTargets VisibilityPass::add(RenderGraph& graph, const DrawTargetSize& size, std::span<const DrawListItem> items,
                                      const MaterialKeys& keys, const ForwardPass::FrameInputs& frame, DrawStats* stats) {
    struct Recorded {
        const vk::Pipeline* pipeline;
        bool masked;
        VkDescriptorSet baseColor;  // masked draws: set 1
        DrawListItem item;
        int32_t vertexOffset;
    };
    std::vector<Recorded> recorded;
    recorded.reserve(items.size());
    for (const DrawListItem& item : items) {
        const bool masked = keys.keys[item.key].alphaMask;
        recorded.push_back({.pipeline = &pipeline({.masked = masked,
                                                   .samples = size.samples,
                                                   .alphaToCoverage = masked && frame.variant.alphaToCoverage}),
                            .masked = masked,
                            .baseColor = masked ? mBaseColorSets[mTextureSets->ofMaterial[item.material]] : VK_NULL_HANDLE,
                            .item = item,
                            .vertexOffset = frame.vertexOffset.empty() ? ForwardPass::kRestVertices : frame.vertexOffset[item.draw]});
    }
    struct Data {
        VisibilityTargets targets;
        BufferId draws, materials, deformed;
    };
    const bool anyMasked = std::any_of(recorded.begin(), recorded.end(), [](const Recorded& r) { return r.masked; });
    const Data& data = graph.addPass<Data>(
        "visibility", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            const TextureDesc desc{.width = size.width, .height = size.height, .format = kVisibilityFormat, .samples = size.samples};
            TextureDesc depth = desc;
            depth.format = kDepthFormat;
            d.targets.visibility = builder.writeColor(builder.createTexture("visibility", desc), VkClearColorValue{});
            d.targets.depth = builder.writeDepth(builder.createTexture("depth", depth), 0.0f);  // reverse-Z: far = 0
            if (frame.posedDraws.valid())
                d.draws = builder.read(frame.posedDraws, Usage::StorageRead,
                                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            // Masked draws read the alpha factor, cutoff and base colour texture transform.
            if (frame.posedMaterials.valid() && anyMasked)
                d.materials = builder.read(frame.posedMaterials, Usage::StorageRead,
                                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            if (frame.deformed.valid()) d.deformed = builder.read(frame.deformed, Usage::Vertex);
        },
        [items = std::move(recorded), push = frame.push, scene = mScene, opaqueSet = mOpaqueSceneSet, maskedSet = mMaskedSceneSet,
         stats](const Data& d, PassContext& ctx) {
            DrawStats unused;
            DrawStats* counts = stats ? stats : &unused;
            VkCommandBuffer cmd = ctx.cmd();
            // A pose: set 0 names this frame's draw (and, for masked draws, material) buffer.
            const auto sceneSet = [&](const vk::Pipeline& pipeline, bool masked) {
                if (!d.draws.valid() && !(masked && d.materials.valid())) return masked ? maskedSet : opaqueSet;
                vk::DescriptorWriter writer(pipeline.program(), 0);
                writer.buffer(ForwardBlock<shading::DrawData>::name, d.draws.valid() ? ctx.buffer(d.draws) : scene->drawBuffer());
                if (masked)
                    writer.buffer(ForwardBlock<shading::MaterialData>::name,
                                  d.materials.valid() ? ctx.buffer(d.materials) : scene->materialBuffer());
                return writer.commit(ctx.context(), ctx.descriptors());
            };
            ctx.beginRendering();
            const VkDeviceSize offset = 0;
            const VkBuffer rest = scene->vertexBuffer();
            const VkBuffer deformed = d.deformed.valid() ? ctx.buffer(d.deformed) : VK_NULL_HANDLE;
            VkBuffer boundVertices = rest;
            if (!items.empty()) {
                vkCmdBindVertexBuffers(cmd, 0, 1, &rest, &offset);
                vkCmdBindIndexBuffer(cmd, scene->indexBuffer(), 0, VK_INDEX_TYPE_UINT32);
                counts->bufferBinds += 2;
            }
            const vk::Pipeline* bound = nullptr;
            VkDescriptorSet boundBaseColor = VK_NULL_HANDLE;
            std::optional<VkCullModeFlags> cullMode;
            std::optional<VkFrontFace> frontFace;
            shading::ForwardPush constants = push;
            for (const Recorded& r : items) {
                if (r.pipeline != bound) {
                    bound = r.pipeline;
                    bound->bind(cmd);
                    ++counts->pipelineBinds;
                    const VkDescriptorSet set0 = sceneSet(*bound, r.masked);
                    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound->layout(), 0, 1, &set0, 0, nullptr);
                    ++counts->descriptorBinds;
                    boundBaseColor = VK_NULL_HANDLE;
                }
                if (r.masked && r.baseColor != boundBaseColor) {
                    boundBaseColor = r.baseColor;
                    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound->layout(), 1, 1, &boundBaseColor, 0, nullptr);
                    ++counts->descriptorBinds;
                }
                const DrawListItem& item = r.item;
                if (const VkCullModeFlags wanted = item.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT; cullMode != wanted) {
                    cullMode = wanted;
                    vkCmdSetCullMode(cmd, wanted);
                    ++counts->dynamicStates;
                }
                if (const VkFrontFace wanted = item.flipWinding ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
                    frontFace != wanted) {
                    frontFace = wanted;
                    vkCmdSetFrontFace(cmd, wanted);
                    ++counts->dynamicStates;
                }
                constants.counts.y = item.drawData;
                bound->pushConstants(cmd, &constants, sizeof(constants));
                const bool restVertices = r.vertexOffset == ForwardPass::kRestVertices;
                if (const VkBuffer wanted = restVertices ? rest : deformed; wanted != boundVertices) {
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
