// Step "cull": reference counting from the outputs, disabled passes and their lost-input cascade.

#include "graph_test_util.h"

#include <gtest/gtest.h>

#include <string>

namespace candela::graph {
namespace {

const PassInfo& info(const RenderGraph& graph, const std::string& pass) {
    return graph.compiled().passes.at(*graph.findPass(pass));
}

// lighting → hdr → bloom → bloomed → tonemap → target (imported), plus a debug pass off hdr.
void buildLightingChain(RenderGraph& graph) {
    const TextureId target = graph.importTexture("target", kColor, {});
    TextureId hdr, bloomed;
    addPass(graph, "lighting", PassType::Graphics,
            [&](PassBuilder& b) { hdr = b.writeColor(b.createTexture("hdr", kColor), VkClearColorValue{}); });
    addPass(graph, "bloom", PassType::Compute, [&](PassBuilder& b) {
        b.read(hdr, Usage::Sampled);
        bloomed = b.write(b.createTexture("bloomed", kColor), Usage::StorageWrite, WriteMode::Discard);
    });
    addPass(graph, "debug", PassType::Compute, [&](PassBuilder& b) {
        b.read(hdr, Usage::Sampled);
        b.write(b.createTexture("histogram", kColor), Usage::StorageWrite, WriteMode::Discard);
    });
    addPass(graph, "tonemap", PassType::Graphics, [&](PassBuilder& b) {
        b.read(bloomed, Usage::Sampled);
        b.writeColor(target, std::nullopt);
    });
}

TEST(GraphCull, ChainIsKeptAndDeadBranchCulled) {
    RenderGraph graph;
    buildLightingChain(graph);
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"lighting", "bloom", "tonemap"}));
    EXPECT_EQ(info(graph, "debug").cullReason, CullReason::NoOutput);
    EXPECT_EQ(info(graph, "debug").cullDetail, "contributes to no output");
    EXPECT_EQ(info(graph, "bloom").cullReason, CullReason::None);
    EXPECT_EQ(info(graph, "bloom").cullDetail, "");
}

TEST(GraphCull, DisabledPassCascadesAsLostInput) {
    RenderGraph graph;
    buildLightingChain(graph);
    graph.setPassEnabled("lighting", false);
    graph.compile();
    EXPECT_TRUE(graph.compiled().order.empty());
    EXPECT_EQ(info(graph, "lighting").cullReason, CullReason::Disabled);
    EXPECT_EQ(info(graph, "lighting").cullDetail, "disabled");
    EXPECT_EQ(info(graph, "bloom").cullReason, CullReason::LostInput);
    EXPECT_EQ(info(graph, "bloom").cullDetail, "input 'hdr' lost: its producer 'lighting' is disabled");
    EXPECT_EQ(info(graph, "debug").cullReason, CullReason::LostInput);
    EXPECT_EQ(info(graph, "tonemap").cullReason, CullReason::LostInput);
    EXPECT_EQ(info(graph, "tonemap").cullDetail,
              "input 'bloomed' lost: its producer 'bloom' was culled (lost input)");
    // Each lost pass names the producer it lacked, so the cascade can be followed back to its root.
    EXPECT_EQ(info(graph, "tonemap").lostProducer, *graph.findPass("bloom"));
    EXPECT_EQ(info(graph, "bloom").lostProducer, *graph.findPass("lighting"));
    EXPECT_EQ(info(graph, "lighting").lostProducer, kInvalidIndex);

    graph.setPassEnabled("lighting", true);
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"lighting", "bloom", "tonemap"}));
}

TEST(GraphCull, CascadeFollowsDataNotDeclarationOrder) {
    // Consumers declared before their producers: availability must still flow producer → consumer.
    GraphDecl decl;
    decl.resources = {{.name = "target", .imported = true}, {.name = "hdr"}, {.name = "bloomed"}};
    decl.passes = {
        {.name = "tonemap",
         .reads = {{.resource = 2, .version = 1, .usage = Usage::Sampled}},
         .writes = {{.resource = 0, .version = 1, .usage = Usage::ColorAttachment}}},
        {.name = "bloom",
         .reads = {{.resource = 1, .version = 1, .usage = Usage::Sampled}},
         .writes = {{.resource = 2, .version = 1, .usage = Usage::StorageWrite, .mode = WriteMode::Discard}}},
        {.name = "lighting",
         .enabled = false,
         .writes = {{.resource = 1, .version = 1, .usage = Usage::ColorAttachment, .mode = WriteMode::Discard}}},
    };
    const CompiledGraph compiled = compileGraph(decl);
    EXPECT_TRUE(compiled.order.empty());
    EXPECT_EQ(compiled.passes[2].cullReason, CullReason::Disabled);
    EXPECT_EQ(compiled.passes[1].cullReason, CullReason::LostInput);
    EXPECT_EQ(compiled.passes[0].cullReason, CullReason::LostInput);
    EXPECT_EQ(compiled.passes[0].cullDetail, "input 'bloomed' lost: its producer 'bloom' was culled (lost input)");
}

