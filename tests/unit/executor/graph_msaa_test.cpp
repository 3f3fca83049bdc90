// Multisampling in the render graph: multisampled transients, render-pass resolves into
// single-sample images, and the results nothing reads (resolves skipped, attachments not stored).
// The frame the renderer builds is the model: "forward" clears a multisampled colour and depth and
// resolves; "skybox" draws over the colour, tests the depth and resolves; "tonemap" samples the
// resolved image into an imported output.

#include "executor/transient_pool.h"
#include "graph_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace candela::graph {
namespace {

constexpr TextureDesc kHdr{.width = 64, .height = 32, .format = VK_FORMAT_R16G16B16A16_SFLOAT};
constexpr TextureDesc kHdr4{.width = 64, .height = 32, .format = VK_FORMAT_R16G16B16A16_SFLOAT, .samples = 4};
constexpr TextureDesc kDepth4{.width = 64, .height = 32, .format = VK_FORMAT_D32_SFLOAT, .samples = 4};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct MsaaFrame {
    RenderGraph graph;
    TextureId msaa, depth, hdr, output;
    MsaaFrame() {
        output = graph.importTexture("output", kColor, {}, ResourceState{});
        addPass(graph, "forward", PassType::Graphics, [&](PassBuilder& b) {
            msaa = b.writeColor(b.createTexture("hdr_msaa", kHdr4), VkClearColorValue{});
            depth = b.writeDepth(b.createTexture("depth", kDepth4), 0.0f);
            hdr = b.resolve(msaa, b.createTexture("hdr", kHdr));
        });
        addPass(graph, "skybox", PassType::Graphics, [&](PassBuilder& b) {
            b.read(depth, Usage::DepthRead);
            msaa = b.writeColor(msaa, std::nullopt);
            hdr = b.resolve(msaa, hdr);
        });
        addPass(graph, "tonemap", PassType::Graphics, [&](PassBuilder& b) {
            b.sample(hdr);
            b.writeColor(output, VkClearColorValue{});
        });
    }
    const std::vector<uint32_t>& unread(std::string_view pass) const {
        return graph.compiled().passes[*graph.findPass(pass)].unreadWrites;
    }
    bool isUnread(std::string_view pass, std::string_view resource) const {
        const std::vector<uint32_t>& list = unread(pass);
        return std::find(list.begin(), list.end(), *graph.findResource(resource)) != list.end();
    }
};

TEST(GraphMsaa, ResolveIsAWriteOfTheTargetNamingItsSource) {
    MsaaFrame frame;
    const PassDecl& forward = frame.graph.declaration().passes[0];
    ASSERT_EQ(forward.writes.size(), 3u);
    const AccessDecl& resolve = forward.writes[2];
    EXPECT_EQ(resolve.usage, Usage::ResolveAttachment);
    EXPECT_EQ(resolve.resolveSource, frame.msaa.index);
    EXPECT_EQ(resolve.mode, WriteMode::Discard);  // the colour was cleared
    // Drawing over the colour makes the skybox's resolve preserving, so switching it off bypasses it.
    EXPECT_EQ(frame.graph.declaration().passes[1].writes[1].mode, WriteMode::Preserve);
    const AccessSync sync = accessSync(Usage::ResolveAttachment, PassType::Graphics, ResourceKind::Texture);
    EXPECT_EQ(sync.stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(sync.access, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(sync.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
}

TEST(GraphMsaa, OnlyTheLastResolveRunsAndTheMultisampledColourIsStoredOnlyForTheNextDraw) {
    MsaaFrame frame;
    frame.graph.compile();
    EXPECT_EQ(orderNames(frame.graph), (std::vector<std::string>{"forward", "skybox", "tonemap"}));
    EXPECT_TRUE(frame.isUnread("forward", "hdr"));        // the skybox resolves over it
    EXPECT_FALSE(frame.isUnread("forward", "hdr_msaa"));  // the skybox draws over it
    EXPECT_FALSE(frame.isUnread("forward", "depth"));     // the skybox tests against it
    EXPECT_TRUE(frame.isUnread("skybox", "hdr_msaa"));    // resolved, never needed again
    EXPECT_FALSE(frame.isUnread("skybox", "hdr"));        // the tonemap samples it
    EXPECT_TRUE(frame.unread("tonemap").empty());         // imported output: read after the graph
}

TEST(GraphMsaa, SwitchingTheLastDrawOffMakesTheEarlierResolveTheOneRead) {
    MsaaFrame frame;
    frame.graph.setPassEnabled("skybox", false);
    frame.graph.compile();
    EXPECT_EQ(orderNames(frame.graph), (std::vector<std::string>{"forward", "tonemap"}));
    EXPECT_TRUE(frame.graph.compiled().passes[1].bypassed);
    EXPECT_FALSE(frame.isUnread("forward", "hdr"));
    EXPECT_TRUE(frame.isUnread("forward", "hdr_msaa"));
    EXPECT_TRUE(frame.isUnread("forward", "depth"));
}

TEST(GraphMsaa, MultisampledTransientsTakeSamplesTimesTheMemory) {
    ResourceDecl single{.name = "a", .texture = kHdr};
    ResourceDecl multi{.name = "b", .texture = kHdr4};
    EXPECT_EQ(estimateMemoryRequirement(multi).size, 4 * estimateMemoryRequirement(single).size);
    MsaaFrame frame;
    frame.graph.compile();
    // hdr_msaa, depth and hdr overlap in time: nothing aliases among them.
    EXPECT_EQ(frame.graph.compiled().bytesRequested, 4 * 64 * 32 * 8 + 4 * 64 * 32 * 4 + 64 * 32 * 8);
}

TEST(GraphMsaa, AttachmentsTheNextPassLoadsAreNoTransientAttachments) {
    // Forward stores the multisampled colour and depth for the skybox, which loads them: neither
    // may live in lazily allocated (tile or memoryless) memory (graph_attachments_test.cpp has the rest).
    MsaaFrame frame;
    const CompiledGraph& compiled = frame.graph.compile();
    const GraphDecl& decl = frame.graph.declaration();
    EXPECT_FALSE(compiled.transientAttachments[frame.msaa.index]);
    EXPECT_FALSE(compiled.transientAttachments[frame.depth.index]);
    EXPECT_EQ(imageUsageOf(decl, frame.msaa.index, compiled.transientAttachments[frame.msaa.index]),
              VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT));
    EXPECT_EQ(imageUsageOf(decl, frame.depth.index, compiled.transientAttachments[frame.depth.index]),
              VkImageUsageFlags(VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT));
    // The resolved image is sampled later: an ordinary image.
    EXPECT_FALSE(compiled.transientAttachments[frame.hdr.index]);
    EXPECT_EQ(imageUsageOf(decl, frame.hdr.index, compiled.transientAttachments[frame.hdr.index]),
              VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT));
}

TEST(GraphMsaa, WithTheSkyboxOffTheForwardPassKeepsItsAttachmentsToItself) {
    MsaaFrame frame;
    frame.graph.setPassEnabled("skybox", false);
    const CompiledGraph& compiled = frame.graph.compile();
    const GraphDecl& decl = frame.graph.declaration();
    EXPECT_TRUE(compiled.transientAttachments[frame.msaa.index]);
    EXPECT_TRUE(compiled.transientAttachments[frame.depth.index]);
    EXPECT_EQ(imageUsageOf(decl, frame.msaa.index, true),
              VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT));
    EXPECT_EQ(imageUsageOf(decl, frame.depth.index, true),
              VkImageUsageFlags(VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT));
    EXPECT_FALSE(compiled.transientAttachments[frame.hdr.index]);
}

TEST(GraphMsaa, ResolvesThatCannotWorkAreRefused) {
    RenderGraph graph;
    std::string message;
    addPass(graph, "p", PassType::Graphics, [&](PassBuilder& b) {
        const TextureId single = b.writeColor(b.createTexture("single", kHdr), std::nullopt);
        const TextureId target = b.createTexture("target", kHdr);
        const TextureId msaa = b.createTexture("msaa", kHdr4);
        message = graphError([&] { b.resolve(single, target); });
        EXPECT_TRUE(contains(message, "'single', which has 1 sample")) << message;
        message = graphError([&] { b.resolve(msaa, target); });
        EXPECT_TRUE(contains(message, "not a colour attachment it writes")) << message;
        const TextureId drawn = b.writeColor(msaa, std::nullopt);
        message = graphError([&] { b.resolve(drawn, b.createTexture("small", {.width = 8, .height = 8, .format = kHdr.format})); });
        EXPECT_TRUE(contains(message, "not a single-sample image of its size and format")) << message;
        message = graphError([&] { b.resolve(drawn, b.createTexture("other", kHdr4)); });
        EXPECT_TRUE(contains(message, "not a single-sample image")) << message;
    });
}

TEST(GraphMsaa, MultisampledImagesAreAttachmentsOfOneSampleCountPerPass) {
    {
        RenderGraph graph;
        TextureId msaa;
        addPass(graph, "draw", PassType::Graphics,
                [&](PassBuilder& b) { msaa = b.writeColor(b.createTexture("msaa", kHdr4), VkClearColorValue{}); });
        addPass(graph, "read", PassType::Compute, [&](PassBuilder& b) {
            b.read(msaa, Usage::StorageRead);
            b.sideEffect();
        });
        const std::string message = graphError([&] { graph.compile(); });
        EXPECT_TRUE(contains(message, "uses multisampled 'msaa' as StorageRead")) << message;
    }
    {
        // Sampled sample by sample (texelFetch of a sampler2DMS): allowed.
        RenderGraph graph;
        TextureId msaa;
        addPass(graph, "draw", PassType::Graphics,
                [&](PassBuilder& b) { msaa = b.writeColor(b.createTexture("msaa", kHdr4), VkClearColorValue{}); });
        addPass(graph, "read", PassType::Compute, [&](PassBuilder& b) {
            b.sample(msaa);
            b.sideEffect();
        });
        EXPECT_NO_THROW(graph.compile());
    }
    {
        RenderGraph graph;
        addPass(graph, "draw", PassType::Graphics, [&](PassBuilder& b) {
            b.writeColor(b.createTexture("msaa", kHdr4), VkClearColorValue{});
            b.writeDepth(b.createTexture("depth", {.width = 64, .height = 32, .format = VK_FORMAT_D32_SFLOAT}), 0.0f);
            b.sideEffect();
        });
        const std::string message = graphError([&] { graph.compile(); });
        EXPECT_TRUE(contains(message, "attachments of 4 and 1 samples")) << message;
    }
}

}  // namespace
}  // namespace candela::graph
