#include "passes/aov/aov_pass.h"

#include "executor/graph_executor.h"
#include "passes/drawing/draw_recorder.h"
#include "passes/drawing/draw_target.h"
#include "passes/drawing/scene_bindings.h"
#include "shared/scene_data.h"
#include "shared/specialization_ids.h"

#include <cmath>
#include <limits>
#include <string>

namespace candela::passes {

using namespace graph;

namespace {

constexpr const char* kAovTargetNames[CANDELA_AOV_TARGET_COUNT] = {
    "aov_view_depth", "aov_normal", "aov_base_color", "aov_metallic_roughness", "aov_emissive", "aov_ids", "aov_instance"};

// What a target holds where nothing is drawn.
VkClearColorValue emptyValue(uint32_t target) {
    VkClearColorValue value{};
    if (target == CANDELA_AOV_VIEW_DEPTH) value.float32[0] = std::numeric_limits<float>::infinity();
    if (target == CANDELA_AOV_IDS || target == CANDELA_AOV_INSTANCE)
        for (uint32_t& id : value.uint32) id = CANDELA_NO_ID;
    return value;
}

}  // namespace

AovPass::AovPass(vk::Context& context) : mContext(context) {}

const vk::Pipeline& AovPass::pipeline(const Variant& v) {
    return mPipelines.get(mContext, v, [&] {
        vk::GraphicsPipelineDesc desc{
            .depthFormat = kDepthFormat,
            .topology = primitiveTopology(v.topology),
            .depthTest = true,
            .depthWrite = true,
            .depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL,
            .dynamicCullMode = true,
            .specialization = shader::specializationValues({{CANDELA_SPEC_AOV_TARGETS, v.targets},
                                                            {CANDELA_SPEC_NORMAL_MAP, v.normalMap},
                                                            {CANDELA_SPEC_ALPHA_MASK, v.alphaTest}}),
            .vertexBindings = sceneVertexBindings(),
            .vertexAttributes = sceneVertexAttributes()};
        // The targets asked for are fixed in the program at load, which then has no output for the
        // others, and their outputs are moved to the attachments' locations: in order, packed.
        desc.frozenConstants = {CANDELA_SPEC_AOV_TARGETS};
        desc.outputLocations.assign(CANDELA_AOV_TARGET_COUNT, CANDELA_AOV_TARGET_COUNT);
        for (uint32_t t = 0; t < CANDELA_AOV_TARGET_COUNT; ++t)
            if ((v.targets >> t) & 1u) {
                desc.outputLocations[t] = uint32_t(desc.colorFormats.size());
                desc.colorFormats.push_back(kAovFormats[t]);
            }
        return vk::Pipeline::graphics(mContext, "aov.vert", "aov.frag", desc);
    });
}

void AovPass::setScene(const gpu_scene::GpuScene& scene, const MaterialKeys& keys) {
    mScene = &scene;
    mKeys = &keys;
    mSets.reset();
    mMaterialSets.clear();
    mSceneSet = VK_NULL_HANDLE;
}

void AovPass::writeSets() {
    // Sets 0 and 1 are alike in every variant (no constant is frozen): the first variant's program
    // writes them for all.
    const vk::Program& program = pipeline({}).program();
    const uint32_t materials = static_cast<uint32_t>(mKeys->ofMaterial.size());
    mSets = std::make_unique<vk::DescriptorAllocator>(mContext, 16);
    vk::DescriptorCounts total = vk::DescriptorCounts::ofSet(program, 1) * materials;
    total += vk::DescriptorCounts::ofSet(program, 0);
    mSets->reserve(total);
    mSceneSet = writeSceneSet(mContext, *mSets, program, sceneBuffersOf(*mScene));
    for (uint32_t m = 0; m < materials; ++m)
        mMaterialSets.push_back(writeMaterialSet(mContext, *mSets, program, *mScene, m, VK_NULL_HANDLE));
}

AovTargets AovPass::add(RenderGraph& graph, uint32_t width, uint32_t height, uint32_t targets, const DrawList& list,
                        const FrameInputs& frame) {
    if (!mSets) writeSets();
    std::vector<DrawCall> draws;
    draws.reserve(list.items.size());
    for (const DrawListItem& item : list.items) {
        const MaterialKey& key = mKeys->keys[item.key];
        draws.push_back({.pipeline = &pipeline({.targets = targets,
                                                .normalMap = key.normalMap,
                                                .alphaTest = key.alphaMask || key.blend,
                                                .topology = key.topology}),
                         .item = item,
                         .vertexOffset = frame.vertexOffsetOf(item.draw),
                         .materialSet = mMaterialSets[item.material]});
    }
    struct Data {
        AovTargets out;
        DeclaredFrameBuffers buffers;
    };
    const Data& data = graph.addPass<Data>(
        "aov", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            for (uint32_t t = 0; t < CANDELA_AOV_TARGET_COUNT; ++t) {
                if (!((targets >> t) & 1u)) continue;
                const TextureId texture = builder.createTexture(kAovTargetNames[t], {.width = width, .height = height, .format = kAovFormats[t]});
                d.out.targets[t] = builder.writeColor(texture, emptyValue(t));  // in target order: packed
            }
            const TextureId depth = builder.createTexture("aov_depth", {.width = width, .height = height, .format = kDepthFormat});
            d.out.depth = builder.writeDepth(depth, 0.0f);  // reverse Z: far = 0
            d.buffers = declareFrameReads(builder, frame,
                                          {.lights = false,
                                           .materials = true,
                                           .sceneStages = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT});
        },
        [draws = std::move(draws), push = frame.push, scene = mScene, sceneSet = mSceneSet](const Data& d, PassContext& ctx) {
            recordDraws(
                ctx, draws, *scene, deformedBuffer(ctx, d.buffers), push, nullptr,
                [&](const vk::Pipeline& bound, const DrawCall&, DrawStats& counts) {
                    bindGraphicsSet(ctx.cmd(), bound, 0, frameSceneSet(ctx, bound.program(), *scene, d.buffers.posed, sceneSet), counts);
                },
                [](const DrawCall& draw) { return draw.materialSet; });
        });
    return data.out;
}

}  // namespace candela::passes