TEST(GraphCull, PreservingWriteLosesInputButDiscardingWriteDoesNot) {
    RenderGraph graph;
    const TextureId target = graph.importTexture("target", kColor, {});
    const TextureId other = graph.importTexture("other", kColor, {});
    TextureId cleared, otherCleared;
    addPass(graph, "clear", PassType::Transfer, [&](PassBuilder& b) {
        cleared = b.write(target, Usage::TransferDst, WriteMode::Discard);
        otherCleared = b.write(other, Usage::TransferDst, WriteMode::Discard);
    });
    addPass(graph, "overlay", PassType::Graphics, [&](PassBuilder& b) { b.writeColor(cleared, std::nullopt); });
    addPass(graph, "fill", PassType::Graphics,
            [&](PassBuilder& b) { b.writeColor(otherCleared, VkClearColorValue{}); });
    graph.setPassEnabled("clear", false);
    graph.compile();
    EXPECT_EQ(info(graph, "overlay").cullReason, CullReason::LostInput);
    EXPECT_EQ(info(graph, "overlay").cullDetail, "input 'target' lost: its producer 'clear' is disabled");
    EXPECT_EQ(info(graph, "fill").cullReason, CullReason::None);
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"fill"}));
}

TEST(GraphCull, ChainContributingToNothingIsCulled) {
    RenderGraph graph;
    TextureId a;
    addPass(graph, "first", PassType::Compute,
            [&](PassBuilder& b) { a = b.write(b.createTexture("a", kColor), Usage::StorageWrite); });
    addPass(graph, "second", PassType::Compute, [&](PassBuilder& b) {
        b.read(a, Usage::Sampled);
        b.write(b.createTexture("b", kColor), Usage::StorageWrite);
    });
    graph.compile();
    EXPECT_TRUE(graph.compiled().order.empty());
    EXPECT_EQ(info(graph, "first").cullReason, CullReason::NoOutput);
    EXPECT_EQ(info(graph, "second").cullReason, CullReason::NoOutput);
    EXPECT_FALSE(graph.compiled().lifetimes[0].used());
    EXPECT_TRUE(graph.compiled().heaps.empty());
}

TEST(GraphCull, SideEffectKeepsPassAndItsInputs) {
    RenderGraph graph;
    TextureId a;
    addPass(graph, "render", PassType::Graphics,
            [&](PassBuilder& b) { a = b.writeColor(b.createTexture("a", kColor), VkClearColorValue{}); });
    addPass(graph, "unused", PassType::Graphics,
            [&](PassBuilder& b) { b.writeColor(b.createTexture("b", kColor), VkClearColorValue{}); });
    addPass(graph, "readback", PassType::Transfer, [&](PassBuilder& b) {
        b.read(a, Usage::TransferSrc);
        b.sideEffect();
    });
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"render", "readback"}));
    EXPECT_EQ(info(graph, "unused").cullReason, CullReason::NoOutput);
}

TEST(GraphCull, ImportedOutputKeepsItsWriter) {
    RenderGraph graph;
    const TextureId history = graph.importTexture("history", kColor, {});
    addPass(graph, "accumulate", PassType::Compute,
            [&](PassBuilder& b) { b.write(history, Usage::StorageReadWrite); });
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"accumulate"}));
}

TEST(GraphCull, ExportedTransientKeepsWritersAndLivesToTheEnd) {
    RenderGraph graph;
    const TextureId target = graph.importTexture("target", kColor, {});
    TextureId shadow;
    addPass(graph, "shadow", PassType::Graphics, [&](PassBuilder& b) {
        const TextureDesc desc{.width = 64, .height = 64, .format = VK_FORMAT_D32_SFLOAT};
        shadow = b.writeDepth(b.createTexture("shadowMap", desc), 1.0f);
    });
    addPass(graph, "main", PassType::Graphics,
            [&](PassBuilder& b) { b.writeColor(target, VkClearColorValue{}); });
    graph.exportTexture(shadow);
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"shadow", "main"}));
    const Lifetime& lifetime = graph.compiled().lifetimes[*graph.findResource("shadowMap")];
    EXPECT_EQ(lifetime.first, 0u);
    EXPECT_EQ(lifetime.last, 1u);
}

