// RenderGraph / PassBuilder: what the setup phase records, and how it rejects misuse.

#include "graph_test_util.h"

#include <gtest/gtest.h>

#include <string>

namespace candela::graph {
namespace {

TEST(GraphBuilder, WritesIncrementVersionsAndReturnNewHandles) {
    RenderGraph graph;
    TextureId created, first, second, readBack;
    addPass(graph, "p", PassType::Compute, [&](PassBuilder& b) {
        created = b.createTexture("t", kColor);
        first = b.write(created, Usage::StorageWrite, WriteMode::Discard);
        second = b.write(first, Usage::StorageReadWrite);
    });
    addPass(graph, "q", PassType::Compute, [&](PassBuilder& b) { readBack = b.read(second, Usage::Sampled); });

    EXPECT_EQ(created, (TextureId{0, 0}));
    EXPECT_EQ(first, (TextureId{0, 1}));
    EXPECT_EQ(second, (TextureId{0, 2}));
    EXPECT_EQ(readBack, second);
    const GraphDecl& decl = graph.declaration();
    ASSERT_EQ(decl.resources.size(), 1u);
    EXPECT_EQ(decl.resources[0].versionCount, 3u);
    EXPECT_FALSE(decl.resources[0].imported);
    ASSERT_EQ(decl.passes[0].writes.size(), 2u);
    EXPECT_EQ(decl.passes[0].writes[0].version, 1u);
    EXPECT_EQ(decl.passes[0].writes[0].mode, WriteMode::Discard);
    EXPECT_EQ(decl.passes[0].writes[1].version, 2u);
    EXPECT_EQ(decl.passes[0].writes[1].mode, WriteMode::Preserve);
    ASSERT_EQ(decl.passes[1].reads.size(), 1u);
    EXPECT_EQ(decl.passes[1].reads[0].version, 2u);
    EXPECT_EQ(decl.passes[1].reads[0].usage, Usage::Sampled);
}

TEST(GraphBuilder, AttachmentWritesClearOrPreserve) {
    RenderGraph graph;
    addPass(graph, "draw", PassType::Graphics, [&](PassBuilder& b) {
        TextureId color = b.createTexture("color", kColor);
        TextureId depth = b.createTexture("depth", {.width = 64, .height = 64, .format = VK_FORMAT_D32_SFLOAT});
        color = b.writeColor(color, VkClearColorValue{{0.25f, 0.5f, 0.75f, 1.0f}});
        color = b.writeColor(color, std::nullopt);
        depth = b.writeDepth(depth, 1.0f);
        b.writeDepth(depth, std::nullopt);
    });
    const std::vector<AccessDecl>& writes = graph.declaration().passes[0].writes;
    ASSERT_EQ(writes.size(), 4u);
    EXPECT_EQ(writes[0].usage, Usage::ColorAttachment);
    EXPECT_EQ(writes[0].mode, WriteMode::Discard);
    ASSERT_TRUE(writes[0].clear.has_value());
    EXPECT_EQ(writes[0].clear->color.float32[1], 0.5f);
    EXPECT_EQ(writes[1].mode, WriteMode::Preserve);
    EXPECT_FALSE(writes[1].clear.has_value());
    EXPECT_EQ(writes[1].version, 2u);
    EXPECT_EQ(writes[2].usage, Usage::DepthAttachment);
    EXPECT_EQ(writes[2].mode, WriteMode::Discard);
    ASSERT_TRUE(writes[2].clear.has_value());
    EXPECT_EQ(writes[2].clear->depthStencil.depth, 1.0f);
    EXPECT_EQ(writes[3].mode, WriteMode::Preserve);
    EXPECT_FALSE(writes[3].clear.has_value());
}

TEST(GraphBuilder, InvalidHandlesNameThePassAndResource) {
    RenderGraph graph;
    const BufferId buffer = graph.importBuffer("params", {.size = 256}, {});
    TextureId texture;
    addPass(graph, "make", PassType::Compute, [&](PassBuilder& b) { texture = b.createTexture("hdr", kColor); });

    const std::string none = graphError([&] {
        addPass(graph, "tonemap", PassType::Graphics,
                [&](PassBuilder& b) { b.read(TextureId{}, Usage::Sampled); });
    });
    EXPECT_NE(none.find("'tonemap'"), std::string::npos) << none;
    EXPECT_NE(none.find("invalid texture handle"), std::string::npos) << none;

    const std::string kind = graphError([&] {
        addPass(graph, "bloom", PassType::Compute,
                [&](PassBuilder& b) { b.read(BufferId{texture.index, 0}, Usage::StorageRead); });
    });
    EXPECT_NE(kind.find("'bloom'"), std::string::npos) << kind;
    EXPECT_NE(kind.find("'hdr'"), std::string::npos) << kind;

    const std::string version = graphError([&] {
        addPass(graph, "blur", PassType::Compute,
                [&](PassBuilder& b) { b.write(BufferId{buffer.index, 3}, Usage::StorageWrite); });
    });
    EXPECT_NE(version.find("'blur'"), std::string::npos) << version;
    EXPECT_NE(version.find("'params'"), std::string::npos) << version;
    EXPECT_NE(version.find("version 3"), std::string::npos) << version;

    const std::string usage = graphError([&] {
        addPass(graph, "mix", PassType::Graphics,
                [&](PassBuilder& b) { b.read(texture, Usage::ColorAttachment); });
    });
    EXPECT_NE(usage.find("'mix'"), std::string::npos) << usage;
    EXPECT_NE(usage.find("'hdr'"), std::string::npos) << usage;

    EXPECT_THROW(graph.exportTexture(TextureId{42, 0}), GraphError);
}

TEST(GraphBuilder, SetPassEnabledRejectsUnknownNames) {
    RenderGraph graph;
    addPass(graph, "ssao", PassType::Compute, [](PassBuilder& b) { b.sideEffect(); });
    graph.setPassEnabled("ssao", false);
    EXPECT_FALSE(graph.declaration().passes[0].enabled);
    EXPECT_TRUE(graph.declaration().passes[0].sideEffect);
    const std::string message = graphError([&] { graph.setPassEnabled("ssoa", false); });
    EXPECT_NE(message.find("'ssoa'"), std::string::npos) << message;
}

TEST(GraphBuilder, WritingAnOldVersionIsRejectedAtCompile) {
    RenderGraph graph;
    const TextureId target = graph.importTexture("target", kColor, {});
    addPass(graph, "first", PassType::Graphics, [&](PassBuilder& b) { b.writeColor(target, std::nullopt); });
    // The builder accepts a second write of version 0; it produces version 1 again.
    addPass(graph, "second", PassType::Graphics, [&](PassBuilder& b) {
        EXPECT_EQ(b.writeColor(target, std::nullopt), (TextureId{target.index, 1}));
    });
    EXPECT_EQ(graph.declaration().resources[0].versionCount, 2u);
    const std::string message = graphError([&] { graph.compile(); });
    EXPECT_EQ(message, "passes 'first' and 'second' both write 'target' (version 1)");
    EXPECT_FALSE(graph.isCompiled());
}

TEST(GraphBuilder, TransientsCreatedOutsidePasses) {
    RenderGraph graph;
    const TextureId ldr = graph.createTexture("ldr", kColor);
    const BufferId histogram = graph.createBuffer("histogram", {.size = 1024});
    EXPECT_EQ(ldr, (TextureId{0, 0}));
    EXPECT_EQ(histogram, (BufferId{1, 0}));
    addPass(graph, "encode", PassType::Graphics, [&](PassBuilder& b) {
        EXPECT_EQ(b.writeColor(ldr, VkClearColorValue{}), (TextureId{0, 1}));
        EXPECT_EQ(b.write(histogram, Usage::TransferDst, WriteMode::Discard), (BufferId{1, 1}));
        b.sideEffect();
    });
    const GraphDecl& decl = graph.declaration();
    EXPECT_EQ(decl.resources[0].kind, ResourceKind::Texture);
    EXPECT_EQ(decl.resources[0].texture.format, VK_FORMAT_R8G8B8A8_UNORM);
    EXPECT_FALSE(decl.resources[0].imported);
    EXPECT_EQ(decl.resources[1].kind, ResourceKind::Buffer);
    EXPECT_EQ(decl.resources[1].buffer.size, 1024u);
    EXPECT_EQ(graph.compile().heaps.size(), 2u);
}

TEST(GraphBuilder, ImportsExportsAndLookups) {
    RenderGraph graph;
    const ResourceState initial{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const ResourceState present{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
    const TextureId env = graph.importTexture("env", kColor, initial);
    const BufferId lights = graph.importBuffer("lights", {.size = 1024}, {}, ResourceState{});
    struct Data {
        TextureId out;
    };
    const Data& data = graph.addPass<Data>(
        "draw", PassType::Graphics,
        [&](PassBuilder& b, Data& d) {
            b.read(env, Usage::Sampled);
            b.read(lights, Usage::Uniform);
            d.out = b.writeColor(b.createTexture("out", kColor), VkClearColorValue{});
        },
        [](const Data&, PassContext&) {});
    graph.exportTexture(data.out, present);

    const GraphDecl& decl = graph.declaration();
    ASSERT_EQ(decl.resources.size(), 3u);
    EXPECT_TRUE(decl.resources[0].imported);
    EXPECT_EQ(decl.resources[0].initialState, initial);
    EXPECT_FALSE(decl.resources[0].finalState.has_value());
    EXPECT_EQ(decl.resources[1].kind, ResourceKind::Buffer);
    EXPECT_TRUE(decl.resources[1].finalState.has_value());
    EXPECT_TRUE(decl.resources[2].exported);
    EXPECT_EQ(decl.resources[2].finalState, present);
    EXPECT_EQ(graph.findPass("draw"), 0u);
    EXPECT_EQ(graph.findPass("nope"), std::nullopt);
    EXPECT_EQ(graph.findResource("out"), 2u);
    EXPECT_EQ(graph.findResource("nope"), std::nullopt);
    EXPECT_TRUE(static_cast<bool>(graph.callback(0)));

    EXPECT_FALSE(graph.isCompiled());
    const CompiledGraph& compiled = graph.compile();
    EXPECT_TRUE(graph.isCompiled());
    EXPECT_EQ(&compiled, &graph.compiled());
    EXPECT_EQ(compiled.order, (std::vector<uint32_t>{0}));
}

TEST(GraphBuilder, SampleReadsInTheShaderThatSamples) {
    RenderGraph graph;
    const TextureId map = graph.importTexture("map", kColor, {});
    const BufferId lights = graph.importBuffer("lights", {.size = 16}, {});
    addPass(graph, "draw", PassType::Graphics, [&](PassBuilder& b) { EXPECT_EQ(b.sample(map), map); });
    addPass(graph, "filter", PassType::Compute, [&](PassBuilder& b) {
        b.sample(map);
        EXPECT_EQ(b.desc(map).width, kColor.width);
        EXPECT_EQ(b.desc(lights).size, 16u);
    });
    const GraphDecl& decl = graph.declaration();
    const AccessDecl& drawn = decl.passes[0].reads[0];
    EXPECT_EQ(drawn.usage, Usage::Sampled);
    EXPECT_EQ(drawn.stageOverride, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    EXPECT_EQ(passAccessState(decl, decl.passes[0], map.index).stages, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    EXPECT_EQ(passAccessState(decl, decl.passes[1], map.index).stages, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    const std::string message = graphError([&] {
        addPass(graph, "bad", PassType::Compute, [&](PassBuilder& b) { b.desc(TextureId{7, 0}); });
    });
    EXPECT_NE(message.find("pass 'bad'"), std::string::npos) << message;
}

TEST(GraphBuilder, TransferPassesOnlyCopy) {
    RenderGraph graph;
    const TextureId map = graph.importTexture("map", kColor, {});
    const std::string message = graphError([&] {
        addPass(graph, "copy", PassType::Transfer, [&](PassBuilder& b) { b.read(map, Usage::Sampled); });
    });
    EXPECT_NE(message.find("pass 'copy' reads 'map' with usage Sampled, but it is a transfer pass"), std::string::npos)
        << message;
    EXPECT_FALSE(graphError([&] {
                     addPass(graph, "clear", PassType::Transfer,
                             [&](PassBuilder& b) { b.write(map, Usage::StorageWrite, WriteMode::Discard); });
                 }).empty());
    addPass(graph, "copy2", PassType::Transfer, [&](PassBuilder& b) {
        b.read(map, Usage::TransferSrc);
        b.sideEffect();
    });
}

}  // namespace
}  // namespace candela::graph
