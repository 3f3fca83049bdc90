#include "passes/deform/skin_morph_pass.h"

#include "core/errors.h"
#include "executor/graph_executor.h"
#include "passes/recording/compute.h"
#include "vk/context.h"
#include "vk/descriptors.h"

#include <climits>
#include <cstring>

namespace candela::passes {

using namespace graph;

static_assert(sizeof(scene::Vertex) == CANDELA_VERTEX_FLOATS * sizeof(float));
static_assert(sizeof(shading::ActiveMorphTarget) == CANDELA_ACTIVE_TARGET_WORDS * sizeof(uint32_t));
static_assert(sizeof(glm::mat4) == CANDELA_JOINT_WORDS * sizeof(uint32_t));

namespace {

template <class T>
void appendWords(std::vector<uint32_t>& words, const T& value) {
    const size_t first = words.size();
    words.resize(first + sizeof(T) / sizeof(uint32_t));
    std::memcpy(words.data() + first, &value, sizeof(T));
}

}  // namespace

SkinMorphFrame skinMorphFrame(const gpu_scene::GpuScene& gpuScene, const pose::ScenePose& pose) {
    const scene::Scene& scene = gpuScene.scene();
    SkinMorphFrame out;
    out.vertexOffset.assign(pose.draws().size(), INT32_MIN);
    // The joint matrices first, then each draw's non-zero weights.
    std::vector<uint32_t> jointWord(scene.skins.size());
    for (size_t s = 0; s < scene.skins.size(); ++s) {
        jointWord[s] = uint32_t(out.frameData.size());
        for (const glm::dmat4& m : pose.jointMatrices(uint32_t(s))) appendWords(out.frameData, glm::mat4(m));
    }
    for (uint32_t d : pose.deformedDraws()) {
        const scene::Draw& draw = pose.draws()[d];
        const scene::Deformation& deformation = scene.deformations[size_t(draw.deformation)];
        SkinMorphJob job{.sourceFirstVertex = deformation.firstVertex,
                         .vertexCount = deformation.vertexCount,
                         .targetFirstVertex = out.vertexCount,
                         .recordWord = gpuScene.deformationWord(size_t(draw.deformation)),
                         .recordWords = gpu_scene::deformationRecordWords(deformation),
                         .deltaWord = deformation.influencesPerVertex * CANDELA_INFLUENCE_WORDS,
                         .influencesPerVertex = draw.skin >= 0 ? deformation.influencesPerVertex : 0,
                         .jointWord = draw.skin >= 0 ? jointWord[size_t(draw.skin)] : 0,
                         .activeWord = uint32_t(out.frameData.size())};
        const std::span<const float> weights = pose.weights(draw);
        for (uint32_t t = 0; t < deformation.targetCount && t < weights.size(); ++t)
            if (weights[t] != 0.0f) {
                appendWords(out.frameData, shading::ActiveMorphTarget{t, weights[t]});
                ++job.activeCount;
            }
        out.activeTargets += job.activeCount;
        out.vertexOffset[d] = int32_t(int64_t(out.vertexCount) - int64_t(deformation.firstVertex));
        out.vertexCount += deformation.vertexCount;
        out.skinnedDraws += draw.skin >= 0;
        out.jobs.push_back(job);
    }
    return out;
}

SkinMorphPass::SkinMorphPass(vk::Context& context, const std::optional<SkinMorphLimits>& limits)
    : mContext(context), mLimits(limits ? *limits : SkinMorphLimits::of(context.caps())) {}

BufferId SkinMorphPass::add(RenderGraph& graph, const Inputs& in) {
    const vk::Pipeline* pipeline =
        &mPipelines.get(mContext, 0, [&] { return vk::Pipeline::compute(mContext, "skin_morph.comp"); });
    std::vector<SkinMorphDispatch> dispatches;
    for (const SkinMorphJob& job : in.jobs) {
        const std::vector<SkinMorphDispatch> split = skinMorphDispatches(job, mLimits);
        dispatches.insert(dispatches.end(), split.begin(), split.end());
    }
    const VkDeviceSize frameBytes = graph.declaration().resources[in.frameData.index].buffer.size;
    if (frameBytes > mLimits.maxStorageBufferRange)
        throw UserError("skin_morph: this frame's joint matrices and morph weights (" + formatBytes(frameBytes) +
                        ") pass the device's maxStorageBufferRange (" + formatBytes(mLimits.maxStorageBufferRange) + ")");
    struct Data {
        BufferId frame, deformed;
    };
    const Data& data = graph.addPass<Data>(
        "skin_morph", PassType::Compute,
        [&](PassBuilder& builder, Data& d) {
            d.frame = builder.read(in.frameData, Usage::StorageRead);
            const BufferId deformed = builder.createBuffer(
                "deformed_vertices", {.size = VkDeviceSize(std::max(in.vertexCount, 1u)) * sizeof(scene::Vertex)});
            d.deformed = builder.write(deformed, Usage::StorageWrite, WriteMode::Discard);
        },
        [pipeline, scene = in.scene, dispatches = std::move(dispatches)](const Data& d, PassContext& ctx) {
            pipeline->bind(ctx.cmd());
            // Each dispatch binds the ranges its vertices need; they write disjoint ranges: no
            // barrier between them.
            for (const SkinMorphDispatch& dispatch : dispatches) {
                const VkDescriptorSet set =
                    vk::DescriptorWriter(pipeline->program(), 0)
                        .buffer("BaseVertices", scene->vertexBuffer(), dispatch.vertices.offset, dispatch.vertices.size)
                        .buffer("Deformation", scene->deformationBuffer(), dispatch.deformation.offset, dispatch.deformation.size)
                        .buffer("FrameData", ctx.buffer(d.frame))
                        .buffer("Deformed", ctx.buffer(d.deformed), dispatch.deformed.offset, dispatch.deformed.size)
                        .commit(ctx.context(), ctx.descriptors());
                vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline->layout(), 0, 1, &set, 0,
                                        nullptr);
                pipeline->pushConstants(ctx.cmd(), &dispatch.push, sizeof(dispatch.push));
                vkCmdDispatch(ctx.cmd(), dispatch.groups.x, dispatch.groups.y, 1);
            }
        });
    return data.deformed;
}

}  // namespace candela::passes
