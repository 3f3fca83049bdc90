#pragma once
// Small recording helpers shared by the compute passes.

#include "executor/graph_executor.h"
#include "vk/commands.h"
#include "vk/pipeline.h"

namespace candela::passes {

inline uint32_t groupCount(uint32_t size, uint32_t group) { return (size + group - 1) / group; }

// Binds `pipeline` and set 0, pushes the constants and dispatches x × y × z workgroups.
inline void dispatchCompute(const graph::PassContext& ctx, const vk::Pipeline& pipeline, VkDescriptorSet set,
                            const void* pushConstants, uint32_t pushSize, uint32_t x, uint32_t y, uint32_t z) {
    pipeline.bind(ctx.cmd());
    vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 0, 1, &set, 0, nullptr);
    pipeline.pushConstants(ctx.cmd(), pushConstants, pushSize);
    vkCmdDispatch(ctx.cmd(), x, y, z);
}

// Makes compute-shader writes visible to compute-shader reads within one pass (between dispatches
// that the graph sees as one pass, e.g. successive mips of one image).
inline void computeWriteToReadBarrier(VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

}  // namespace candela::passes
