#include "passes/skin_morph_pass.h"

#include "executor/graph_executor.h"
#include "passes/compute.h"
#include "vk/descriptors.h"

#include <climits>

namespace candela::passes {

using namespace graph;

static_assert(sizeof(scene::Vertex) == CANDELA_VERTEX_FLOATS * sizeof(float));
static_assert(sizeof(shading::ActiveMorphTarget) == sizeof(scene::JointInfluence));

SkinMorphFrame skinMorphFrame(const scene::GpuScene& gpuScene, const scene::ScenePose& pose) {
    const scene::Scene& scene = gpuScene.scene();
    SkinMorphFrame out;
    out.vertexOffset.assign(pose.draws().size(), INT32_MIN);
    std::vector<uint32_t> jointBase(scene.skins.size());
    for (size_t s = 0; s < scene.skins.size(); ++s) {
        jointBase[s] = uint32_t(out.joints.size());
        for (const glm::dmat4& m : pose.jointMatrices(uint32_t(s))) out.joints.emplace_back(m);
    }
    for (uint32_t d : pose.deformedDraws()) {
        const scene::Draw& draw = pose.draws()[d];
        const scene::Deformation& deformation = scene.deformations[size_t(draw.deformation)];
        shading::SkinMorphPush job{.sourceFirstVertex = deformation.firstVertex,
                                   .vertexCount = deformation.vertexCount,
                                   .targetFirstVertex = out.vertexCount,
                                   .deltaBase = gpuScene.deltaBase(size_t(draw.deformation)),
                                   .activeBase = uint32_t(out.activeTargets.size()),
                                   .jointBase = draw.skin >= 0 ? jointBase[size_t(draw.skin)] : 0,
                                   .influenceBase = gpuScene.influenceBase(size_t(draw.deformation)),
                                   .influencesPerVertex = draw.skin >= 0 ? deformation.influencesPerVertex : 0};
        const std::span<const float> weights = pose.weights(draw);
        for (uint32_t t = 0; t < deformation.targetCount && t < weights.size(); ++t)
            if (weights[t] != 0.0f) out.activeTargets.push_back({t, weights[t]});
        job.activeCount = uint32_t(out.activeTargets.size()) - job.activeBase;
        out.vertexOffset[d] = int32_t(int64_t(out.vertexCount) - int64_t(deformation.firstVertex));
        out.vertexCount += deformation.vertexCount;
        out.skinnedDraws += draw.skin >= 0;
        out.jobs.push_back(job);
    }
    return out;
}

SkinMorphPass::SkinMorphPass(vk::Context& context) : mContext(context) {}

BufferId SkinMorphPass::add(RenderGraph& graph, const Inputs& in) {
    const vk::Pipeline* pipeline =
        &mPipelines.get(mContext, 0, [&] { return vk::Pipeline::compute(mContext, "skin_morph.comp"); });
    struct Data {
        BufferId joints, active, deformed;
    };
    const Data& data = graph.addPass<Data>(
        "skin_morph", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            d.joints = builder.read(in.joints, Usage::StorageRead);
            d.active = builder.read(in.activeTargets, Usage::StorageRead);
            const BufferId deformed = builder.createBuffer(
                "deformed_vertices", {.size = VkDeviceSize(std::max(in.vertexCount, 1u)) * sizeof(scene::Vertex)});
            d.deformed = builder.write(deformed, Usage::StorageWrite, WriteMode::Discard);
        },
        [pipeline, scene = in.scene, jobs = in.jobs](const Data& d, PassContext& ctx) {
            const VkDescriptorSet set = vk::DescriptorWriter(pipeline->program(), 0)
                                            .buffer("BaseVertices", scene->vertexBuffer())
                                            .buffer("Deltas", scene->deltaBuffer())
                                            .buffer("Influences", scene->influenceBuffer())
                                            .buffer("Joints", ctx.buffer(d.joints))
                                            .buffer("ActiveTargets", ctx.buffer(d.active))
                                            .buffer("Deformed", ctx.buffer(d.deformed))
                                            .commit(ctx.context(), ctx.descriptors());
            pipeline->bind(ctx.cmd());
            vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline->layout(), 0, 1, &set, 0, nullptr);
            // The jobs write disjoint ranges: no barrier between them.
            for (const shading::SkinMorphPush& job : jobs) {
                pipeline->pushConstants(ctx.cmd(), &job, sizeof(job));
                vkCmdDispatch(ctx.cmd(), groupCount(job.vertexCount, CANDELA_SKIN_MORPH_GROUP_SIZE), 1, 1);
            }
        });
    return data.deformed;
}

}  // namespace candela::passes
