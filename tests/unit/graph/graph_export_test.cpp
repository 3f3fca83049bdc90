// exportJson / exportDot: machine-readable and Graphviz views of a compiled graph.

#include "graph/graph_export.h"
#include "graph_test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace candela::graph {
namespace {

const TextureDesc kHdr{.width = 64, .height = 32, .format = VK_FORMAT_R16G16B16A16_SFLOAT};

// target ← tonemap ← hdr ← lighting, plus "debug" (culled: no output) reading hdr.
void buildGraph(RenderGraph& graph) {
    const TextureId target =
        graph.importTexture("target", kHdr, {}, ResourceState{0, 0, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR});
    TextureId hdr;
    addPass(graph, "lighting", PassType::Graphics,
            [&](PassBuilder& b) { hdr = b.writeColor(b.createTexture("hdr", kHdr), VkClearColorValue{}); });
    addPass(graph, "debug", PassType::Compute, [&](PassBuilder& b) {
        b.read(hdr, Usage::Sampled);
        b.write(b.createTexture("histogram", kHdr), Usage::StorageWrite);
    });
    addPass(graph, "tonemap", PassType::Graphics, [&](PassBuilder& b) {
        b.read(hdr, Usage::Sampled);
        b.writeColor(target, std::nullopt);
    });
}

TEST(GraphExport, JsonDescribesPassesResourcesHeapsAndBarriers) {
    RenderGraph graph;
    buildGraph(graph);
    const CompiledGraph& compiled = graph.compile();
    const GraphTimings timings{{1.5, -1.0, 0.25}};
    const nlohmann::json json = nlohmann::json::parse(exportJson(graph.declaration(), compiled, &timings));

    ASSERT_EQ(json["passes"].size(), 3u);
    const nlohmann::json& lighting = json["passes"][0];
    EXPECT_EQ(lighting["name"], "lighting");
    EXPECT_EQ(lighting["type"], "graphics");
    EXPECT_EQ(lighting["order"], 0);
    EXPECT_EQ(lighting["culled"], false);
    EXPECT_EQ(lighting["gpuMs"], 1.5);
    EXPECT_EQ(lighting["writes"][0]["resource"], "hdr");
    EXPECT_EQ(lighting["writes"][0]["version"], 1);
    EXPECT_EQ(lighting["writes"][0]["usage"], "ColorAttachment");
    EXPECT_EQ(lighting["writes"][0]["loadOp"], "clear");
    EXPECT_EQ(lighting["writes"][0]["storeOp"], "store");  // the tonemap samples it
    EXPECT_EQ(json["passes"][2]["writes"][0]["loadOp"], "load");  // the imported target's contents

    const nlohmann::json& debug = json["passes"][1];
    EXPECT_EQ(debug["culled"], true);
    EXPECT_TRUE(debug["order"].is_null());
    EXPECT_EQ(debug["reason"], "NoOutput");
    EXPECT_EQ(debug["detail"], "contributes to no output");
    EXPECT_FALSE(debug.contains("gpuMs"));
    EXPECT_EQ(debug["reads"][0]["resource"], "hdr");

    EXPECT_EQ(json["order"], (nlohmann::json{"lighting", "tonemap"}));

    ASSERT_EQ(json["resources"].size(), 3u);
    const nlohmann::json& hdr = json["resources"][1];
    EXPECT_EQ(hdr["name"], "hdr");
    EXPECT_EQ(hdr["kind"], "texture");
    EXPECT_EQ(hdr["width"], 64);
    EXPECT_EQ(hdr["height"], 32);
    EXPECT_EQ(hdr["format"], "R16G16B16A16Sfloat");
    EXPECT_EQ(hdr["size"], 64 * 32 * 8);
    EXPECT_EQ(hdr["first"], 0);
    EXPECT_EQ(hdr["last"], 1);
    EXPECT_EQ(hdr["heap"], 0);
    EXPECT_EQ(hdr["offset"], 0);
    EXPECT_EQ(hdr["transientAttachment"], false);  // sampled
    EXPECT_TRUE(json["resources"][0]["heap"].is_null());  // imported
    EXPECT_TRUE(json["resources"][2]["first"].is_null());  // only used by the culled pass

    ASSERT_EQ(json["heaps"].size(), 1u);
    EXPECT_EQ(json["heaps"][0]["kind"], "texture");
    EXPECT_EQ(json["heaps"][0]["size"], 64 * 32 * 8);
    EXPECT_EQ(json["heaps"][0]["residents"], (nlohmann::json{"hdr"}));
    EXPECT_EQ(json["bytesRequested"], 64 * 32 * 8);
    EXPECT_EQ(json["bytesAllocated"], 64 * 32 * 8);

    const nlohmann::json& barriers = json["barriers"];
    ASSERT_EQ(barriers.size(), 4u);
    EXPECT_EQ(barriers[1]["before"], "tonemap");
    EXPECT_EQ(barriers[1]["resource"], "hdr");
    EXPECT_EQ(barriers[1]["srcStages"], (nlohmann::json{"ColorAttachmentOutput"}));
    EXPECT_EQ(barriers[1]["srcAccess"], (nlohmann::json{"ColorAttachmentWrite"}));
    EXPECT_EQ(barriers[1]["dstStages"], (nlohmann::json{"VertexShader", "FragmentShader"}));
    EXPECT_EQ(barriers[1]["dstAccess"], (nlohmann::json{"ShaderSampledRead"}));
    EXPECT_EQ(barriers[1]["oldLayout"], "ColorAttachmentOptimal");
    EXPECT_EQ(barriers[1]["newLayout"], "ShaderReadOnlyOptimal");
    EXPECT_TRUE(barriers[1]["aliasedFrom"].is_null());
    EXPECT_EQ(barriers[3]["before"], "end");
    EXPECT_EQ(barriers[3]["resource"], "target");
    EXPECT_EQ(barriers[3]["newLayout"], "PresentSrcKHR");

    EXPECT_EQ(json["steps"],
              (nlohmann::json{"validate", "cull", "order", "unread writes", "lifetimes", "attachments", "aliasing",
                              "barriers"}));
}

TEST(GraphExport, DotListsPassesResourcesAndCulling) {
    RenderGraph graph;
    buildGraph(graph);
    const CompiledGraph& compiled = graph.compile();
    const GraphTimings timings{{1.5, -1.0, 0.25}};
    const std::string dot = exportDot(graph.declaration(), compiled, &timings);
    EXPECT_EQ(dot.rfind("digraph", 0), 0u) << dot;
    EXPECT_NE(dot.find("lighting\\n#0 1.500 ms"), std::string::npos) << dot;
    EXPECT_NE(dot.find("tonemap\\n#1 0.250 ms"), std::string::npos) << dot;
    EXPECT_NE(dot.find("debug\\nculled: NoOutput"), std::string::npos) << dot;
    EXPECT_NE(dot.find("style=dashed"), std::string::npos) << dot;
    EXPECT_NE(dot.find("heap 0 @ 0"), std::string::npos) << dot;
    EXPECT_NE(dot.find("r1 -> p2"), std::string::npos) << dot;  // tonemap reads hdr
    EXPECT_NE(dot.find("p0 -> r1"), std::string::npos) << dot;  // lighting writes hdr
    EXPECT_EQ(dot.back(), '\n');
}

TEST(GraphExport, SaysWhenTheGpuTimesMissDeferredWork) {
    RenderGraph graph;
    buildGraph(graph);
    const CompiledGraph& compiled = graph.compile();
    GraphTimings timings{{1.5, -1.0, 0.25}};
    EXPECT_FALSE(nlohmann::json::parse(exportJson(graph.declaration(), compiled, &timings)).contains("gpuMsUnreliable"));
    EXPECT_EQ(exportDot(graph.declaration(), compiled, &timings).find("unreliable"), std::string::npos);
    timings.gpuMsUnreliable = true;  // as on a CPU device
    const nlohmann::json json = nlohmann::json::parse(exportJson(graph.declaration(), compiled, &timings));
    EXPECT_EQ(json["gpuMsUnreliable"], kUnreliableGpuTimes);
    EXPECT_EQ(json["passes"][0]["gpuMs"], 1.5);  // still listed
    const std::string dot = exportDot(graph.declaration(), compiled, &timings);
    EXPECT_NE(dot.find("lighting\\n#0 1.500 ms*"), std::string::npos) << dot;
    EXPECT_NE(dot.find("label=\"* per-pass GPU times are unreliable"), std::string::npos) << dot;
}

TEST(GraphExport, RejectsAGraphThatWasNotCompiled) {
    RenderGraph graph;
    buildGraph(graph);
    EXPECT_THROW(exportJson(graph.declaration(), CompiledGraph{}), GraphError);
}

}  // namespace
}  // namespace candela::graph
