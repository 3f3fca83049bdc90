// compileGraph as a whole: the named steps, empty graphs, and a synthetic graph of realistic size.

#include "graph_test_util.h"

#include <gtest/gtest.h>

#include <string>

namespace candela::graph {
namespace {

const std::vector<std::string> kSteps{"validate",  "cull",        "order",    "unread writes",
                                      "lifetimes", "attachments", "aliasing", "barriers"};

TEST(GraphCompile, RunsTheNamedStepsInOrder) {
    RenderGraph graph;
    const TextureDesc desc{.width = 8, .height = 8, .format = VK_FORMAT_R8G8B8A8_UNORM};
    const TextureId target = graph.importTexture("target", desc, {});
    addPass(graph, "clear", PassType::Graphics,
            [&](PassBuilder& b) { b.writeColor(target, VkClearColorValue{}); });
    EXPECT_EQ(graph.compile().steps, kSteps);
}

TEST(GraphCompile, EmptyGraph) {
    const CompiledGraph compiled = compileGraph(GraphDecl{});
    EXPECT_TRUE(compiled.order.empty());
    EXPECT_TRUE(compiled.heaps.empty());
    EXPECT_TRUE(compiled.finalBarriers.empty());
    EXPECT_EQ(compiled.steps, kSteps);
}

// 50 passes: each reads the outputs of the previous pass and of the pass three back, writes a new
// transient; every seventh pass also updates an imported buffer; the last one writes the target.
TEST(GraphCompile, SyntheticFiftyPassGraph) {
    RenderGraph graph;
    const TextureDesc desc{.width = 256, .height = 256, .format = VK_FORMAT_R16G16B16A16_SFLOAT};
    const TextureId target = graph.importTexture("target", desc, {});
    BufferId stats = graph.importBuffer("stats", {.size = 1024}, {});
    std::vector<TextureId> outputs;
    constexpr int kPasses = 50;
    for (int i = 0; i < kPasses; ++i) {
        const PassType type = i % 2 == 0 ? PassType::Compute : PassType::Graphics;
        addPass(graph, indexed("pass", i), type, [&](PassBuilder& b) {
            if (i >= 1) b.read(outputs[i - 1], Usage::Sampled);
            if (i >= 3) b.read(outputs[i - 3], Usage::Sampled);
            if (i % 7 == 0) stats = b.write(stats, Usage::StorageReadWrite);
            TextureId created = b.createTexture(indexed("t", i), desc);
            outputs.push_back(type == PassType::Compute ? b.write(created, Usage::StorageWrite, WriteMode::Discard)
                                                        : b.writeColor(created, VkClearColorValue{}));
            if (i + 1 == kPasses) b.writeColor(target, std::nullopt);
        });
    }
    const CompiledGraph& compiled = graph.compile();
    ASSERT_EQ(compiled.order.size(), static_cast<size_t>(kPasses));
    for (uint32_t i = 0; i < kPasses; ++i) EXPECT_EQ(compiled.order[i], i);
    EXPECT_EQ(compiled.barriers.size(), static_cast<size_t>(kPasses));
    EXPECT_LT(compiled.bytesAllocated, compiled.bytesRequested);
    // A transient read three passes later overlaps at most four others, so memory stays bounded.
    EXPECT_LE(compiled.bytesAllocated, 5 * 256 * 256 * 8u);
}

}  // namespace
}  // namespace candela::graph
