// Step "barriers": the exact synchronization2 barriers planned for RAW, WAR, WAW, layout changes,
// repeated readers, imported initial/final states and memory taken over from aliased transients.

#include "graph_test_util.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace candela::graph {
namespace {

constexpr VkPipelineStageFlags2 kNoStage = VK_PIPELINE_STAGE_2_NONE;
constexpr VkPipelineStageFlags2 kColorOut = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkPipelineStageFlags2 kVsFs =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kFs = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
constexpr VkPipelineStageFlags2 kDepthTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags2 kNoAccess = VK_ACCESS_2_NONE;
constexpr VkAccessFlags2 kColorW = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
constexpr VkAccessFlags2 kColorRW = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | kColorW;
constexpr VkAccessFlags2 kSampled = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
constexpr VkAccessFlags2 kStorageR = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
constexpr VkAccessFlags2 kStorageW = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
constexpr VkAccessFlags2 kTransferW = VK_ACCESS_2_TRANSFER_WRITE_BIT;
constexpr VkImageLayout kUndefined = VK_IMAGE_LAYOUT_UNDEFINED;
constexpr VkImageLayout kGeneral = VK_IMAGE_LAYOUT_GENERAL;
constexpr VkImageLayout kColorLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
constexpr VkImageLayout kReadOnly = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;

const ResourceState kNothing{kNoStage, kNoAccess, kUndefined};
const ResourceState kColorTarget{kColorOut, kColorRW, kColorLayout};

// Barriers compare as text so a failure shows every field of both sides.
std::string text(const ResourceState& state) {
    std::ostringstream out;
    out << std::hex << "stages 0x" << state.stages << " access 0x" << state.access << std::dec << " layout "
        << state.layout;
    return out.str();
}

std::string text(const Barrier& barrier) {
    std::string result = "resource " + std::to_string(barrier.resource) + ": " + text(barrier.src) + " -> " +
                         text(barrier.dst);
    if (barrier.aliasedFrom != kInvalidIndex) result += " aliased from " + std::to_string(barrier.aliasedFrom);
    return result;
}

std::vector<std::string> text(const std::vector<Barrier>& barriers) {
    std::vector<std::string> result;
    for (const Barrier& barrier : barriers) result.push_back(text(barrier));
    return result;
}

std::vector<std::string> expected(std::initializer_list<Barrier> barriers) { return text(barriers); }

TEST(GraphBarriers, ColorThenSampledIsOneTransition) {
    RenderGraph graph;
    const TextureId target = graph.importTexture("target", kColor, {});  // resource 0
    TextureId t;                                                         // resource 1
    addPass(graph, "draw", PassType::Graphics,
            [&](PassBuilder& b) { t = b.writeColor(b.createTexture("t", kColor), VkClearColorValue{}); });
    addPass(graph, "post", PassType::Graphics, [&](PassBuilder& b) {
        b.read(t, Usage::Sampled);
        b.writeColor(target, VkClearColorValue{});
    });
    const CompiledGraph& compiled = graph.compile();
    ASSERT_EQ(compiled.barriers.size(), 2u);
    EXPECT_EQ(text(compiled.barriers[0]), expected({{1, kNothing, kColorTarget}}));
    EXPECT_EQ(text(compiled.barriers[1]),
              expected({{1, {kColorOut, kColorW, kColorLayout}, {kVsFs, kSampled, kReadOnly}},
                        {0, kNothing, kColorTarget}}));
    EXPECT_TRUE(compiled.finalBarriers.empty());
    EXPECT_EQ(compiled.finalStates[0], kColorTarget);
    EXPECT_EQ(compiled.finalStates[1], (ResourceState{kVsFs, kSampled, kReadOnly}));
}

TEST(GraphBarriers, StorageBufferReadAfterWrite) {
    RenderGraph graph;
    const BufferId out = graph.importBuffer("out", {.size = 256}, {});  // 0
    BufferId data;                                                      // 1
    addPass(graph, "produce", PassType::Compute, [&](PassBuilder& b) {
        data = b.write(b.createBuffer("data", {.size = 256}), Usage::StorageWrite, WriteMode::Discard);
    });
    addPass(graph, "consume", PassType::Compute, [&](PassBuilder& b) {
        b.read(data, Usage::StorageRead);
        b.write(out, Usage::StorageWrite, WriteMode::Discard);
    });
    const CompiledGraph& compiled = graph.compile();
    EXPECT_TRUE(compiled.barriers[0].empty());  // nothing happened to either buffer before
    EXPECT_EQ(text(compiled.barriers[1]),
              expected({{1, {kCompute, kStorageW, kUndefined}, {kCompute, kStorageR, kUndefined}}}));
}

TEST(GraphBarriers, WriteAfterReadWaitsForTheReaders) {
    RenderGraph graph;
    const TextureId image = graph.importTexture("image", kColor, {kCompute, kStorageR, kGeneral});  // 0
    const BufferId stats = graph.importBuffer("stats", {.size = 64}, {});                          // 1
    addPass(graph, "inspect", PassType::Compute, [&](PassBuilder& b) {
        b.read(image, Usage::StorageRead);
        b.write(stats, Usage::StorageWrite);
    });
    addPass(graph, "overwrite", PassType::Compute,
            [&](PassBuilder& b) { b.write(image, Usage::StorageWrite, WriteMode::Discard); });
    const CompiledGraph& compiled = graph.compile();
    // Reading an import whose initial state is a read needs no barrier.
    EXPECT_TRUE(compiled.barriers[0].empty());
    EXPECT_EQ(text(compiled.barriers[1]),
              expected({{0, {kCompute, kNoAccess, kGeneral}, {kCompute, kStorageW, kGeneral}}}));
}

TEST(GraphBarriers, WriteAfterWrite) {
    RenderGraph graph;
    const TextureId acc = graph.importTexture("acc", kColor, {});           // 0
    const BufferId counts = graph.importBuffer("counts", {.size = 64}, {});  // 1
    TextureId cleared;
    BufferId filled;
    addPass(graph, "clear", PassType::Transfer,
            [&](PassBuilder& b) { cleared = b.write(acc, Usage::TransferDst, WriteMode::Discard); });
    addPass(graph, "fill", PassType::Transfer,
            [&](PassBuilder& b) { filled = b.write(counts, Usage::TransferDst, WriteMode::Discard); });
    addPass(graph, "add", PassType::Compute, [&](PassBuilder& b) {
        b.write(cleared, Usage::StorageReadWrite);
        b.write(filled, Usage::StorageReadWrite);
    });
    const CompiledGraph& compiled = graph.compile();
    EXPECT_EQ(text(compiled.barriers[0]),
              expected({{0, kNothing, {kTransfer, kTransferW, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL}}}));
    EXPECT_TRUE(compiled.barriers[1].empty());
    EXPECT_EQ(text(compiled.barriers[2]),
              expected({{0, {kTransfer, kTransferW, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL},
                         {kCompute, kStorageR | kStorageW, kGeneral}},
                        {1, {kTransfer, kTransferW, kUndefined}, {kCompute, kStorageR | kStorageW, kUndefined}}}));
    EXPECT_EQ(compiled.finalStates[0], (ResourceState{kCompute, kStorageR | kStorageW, kGeneral}));
}

TEST(GraphBarriers, RepeatedReadersGetOneBarrierPerNewStage) {
    RenderGraph graph;
    TextureId t;  // 0
    addPass(graph, "draw", PassType::Graphics,
            [&](PassBuilder& b) { t = b.writeColor(b.createTexture("t", kColor), VkClearColorValue{}); });
    auto reader = [&](const std::string& name, PassType type, VkPipelineStageFlags2 stages) {
        addPass(graph, name, type, [&](PassBuilder& b) {
            b.read(t, Usage::Sampled, stages);
            b.sideEffect();
        });
    };
    reader("a", PassType::Graphics, 0);
    reader("b", PassType::Graphics, 0);
    reader("c", PassType::Compute, 0);
    reader("d", PassType::Compute, 0);
    reader("e", PassType::Graphics, kFs);
    const CompiledGraph& compiled = graph.compile();
    ASSERT_EQ(compiled.order, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(text(compiled.barriers[1]),
              expected({{0, {kColorOut, kColorW, kColorLayout}, {kVsFs, kSampled, kReadOnly}}}));
    EXPECT_TRUE(compiled.barriers[2].empty());
    // The transition counts as the last write: compute waits for it, with nothing more to flush.
    EXPECT_EQ(text(compiled.barriers[3]),
              expected({{0, {kVsFs, kNoAccess, kReadOnly}, {kCompute, kSampled, kReadOnly}}}));
    EXPECT_TRUE(compiled.barriers[4].empty());
    EXPECT_TRUE(compiled.barriers[5].empty());
}

TEST(GraphBarriers, DepthWriteThenReadInTwoWaysMergesIntoOneBarrier) {
    RenderGraph graph;
    TextureId depth;  // 0
    addPass(graph, "prepass", PassType::Graphics, [&](PassBuilder& b) {
        depth = b.writeDepth(b.createTexture("depth", {.width = 64, .height = 64, .format = VK_FORMAT_D32_SFLOAT}),
                             1.0f);
    });
    addPass(graph, "shade", PassType::Graphics, [&](PassBuilder& b) {
        b.read(depth, Usage::DepthRead);
        b.read(depth, Usage::Sampled);
        b.sideEffect();
    });
    const CompiledGraph& compiled = graph.compile();
    constexpr VkAccessFlags2 kDepthRW =
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    EXPECT_EQ(text(compiled.barriers[0]),
              expected({{0, kNothing, {kDepthTests, kDepthRW, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL}}}));
    EXPECT_EQ(text(compiled.barriers[1]),
              expected({{0,
                         {kDepthTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                          VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL},
                         {kDepthTests | kVsFs, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | kSampled,
                          VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL}}}));
}

TEST(GraphBarriers, DifferentLayoutsInOnePassFallBackToGeneral) {
    RenderGraph graph;
    TextureId t;  // 0
    addPass(graph, "write", PassType::Compute,
            [&](PassBuilder& b) { t = b.write(b.createTexture("t", kColor), Usage::StorageWrite); });
    addPass(graph, "read", PassType::Compute, [&](PassBuilder& b) {
        b.read(t, Usage::Sampled);
        b.read(t, Usage::StorageRead);
        b.sideEffect();
    });
    const CompiledGraph& compiled = graph.compile();
    EXPECT_EQ(text(compiled.barriers[0]), expected({{0, kNothing, {kCompute, kStorageW, kGeneral}}}));
    EXPECT_EQ(text(compiled.barriers[1]),
              expected({{0, {kCompute, kStorageW, kGeneral}, {kCompute, kSampled | kStorageR, kGeneral}}}));
}

TEST(GraphBarriers, ImportedInitialAndFinalStates) {
    RenderGraph graph;
    const ResourceState sampledInFs{kFs, kSampled, kReadOnly};
    const ResourceState storageWritten{kCompute, kStorageW, kGeneral};
    const ResourceState present{kNoStage, kNoAccess, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
    const TextureId env = graph.importTexture("env", kColor, sampledInFs, sampledInFs);        // 0
    const TextureId target = graph.importTexture("target", kColor, {}, present);               // 1
    const TextureId hist = graph.importTexture("hist", kColor, storageWritten, storageWritten);  // 2
    graph.importTexture("idle", kColor, storageWritten, sampledInFs);                          // 3
    graph.importTexture("same", kColor, storageWritten, storageWritten);                       // 4
    addPass(graph, "sky", PassType::Graphics, [&](PassBuilder& b) {
        b.read(env, Usage::Sampled);
        b.read(hist, Usage::Sampled);
        b.writeColor(target, VkClearColorValue{});
    });
    const CompiledGraph& compiled = graph.compile();
    // env: read-only before and in the graph, same layout: no barrier.
    EXPECT_EQ(text(compiled.barriers[0]),
              expected({{2, storageWritten, {kVsFs, kSampled, kReadOnly}}, {1, kNothing, kColorTarget}}));
    EXPECT_EQ(text(compiled.finalBarriers),
              expected({{1, {kColorOut, kColorW, kColorLayout}, present},
                        {2, {kVsFs, kNoAccess, kReadOnly}, storageWritten},
                        {3, storageWritten, sampledInFs}}));
    EXPECT_EQ(compiled.finalStates[0], sampledInFs);
    EXPECT_EQ(compiled.finalStates[1], present);
    EXPECT_EQ(compiled.finalStates[2], storageWritten);
    EXPECT_EQ(compiled.finalStates[3], sampledInFs);
    EXPECT_EQ(compiled.finalStates[4], storageWritten);
}

TEST(GraphBarriers, TextureTakingOverMemoryWaitsForThePreviousOwner) {
    // p0 → t0 → p1 → t1 → p2 → t2 → p3 → out: t2 reuses t0's bytes.
    RenderGraph graph;
    const TextureId out = graph.importTexture("out", kColor, {});  // 0
    TextureId previous;                                            // t0..t2 = 1..3
    for (int i = 0; i <= 3; ++i) {
        addPass(graph, indexed("p", i), PassType::Graphics, [&](PassBuilder& b) {
            if (previous.valid()) b.read(previous, Usage::Sampled);
            previous = b.writeColor(i < 3 ? b.createTexture(indexed("t", i), kColor) : out,
                                    VkClearColorValue{});
        });
    }
    const CompiledGraph& compiled = graph.compile();
    ASSERT_EQ(compiled.placements[3].offset, compiled.placements[1].offset);
    EXPECT_EQ(text(compiled.barriers[0]), expected({{1, kNothing, kColorTarget}}));
    EXPECT_EQ(text(compiled.barriers[2]),
              expected({{2, {kColorOut, kColorW, kColorLayout}, {kVsFs, kSampled, kReadOnly}},
                        {3, {kVsFs, kNoAccess, kUndefined}, kColorTarget, 1}}));
}

TEST(GraphBarriers, BufferTakingOverMemoryGetsABarrierToo) {
    auto build = [](RenderGraph& graph) {
        const BufferId out = graph.importBuffer("out", {.size = 4096}, {});  // 0
        BufferId previous;                                                  // b0..b2 = 1..3
        for (int i = 0; i <= 3; ++i) {
            addPass(graph, indexed("p", i), PassType::Compute, [&](PassBuilder& b) {
                if (previous.valid()) b.read(previous, Usage::StorageRead);
                previous = b.write(i < 3 ? b.createBuffer(indexed("b", i), {.size = 4096}) : out,
                                   Usage::StorageWrite, WriteMode::Discard);
            });
        }
    };
    const Barrier raw{2, {kCompute, kStorageW, kUndefined}, {kCompute, kStorageR, kUndefined}};
    RenderGraph aliased;
    build(aliased);
    EXPECT_EQ(text(aliased.compile().barriers[2]),
              expected({raw, {3, {kCompute, kStorageW, kUndefined}, {kCompute, kStorageW, kUndefined}, 1}}));
    RenderGraph separate;
    build(separate);
    EXPECT_EQ(text(separate.compile({.aliasing = false}).barriers[2]), expected({raw}));
}

}  // namespace
}  // namespace candela::graph
