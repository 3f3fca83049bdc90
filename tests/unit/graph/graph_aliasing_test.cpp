// Steps "lifetimes" and "aliasing": transients alive at the same time never share bytes, the
// others may; alignment, resource kinds and memory types are respected.

#include "graph_test_util.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace candela::graph {
namespace {

constexpr VkDeviceSize kColorBytes = 64 * 64 * 4;

// Checks the aliasing invariants on any compiled graph.
void expectValidPlacement(const GraphDecl& decl, const CompiledGraph& compiled) {
    for (uint32_t a = 0; a < decl.resources.size(); ++a) {
        const Placement& pa = compiled.placements[a];
        const bool transient = !decl.resources[a].imported && compiled.lifetimes[a].used();
        ASSERT_EQ(pa.heap != kInvalidIndex, transient) << decl.resources[a].name;
        if (!transient) continue;
        const Heap& heap = compiled.heaps[pa.heap];
        EXPECT_EQ(heap.kind, decl.resources[a].kind);
        EXPECT_LE(pa.offset + pa.size, heap.size);
        for (uint32_t b = a + 1; b < decl.resources.size(); ++b) {
            const Placement& pb = compiled.placements[b];
            if (pb.heap != pa.heap) continue;
            const Lifetime& la = compiled.lifetimes[a];
            const Lifetime& lb = compiled.lifetimes[b];
            const bool together = la.first <= lb.last && lb.first <= la.last;
            const bool sharesBytes = pa.offset < pb.offset + pb.size && pb.offset < pa.offset + pa.size;
            EXPECT_FALSE(together && sharesBytes)
                << decl.resources[a].name << " and " << decl.resources[b].name << " overlap";
        }
    }
}

// p0 → t0 → p1 → t1 → ... → p{n} → out (imported): resources out, t0, ..., t{n-1}.
void buildChain(RenderGraph& graph, int transients) {
    const TextureId out = graph.importTexture("out", kColor, {});
    TextureId previous;
    for (int i = 0; i <= transients; ++i) {
        addPass(graph, indexed("p", i), PassType::Graphics, [&](PassBuilder& b) {
            if (previous.valid()) b.read(previous, Usage::Sampled);
            previous = i < transients
                           ? b.writeColor(b.createTexture(indexed("t", i), kColor), VkClearColorValue{})
                           : b.writeColor(out, VkClearColorValue{});
        });
    }
}

const Placement& placementOf(const RenderGraph& graph, const std::string& name) {
    return graph.compiled().placements[*graph.findResource(name)];
}

TEST(GraphAliasing, ChainReusesMemory) {
    RenderGraph graph;
    buildChain(graph, 4);
    const CompiledGraph& compiled = graph.compile();
    expectValidPlacement(graph.declaration(), compiled);
    EXPECT_EQ(compiled.lifetimes[*graph.findResource("t0")].first, 0u);
    EXPECT_EQ(compiled.lifetimes[*graph.findResource("t0")].last, 1u);
    EXPECT_EQ(compiled.lifetimes[*graph.findResource("t3")].first, 3u);
    EXPECT_EQ(compiled.lifetimes[*graph.findResource("t3")].last, 4u);
    ASSERT_EQ(compiled.heaps.size(), 1u);
    EXPECT_EQ(compiled.heaps[0].size, 2 * kColorBytes);
    EXPECT_EQ(compiled.heaps[0].residents, (std::vector<uint32_t>{1, 2, 3, 4}));
    EXPECT_EQ(placementOf(graph, "t0").offset, 0u);
    EXPECT_EQ(placementOf(graph, "t1").offset, kColorBytes);
    EXPECT_EQ(placementOf(graph, "t2").offset, 0u);
    EXPECT_EQ(placementOf(graph, "t3").offset, kColorBytes);
    EXPECT_EQ(compiled.bytesRequested, 4 * kColorBytes);
    EXPECT_EQ(compiled.bytesAllocated, 2 * kColorBytes);
    EXPECT_LT(compiled.bytesAllocated, compiled.bytesRequested);
    EXPECT_EQ(placementOf(graph, "out").heap, kInvalidIndex);
}

TEST(GraphAliasing, DisabledAliasingGivesEveryTransientItsHeap) {
    RenderGraph graph;
    buildChain(graph, 4);
    const CompiledGraph& compiled = graph.compile({.aliasing = false});
    expectValidPlacement(graph.declaration(), compiled);
    ASSERT_EQ(compiled.heaps.size(), 4u);
    for (const Heap& heap : compiled.heaps) EXPECT_EQ(heap.size, kColorBytes);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(placementOf(graph, indexed("t", i)).offset, 0u);
    EXPECT_EQ(compiled.bytesAllocated, compiled.bytesRequested);
}

TEST(GraphAliasing, AlignmentIsRespected) {
    RenderGraph graph;
    buildChain(graph, 2);
    CompileOptions options;
    options.memoryRequirements = [](uint32_t, const ResourceDecl& r, bool) {
        return r.name == "t0" ? MemoryRequirement{1000, 256, ~0u} : MemoryRequirement{100, 4096, ~0u};
    };
    const CompiledGraph& compiled = graph.compile(options);
    ASSERT_EQ(compiled.heaps.size(), 1u);
    EXPECT_EQ(placementOf(graph, "t0").offset, 0u);
    EXPECT_EQ(placementOf(graph, "t1").offset, 4096u);
    EXPECT_EQ(compiled.heaps[0].alignment, 4096u);
    EXPECT_EQ(compiled.heaps[0].size, 4196u);
    EXPECT_EQ(compiled.bytesRequested, 1100u);
}

TEST(GraphAliasing, ImagesAndBuffersNeverShareAHeap) {
    // texture tA [0,1] and buffer bufC [2,3] never live together, yet must not share memory.
    RenderGraph graph;
    const BufferId out = graph.importBuffer("out", {.size = 4096}, {});
    TextureId a, b;
    BufferId c;
    addPass(graph, "p0", PassType::Compute,
            [&](PassBuilder& pb) { a = pb.write(pb.createTexture("tA", kColor), Usage::StorageWrite); });
    addPass(graph, "p1", PassType::Compute, [&](PassBuilder& pb) {
        pb.read(a, Usage::Sampled);
        b = pb.write(pb.createTexture("tB", kColor), Usage::StorageWrite);
    });
    addPass(graph, "p2", PassType::Compute, [&](PassBuilder& pb) {
        pb.read(b, Usage::Sampled);
        c = pb.write(pb.createBuffer("bufC", {.size = kColorBytes}), Usage::StorageWrite);
    });
    addPass(graph, "p3", PassType::Compute, [&](PassBuilder& pb) {
        pb.read(c, Usage::StorageRead);
        pb.write(out, Usage::StorageWrite);
    });
    const CompiledGraph& compiled = graph.compile();
    expectValidPlacement(graph.declaration(), compiled);
    ASSERT_EQ(compiled.heaps.size(), 2u);
    const Placement& texture = placementOf(graph, "tA");
    const Placement& buffer = placementOf(graph, "bufC");
    EXPECT_NE(texture.heap, buffer.heap);
    EXPECT_EQ(compiled.heaps[texture.heap].kind, ResourceKind::Texture);
    EXPECT_EQ(compiled.heaps[buffer.heap].kind, ResourceKind::Buffer);
    EXPECT_EQ(compiled.heaps[buffer.heap].residents, (std::vector<uint32_t>{*graph.findResource("bufC")}));
}

TEST(GraphAliasing, IncompatibleMemoryTypesGetSeparateHeaps) {
    RenderGraph graph;
    buildChain(graph, 3);
    CompileOptions options;
    options.memoryRequirements = [](uint32_t, const ResourceDecl& r, bool) {
        const uint32_t bits = r.name == "t0" ? 0b01u : r.name == "t1" ? 0b11u : 0b10u;
        return MemoryRequirement{1024, 256, bits};
    };
    const CompiledGraph& compiled = graph.compile(options);
    expectValidPlacement(graph.declaration(), compiled);
    ASSERT_EQ(compiled.heaps.size(), 2u);
    EXPECT_EQ(placementOf(graph, "t0").heap, 0u);
    EXPECT_EQ(placementOf(graph, "t1").heap, 0u);
    EXPECT_EQ(placementOf(graph, "t1").offset, 1024u);
    EXPECT_EQ(compiled.heaps[0].memoryTypeBits, 0b01u);
    EXPECT_EQ(placementOf(graph, "t2").heap, 1u);
    EXPECT_EQ(compiled.heaps[1].memoryTypeBits, 0b10u);
}

TEST(GraphAliasing, EstimatedSizes) {
    ResourceDecl texture{.name = "t", .texture = kColor};
    EXPECT_EQ(estimateMemoryRequirement(texture).size, kColorBytes);
    EXPECT_EQ(estimateMemoryRequirement(texture).alignment, 256u);
    texture.texture.mipLevels = 7;  // 64² + 32² + ... + 1² = 5461 texels, rounded up to 256 bytes
    EXPECT_EQ(estimateMemoryRequirement(texture).size, 22016u);
    texture.texture.mipLevels = 1;
    texture.texture.arrayLayers = 6;
    EXPECT_EQ(estimateMemoryRequirement(texture).size, 6 * kColorBytes);
    const ResourceDecl buffer{.name = "b", .kind = ResourceKind::Buffer, .buffer = {.size = 1000}};
    EXPECT_EQ(estimateMemoryRequirement(buffer).size, 1024u);
}

// Random DAGs of passes reading earlier versions and creating transients of random sizes,
// alignments and memory types.
TEST(GraphAliasing, RandomGraphsNeverOverlapLiveResources) {
    std::mt19937 random(1234);
    auto pick = [&](uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(random); };
    for (int graphIndex = 0; graphIndex < 200; ++graphIndex) {
        RenderGraph graph;
        const TextureId out = graph.importTexture("out", kColor, {});
        std::vector<TextureId> textures;
        std::vector<BufferId> buffers;
        const uint32_t passCount = 2 + pick(20);
        for (uint32_t p = 0; p < passCount; ++p) {
            addPass(graph, indexed("p", p), PassType::Compute, [&](PassBuilder& b) {
                for (uint32_t k = 0; k < 2 && !textures.empty(); ++k)
                    b.read(textures[pick(textures.size())], Usage::Sampled);
                if (!buffers.empty() && pick(2) == 0) b.read(buffers[pick(buffers.size())], Usage::StorageRead);
                const std::string suffix = std::to_string(p);
                if (pick(3) != 0)
                    textures.push_back(b.write(b.createTexture("t" + suffix, kColor), Usage::StorageWrite));
                if (pick(3) == 0)
                    buffers.push_back(b.write(b.createBuffer("b" + suffix, {.size = 64}), Usage::StorageWrite));
                if (pick(4) == 0) b.sideEffect();
                if (p + 1 == passCount) b.write(out, Usage::StorageWrite);
            });
        }
        CompileOptions options;
        std::vector<MemoryRequirement> requirements(graph.declaration().resources.size());
        for (MemoryRequirement& requirement : requirements) {
            requirement = {256 * (1 + VkDeviceSize{pick(16)}), VkDeviceSize{1} << pick(12), 1u + pick(3)};
        }
        options.memoryRequirements = [&](uint32_t resource, const ResourceDecl&, bool) {
            return requirements[resource];
        };
        const CompiledGraph& compiled = graph.compile(options);
        expectValidPlacement(graph.declaration(), compiled);
        VkDeviceSize requested = 0;
        for (uint32_t r = 0; r < requirements.size(); ++r) {
            const Placement& placement = compiled.placements[r];
            if (placement.heap == kInvalidIndex) continue;
            requested += requirements[r].size;
            EXPECT_EQ(placement.offset % requirements[r].alignment, 0u);
            // The heap's memory types are the intersection of its residents'.
            const uint32_t heapBits = compiled.heaps[placement.heap].memoryTypeBits;
            EXPECT_NE(heapBits, 0u);
            EXPECT_EQ(heapBits & ~requirements[r].memoryTypeBits, 0u);
        }
        EXPECT_EQ(compiled.bytesRequested, requested);
        if (HasFailure()) {
            ADD_FAILURE() << "graph " << graphIndex;
            return;
        }
    }
}

}  // namespace
}  // namespace candela::graph
