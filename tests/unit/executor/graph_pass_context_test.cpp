// PassContext: a pass's execute callback resolves only what its setup declared, in the layout the
// barrier planner put it in. No GPU: the imported resources are bound to made-up handles, and
// nothing here records a command.

#include "executor/graph_executor.h"
#include "graph_test_util.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace candela::graph::graph_pass_context_test {
namespace {

template <class Handle>
Handle fake(uintptr_t value) {
    return reinterpret_cast<Handle>(value);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const TextureDesc kCube{.width = 16, .height = 16, .mipLevels = 3, .arrayLayers = 6,
                        .format = VK_FORMAT_R16G16B16A16_SFLOAT, .cube = true};

struct Imported {
    RenderGraph graph;
    ImportBindings imports;
    TextureId maps, other;
    BufferId sh;
    Imported() {
        maps = graph.importTexture("maps", kCube, {});
        other = graph.importTexture("other", kColor, {});
        sh = graph.importBuffer("sh", {.size = 144}, {});
        imports.bind(maps, fake<VkImage>(0x10), fake<VkImageView>(0x11),
                     {fake<VkImageView>(0x20), fake<VkImageView>(0x21), fake<VkImageView>(0x22)});
        imports.bind(other, fake<VkImage>(0x30), fake<VkImageView>(0x31));
        imports.bind(sh, fake<VkBuffer>(0x40));
    }
    PassContext context(std::string_view pass) { return PassContext(graph, *graph.findPass(pass), {.imports = &imports}); }
};

TEST(GraphPassContext, ResolvesWhatThePassDeclared) {
    Imported g;
    addPass(g.graph, "shade", PassType::Graphics, [&](PassBuilder& b) {
        b.sample(g.maps);
        b.read(g.sh, Usage::Uniform);
        b.sideEffect();
    });
    g.graph.compile();
    const PassContext ctx = g.context("shade");
    EXPECT_EQ(ctx.image(g.maps), fake<VkImage>(0x10));
    EXPECT_EQ(ctx.view(g.maps), fake<VkImageView>(0x11));
    EXPECT_EQ(ctx.mipView(g.maps, 2), fake<VkImageView>(0x22));
    EXPECT_EQ(ctx.buffer(g.sh), fake<VkBuffer>(0x40));
    EXPECT_EQ(ctx.desc(g.maps).mipLevels, 3u);
    EXPECT_EQ(ctx.layout(g.maps), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

TEST(GraphPassContext, RefusesAResourceThePassDidNotDeclare) {
    Imported g;
    addPass(g.graph, "skybox", PassType::Graphics, [&](PassBuilder& b) {
        b.sample(g.maps);
        b.sideEffect();
    });
    g.graph.compile();
    const PassContext ctx = g.context("skybox");
    // Bound and valid, but not declared by this pass: it would get no barrier.
    const std::string message = graphError([&] { ctx.view(g.other); });
    EXPECT_TRUE(contains(message, "pass 'skybox'")) << message;
    EXPECT_TRUE(contains(message, "'other' v0")) << message;
    EXPECT_TRUE(contains(message, "it declared: reads 'maps' v0 (Sampled)")) << message;
    EXPECT_TRUE(contains(graphError([&] { ctx.image(g.other); }), "'other'"));
    EXPECT_TRUE(contains(graphError([&] { ctx.buffer(g.sh); }), "'sh'"));
    EXPECT_TRUE(contains(graphError([&] { ctx.layout(g.other); }), "'other'"));
    EXPECT_TRUE(contains(graphError([&] { ctx.desc(g.sh); }), "'sh'"));
    EXPECT_TRUE(contains(graphError([&] { ctx.view(TextureId{}); }), "an invalid texture handle"));
}

TEST(GraphPassContext, RefusesAnotherVersionThanTheDeclaredOne) {
    Imported g;
    TextureId written;
    addPass(g.graph, "filter", PassType::Compute,
            [&](PassBuilder& b) { written = b.write(g.maps, Usage::StorageWrite, WriteMode::Discard); });
    g.graph.compile();
    const PassContext ctx = g.context("filter");
    EXPECT_EQ(ctx.mipView(written, 0), fake<VkImageView>(0x20));
    // The version the write consumed is not what the pass declared it uses.
    const std::string message = graphError([&] { ctx.view(g.maps); });
    EXPECT_TRUE(contains(message, "'maps' v0")) << message;
    EXPECT_TRUE(contains(message, "writes 'maps' v1 (StorageWrite)")) << message;
}

TEST(GraphPassContext, LayoutIsTheMergedLayoutOfThePassAccesses) {
    Imported g;
    TextureId written;
    addPass(g.graph, "copy", PassType::Compute, [&](PassBuilder& b) {
        b.sample(g.other);
        written = b.write(g.maps, Usage::StorageWrite, WriteMode::Discard);
    });
    TextureId both;
    addPass(g.graph, "both", PassType::Compute, [&](PassBuilder& b) {
        b.read(written, Usage::Sampled);
        both = b.write(written, Usage::StorageWrite);
    });
    g.graph.compile();
    EXPECT_EQ(g.context("copy").layout(g.other), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(g.context("copy").layout(written), VK_IMAGE_LAYOUT_GENERAL);
    // Sampled and storage in one pass: one layout serves both.
    EXPECT_EQ(g.context("both").layout(written), VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(g.context("both").layout(both), VK_IMAGE_LAYOUT_GENERAL);
    // The planner transitions into exactly that layout before the pass.
    const CompiledGraph& compiled = g.graph.compiled();
    for (size_t i = 0; i < compiled.order.size(); ++i) {
        if (g.graph.declaration().passes[compiled.order[i]].name != "both") continue;
        for (const Barrier& barrier : compiled.barriers[i]) {
            if (barrier.resource == written.index) {
                EXPECT_EQ(barrier.dst.layout, VK_IMAGE_LAYOUT_GENERAL);
            }
        }
    }
}

TEST(GraphPassContext, MipViewsMustExist) {
    Imported g;
    addPass(g.graph, "p", PassType::Compute, [&](PassBuilder& b) {
        b.sample(g.maps);
        b.sample(g.other);
        b.sideEffect();
    });
    g.graph.compile();
    const PassContext ctx = g.context("p");
    EXPECT_TRUE(contains(graphError([&] { ctx.mipView(g.maps, 3); }), "mip 3 of 'maps', which has 3 mips"));
    EXPECT_TRUE(contains(graphError([&] { ctx.mipView(g.other, 0); }), "no view of it was bound"));
}

}  // namespace
}  // namespace candela::graph::graph_pass_context_test
