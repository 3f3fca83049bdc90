#include "passes/visibility/visibility_classify_pass.h"

#include "executor/graph_executor.h"
#include "passes/recording/compute.h"
#include "vk/descriptors.h"
#include "vk/sampler.h"

#include <algorithm>

namespace candela::passes {

using namespace graph;

VisibilityClassifyPass::VisibilityClassifyPass(vk::Context& context)
    : mContext(context), mNearest(vk::createSampler(context, vk::kNearestSampler)) {}

VisibilityTileLists VisibilityClassifyPass::add(RenderGraph& graph, TextureId visibility, BufferId draws, BufferId frameData,
                                                const shading::VisibilityFrame& extent) {
    const bool msaa = extent.samples.x > 1;
    const vk::Pipeline* classify = &mPipelines.get(mContext, msaa ? 2 : 0, [&] {
        return vk::Pipeline::compute(mContext, msaa ? "visibility_classify_msaa.comp" : "visibility_classify.comp");
    });
    const vk::Pipeline* tiles = &mPipelines.get(mContext, 1, [&] { return vk::Pipeline::compute(mContext, "visibility_tiles.comp"); });
    const uint32_t lists = std::max(extent.lists.x, 1u);  // buffers are never empty
    struct Data {
        TextureId visibility;
        BufferId draws, frame, masks, lists, arguments;
    };
    const Data& data = graph.addPass<Data>(
        "visibility_classify", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            d.visibility = builder.read(visibility, Usage::Sampled);
            d.draws = builder.read(draws, Usage::StorageRead);
            d.frame = builder.read(frameData, Usage::StorageRead);
            const VkDeviceSize tileCount = extent.extent.w;
            d.masks = builder.write(builder.createBuffer("visibility_tile_masks", {.size = tileCount * extent.lists.y * sizeof(uint32_t)}),
                                    Usage::StorageReadWrite, WriteMode::Discard);
            d.lists = builder.write(builder.createBuffer("visibility_tile_lists", {.size = tileCount * lists * sizeof(uint32_t)}),
                                    Usage::StorageWrite, WriteMode::Discard);
            d.arguments = builder.write(
                builder.createBuffer("visibility_dispatch_arguments", {.size = lists * sizeof(VkDispatchIndirectCommand)}),
                Usage::StorageWrite, WriteMode::Discard);
        },
        [classify, tiles, extent, lists, nearest = mNearest.get()](const Data& d, PassContext& ctx) {
            const VkDescriptorSet classifySet = vk::DescriptorWriter(classify->program(), 0)
                                                    .image("visibility", ctx.view(d.visibility), ctx.layout(d.visibility),
                                                           nearest)
                                                    .buffer("VisibilityDraws", ctx.buffer(d.draws))
                                                    .buffer("TileMasks", ctx.buffer(d.masks))
                                                    .buffer("Frame", ctx.buffer(d.frame))
                                                    .commit(ctx.context(), ctx.descriptors());
            classify->bind(ctx.cmd());
            vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, classify->layout(), 0, 1, &classifySet, 0, nullptr);
            vkCmdDispatch(ctx.cmd(), groupCount(extent.extent.w, 64), 1, 1);
            computeWriteToReadBarrier(ctx.cmd());
            const VkDescriptorSet tilesSet = vk::DescriptorWriter(tiles->program(), 0)
                                                 .buffer("TileMasks", ctx.buffer(d.masks))
                                                 .buffer("TileLists", ctx.buffer(d.lists))
                                                 .buffer("DispatchArguments", ctx.buffer(d.arguments))
                                                 .buffer("Frame", ctx.buffer(d.frame))
                                                 .commit(ctx.context(), ctx.descriptors());
            tiles->bind(ctx.cmd());
            vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, tiles->layout(), 0, 1, &tilesSet, 0, nullptr);
            if (extent.lists.x) vkCmdDispatch(ctx.cmd(), extent.lists.x, 1, 1);
        });
    return {data.lists, data.arguments};
}

}  // namespace candela::passes
