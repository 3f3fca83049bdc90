// The "attachments" compile step: the load and store operation of every attachment a running pass
// draws into or tests against, and which transients are transient attachments — used by one
// render pass alone, neither loaded nor stored, so that they may live in lazily allocated memory
// (tile memory on tile-based GPUs, Apple's memoryless textures, which drop anything stored). The
// image usage that follows (TRANSIENT_ATTACHMENT) is checked in graph_msaa_test.cpp, the device's
// images in tests/gpu/msaa_test.cpp.
// The frames are shaped like the renderer's (passes/drawing/draw_target.h): "forward" clears a
// colour and a depth and (with MSAA) resolves, "skybox" draws over the colour, tests the depth and
// resolves, "forward_transmission" draws over both and resolves, "tonemap" samples the resolved
// image.

#include "graph_test_util.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace candela::graph::graph_attachments_test {
namespace {

constexpr TextureDesc kHdr{.width = 64, .height = 32, .format = VK_FORMAT_R16G16B16A16_SFLOAT};
constexpr TextureDesc kHdr4{.width = 64, .height = 32, .format = VK_FORMAT_R16G16B16A16_SFLOAT, .samples = 4};
constexpr TextureDesc kDepth4{.width = 64, .height = 32, .format = VK_FORMAT_D32_SFLOAT, .samples = 4};

struct Frame {
    RenderGraph graph;
    TextureId msaa, depth, hdr, output;
    // forward [→ skybox] [→ forward_transmission] → tonemap, at 4 samples.
    explicit Frame(bool skybox, bool transmission = false) {
        output = graph.importTexture("output", kColor, {}, ResourceState{});
        addPass(graph, "forward", PassType::Graphics, [&](PassBuilder& b) {
            msaa = b.writeColor(b.createTexture("hdr_msaa", kHdr4), VkClearColorValue{});
            depth = b.writeDepth(b.createTexture("depth", kDepth4), 0.0f);
            hdr = b.resolve(msaa, b.createTexture("hdr", kHdr));
        });
        if (skybox)
            addPass(graph, "skybox", PassType::Graphics, [&](PassBuilder& b) {
                b.read(depth, Usage::DepthRead);
                msaa = b.writeColor(msaa, std::nullopt);
                hdr = b.resolve(msaa, hdr);
            });
        if (transmission)
            addPass(graph, "forward_transmission", PassType::Graphics, [&](PassBuilder& b) {
                msaa = b.writeColor(msaa, std::nullopt);
                depth = b.writeDepth(depth, std::nullopt);
                hdr = b.resolve(msaa, hdr);
            });
        addPass(graph, "tonemap", PassType::Graphics, [&](PassBuilder& b) {
            b.sample(hdr);
            b.writeColor(output, VkClearColorValue{});
        });
    }
    const CompiledGraph& compiled() const { return graph.compiled(); }
    bool transient(TextureId texture) const { return compiled().transientAttachments[texture.index]; }
    // The planned operations of `pass` on `texture` (fails the test if there are none).
    AttachmentOps ops(std::string_view pass, TextureId texture) const {
        const AttachmentOps* found = compiled().passes[*graph.findPass(pass)].attachmentOps(texture.index);
        EXPECT_NE(found, nullptr) << pass << " has no attachment operations for resource " << texture.index;
        return found ? *found : AttachmentOps{};
    }
};

TEST(GraphAttachments, ForwardThenSkyboxStoresAndLoadsTheMultisampledColourAndDepth) {
    Frame frame(/*skybox=*/true);
    frame.graph.compile();
    EXPECT_EQ(frame.ops("forward", frame.msaa).load, LoadOp::Clear);
    EXPECT_EQ(frame.ops("forward", frame.msaa).store, StoreOp::Store);  // the skybox draws over it
    EXPECT_EQ(frame.ops("forward", frame.depth).load, LoadOp::Clear);
    EXPECT_EQ(frame.ops("forward", frame.depth).store, StoreOp::Store);  // the skybox tests against it
    EXPECT_EQ(frame.ops("skybox", frame.msaa).load, LoadOp::Load);
    EXPECT_EQ(frame.ops("skybox", frame.msaa).store, StoreOp::DontCare);  // resolved, never needed again
    EXPECT_EQ(frame.ops("skybox", frame.depth).load, LoadOp::Load);
    EXPECT_EQ(frame.ops("skybox", frame.depth).store, StoreOp::None);  // tested only
    // Stored by one render pass and loaded by another: tile memory would lose them in between.
    EXPECT_FALSE(frame.transient(frame.msaa));
    EXPECT_FALSE(frame.transient(frame.depth));
    EXPECT_FALSE(frame.transient(frame.hdr));
}

TEST(GraphAttachments, TransmissionLoadsWhatTheSkyboxLeftAndDepthFromTheForwardPass) {
    Frame frame(/*skybox=*/true, /*transmission=*/true);
    frame.graph.compile();
    EXPECT_EQ(frame.ops("skybox", frame.msaa).store, StoreOp::Store);  // now drawn over again
    EXPECT_EQ(frame.ops("forward_transmission", frame.msaa).load, LoadOp::Load);
    EXPECT_EQ(frame.ops("forward_transmission", frame.depth).load, LoadOp::Load);
    EXPECT_EQ(frame.ops("forward_transmission", frame.msaa).store, StoreOp::DontCare);
    EXPECT_EQ(frame.ops("forward_transmission", frame.depth).store, StoreOp::DontCare);
    EXPECT_FALSE(frame.transient(frame.msaa));
    EXPECT_FALSE(frame.transient(frame.depth));
}

TEST(GraphAttachments, ASinglePassMultisampledColourAndDepthAreTransient) {
    Frame frame(/*skybox=*/false);
    frame.graph.compile();
    EXPECT_EQ(frame.ops("forward", frame.msaa).load, LoadOp::Clear);
    EXPECT_EQ(frame.ops("forward", frame.msaa).store, StoreOp::DontCare);  // resolved in the same pass
    EXPECT_EQ(frame.ops("forward", frame.depth).load, LoadOp::Clear);
    EXPECT_EQ(frame.ops("forward", frame.depth).store, StoreOp::DontCare);
    EXPECT_TRUE(frame.transient(frame.msaa));
    EXPECT_TRUE(frame.transient(frame.depth));
    // The resolve target is written to memory and sampled by the tonemap.
    EXPECT_FALSE(frame.transient(frame.hdr));
    EXPECT_FALSE(frame.transient(frame.output));  // imported
}

TEST(GraphAttachments, TheDecisionFollowsWhichPassesRun) {
    // The skybox switched off (bypassed): the forward pass is the only one drawing.
    Frame frame(/*skybox=*/true);
    frame.graph.setPassEnabled("skybox", false);
    frame.graph.compile();
    EXPECT_EQ(frame.ops("forward", frame.msaa).store, StoreOp::DontCare);
    EXPECT_EQ(frame.ops("forward", frame.depth).store, StoreOp::DontCare);
    EXPECT_TRUE(frame.transient(frame.msaa));
    EXPECT_TRUE(frame.transient(frame.depth));
    // Its attachment operations are planned for running passes only.
    EXPECT_TRUE(frame.compiled().passes[*frame.graph.findPass("skybox")].attachments.empty());
    frame.graph.setPassEnabled("skybox", true);
    frame.graph.compile();
    EXPECT_FALSE(frame.transient(frame.msaa));
    EXPECT_FALSE(frame.transient(frame.depth));
}

TEST(GraphAttachments, OneRunningPassIsNotEnoughWhenAnotherDeclaresItOtherwise) {
    // "probe" would sample the colour but does not run: the image (one for every frame of this
    // graph, whichever passes run) still needs SAMPLED usage, which TRANSIENT_ATTACHMENT does not
    // allow beside it.
    RenderGraph graph;
    TextureId color;
    addPass(graph, "draw", PassType::Graphics, [&](PassBuilder& b) {
        color = b.writeColor(b.createTexture("color", kColor), VkClearColorValue{});
        b.sideEffect();
    });
    addPass(graph, "probe", PassType::Graphics, [&](PassBuilder& b) {
        b.sample(color);
        b.sideEffect();
    });
    graph.setPassEnabled("probe", false);
    const CompiledGraph& compiled = graph.compile();
    EXPECT_EQ(compiled.passes[0].attachmentOps(color.index)->store, StoreOp::DontCare);
    EXPECT_FALSE(compiled.transientAttachments[color.index]);
}

TEST(GraphAttachments, AnOutputIsStoredAndNeverTransient) {
    RenderGraph graph;
    TextureId color;
    addPass(graph, "draw", PassType::Graphics,
            [&](PassBuilder& b) { color = b.writeColor(b.createTexture("color", kColor), VkClearColorValue{}); });
    graph.exportTexture(color);
    const CompiledGraph& compiled = graph.compile();
    EXPECT_EQ(compiled.passes[0].attachmentOps(color.index)->store, StoreOp::Store);
    EXPECT_FALSE(compiled.transientAttachments[color.index]);
}

TEST(GraphAttachments, NothingIsLoadedThatNoEarlierPassWrote) {
    // A preserving write of a fresh transient (drawn over without a clear) has nothing to load; a
    // discarding write without a clear value does not care either.
    RenderGraph graph;
    TextureId kept, replaced;
    addPass(graph, "draw", PassType::Graphics, [&](PassBuilder& b) {
        kept = b.writeColor(b.createTexture("kept", kColor), std::nullopt);
        replaced = b.write(b.createTexture("replaced", kColor), Usage::ColorAttachment, WriteMode::Discard);
        b.sideEffect();
    });
    addPass(graph, "again", PassType::Graphics, [&](PassBuilder& b) {
        kept = b.writeColor(kept, std::nullopt);
        b.sideEffect();
    });
    const CompiledGraph& compiled = graph.compile();
    EXPECT_EQ(compiled.passes[0].attachmentOps(kept.index)->load, LoadOp::DontCare);
    EXPECT_EQ(compiled.passes[0].attachmentOps(replaced.index)->load, LoadOp::DontCare);
    EXPECT_EQ(compiled.passes[1].attachmentOps(kept.index)->load, LoadOp::Load);  // "draw" wrote it
    EXPECT_TRUE(compiled.transientAttachments[replaced.index]);
    EXPECT_FALSE(compiled.transientAttachments[kept.index]);  // two passes
}

TEST(GraphAttachments, AnImportIsLoadedAndALostInputClearedToItsFallback) {
    RenderGraph graph;
    const TextureId target = graph.importTexture("target", kColor, {}, ResourceState{});
    TextureId scene, overlay;
    addPass(graph, "scene", PassType::Graphics,
            [&](PassBuilder& b) { scene = b.writeColor(b.createTexture("scene", kColor), VkClearColorValue{}); });
    addPass(graph, "overlay", PassType::Graphics, [&](PassBuilder& b) {
        overlay = b.drawOver(scene, VkClearColorValue{{0.25f, 0.5f, 0.75f, 1.0f}});
        b.writeColor(target, std::nullopt);
    });
    graph.exportTexture(overlay);
    const CompiledGraph& drawn = graph.compile();
    EXPECT_EQ(drawn.passes[1].attachmentOps(target.index)->load, LoadOp::Load);  // an import has contents
    EXPECT_EQ(drawn.passes[1].attachmentOps(scene.index)->load, LoadOp::Load);
    graph.setPassEnabled("scene", false);
    const CompiledGraph& lost = graph.compile();
    const AttachmentOps* ops = lost.passes[1].attachmentOps(scene.index);
    ASSERT_NE(ops, nullptr);
    EXPECT_EQ(ops->load, LoadOp::Clear);
    EXPECT_EQ(ops->clear.color.float32[2], 0.75f);
}

}  // namespace
}  // namespace candela::graph::graph_attachments_test