TEST(GraphCull, WriteAfterReadIsNotADependency) {
    // A disabled reader of the old contents must not take the next writer down with it.
    RenderGraph graph;
    const TextureId image = graph.importTexture("image", kColor, {});
    addPass(graph, "inspect", PassType::Compute, [&](PassBuilder& b) {
        b.read(image, Usage::StorageRead);
        b.sideEffect();
    });
    addPass(graph, "overwrite", PassType::Compute,
            [&](PassBuilder& b) { b.write(image, Usage::StorageWrite, WriteMode::Discard); });
    graph.setPassEnabled("inspect", false);
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"overwrite"}));
    EXPECT_EQ(info(graph, "overwrite").cullReason, CullReason::None);
}

}  // namespace
}  // namespace candela::graph

namespace candela::graph {
namespace {

// lighting → hdr v1 → sky (draws over hdr) → v2 → haze (draws over) → v3 → tonemap → target v1
// → ui (draws over target, clear if lost) → target v2.
struct OverlayChain {
    TextureId target;
    explicit OverlayChain(RenderGraph& graph) {
        target = graph.importTexture("target", kColor, {});
        TextureId hdr;
        addPass(graph, "lighting", PassType::Graphics,
                [&](PassBuilder& b) { hdr = b.writeColor(b.createTexture("hdr", kColor), VkClearColorValue{}); });
        addPass(graph, "sky", PassType::Graphics, [&](PassBuilder& b) { hdr = b.writeColor(hdr, std::nullopt); });
        addPass(graph, "haze", PassType::Graphics, [&](PassBuilder& b) { hdr = b.writeColor(hdr, std::nullopt); });
        addPass(graph, "tonemap", PassType::Graphics, [&](PassBuilder& b) {
            b.read(hdr, Usage::Sampled);
            target = b.writeColor(target, VkClearColorValue{});
        });
        addPass(graph, "ui", PassType::Graphics,
                [&](PassBuilder& b) { b.drawOver(target, VkClearColorValue{{0.0f, 0.0f, 0.0f, 1.0f}}); });
    }
};

TEST(GraphCull, DisabledOverlayIsBypassed) {
    RenderGraph graph;
    OverlayChain chain(graph);
    graph.setPassEnabled("sky", false);
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"lighting", "haze", "tonemap", "ui"}));
    EXPECT_EQ(info(graph, "sky").cullReason, CullReason::Disabled);
    EXPECT_TRUE(info(graph, "sky").bypassed);
    EXPECT_EQ(info(graph, "sky").cullDetail, "disabled (bypassed: later passes read what it would have drawn over)");
    EXPECT_TRUE(info(graph, "ui").clearedLostInputs.empty());
}

TEST(GraphCull, BypassFollowsAChainOfOverlays) {
    RenderGraph graph;
    OverlayChain chain(graph);
    graph.setPassEnabled("sky", false);
    graph.setPassEnabled("haze", false);
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"lighting", "tonemap", "ui"}));
}

TEST(GraphCull, BypassDoesNotHideALostBase) {
    RenderGraph graph;
    OverlayChain chain(graph);
    graph.setPassEnabled("lighting", false);  // a discarding write: not bypassable
    graph.setPassEnabled("sky", false);
    graph.compile();
    EXPECT_FALSE(info(graph, "lighting").bypassed);
    EXPECT_EQ(info(graph, "haze").cullReason, CullReason::LostInput);
    EXPECT_EQ(info(graph, "haze").cullDetail, "input 'hdr' lost: its producer 'lighting' is disabled");
    EXPECT_EQ(info(graph, "tonemap").cullReason, CullReason::LostInput);
    // The UI stays, on a cleared target.
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"ui"}));
    EXPECT_EQ(info(graph, "ui").clearedLostInputs, (std::vector<uint32_t>{*graph.findResource("target")}));
}

TEST(GraphCull, DrawOverSurvivesItsProducerBeingSwitchedOff) {
    RenderGraph graph;
    OverlayChain chain(graph);
    graph.setPassEnabled("tonemap", false);
    graph.compile();
    EXPECT_EQ(orderNames(graph), (std::vector<std::string>{"ui"}));
    EXPECT_EQ(info(graph, "ui").cullReason, CullReason::None);
    EXPECT_EQ(info(graph, "ui").clearedLostInputs.size(), 1u);
    // What fed the tonemap contributes to nothing now.
    EXPECT_EQ(info(graph, "lighting").cullReason, CullReason::NoOutput);
    EXPECT_EQ(info(graph, "sky").cullReason, CullReason::NoOutput);
}

}  // namespace
}  // namespace candela::graph
