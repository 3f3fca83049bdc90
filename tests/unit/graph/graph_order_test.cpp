// Steps "validate" and "order": execution order follows the data (never the declaration order),
// and malformed graphs are rejected with messages naming the passes and resources.
// Graphs are built as GraphDecl directly: the builder cannot express most of these mistakes.

#include "graph/compiled_graph.h"

#include <gtest/gtest.h>

#include <string>

namespace candela::graph {
namespace {

ResourceDecl texture(std::string name, bool imported = false) {
    return {.name = std::move(name), .imported = imported};
}

AccessDecl reads(uint32_t resource, uint32_t version, Usage usage = Usage::Sampled) {
    return {.resource = resource, .version = version, .usage = usage};
}

AccessDecl writes(uint32_t resource, uint32_t version, WriteMode mode = WriteMode::Discard,
                  Usage usage = Usage::StorageWrite) {
    return {.resource = resource, .version = version, .usage = usage, .mode = mode};
}

PassDecl pass(std::string name, std::vector<AccessDecl> readList, std::vector<AccessDecl> writeList) {
    return {.name = std::move(name), .type = PassType::Compute, .reads = std::move(readList),
            .writes = std::move(writeList)};
}

std::vector<std::string> orderNames(const GraphDecl& decl, const CompiledGraph& compiled) {
    std::vector<std::string> names;
    for (uint32_t p : compiled.order) names.push_back(decl.passes[p].name);
    return names;
}

std::string compileError(const GraphDecl& decl) {
    try {
        compileGraph(decl);
    } catch (const GraphError& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected a GraphError";
    return {};
}

TEST(GraphOrder, FollowsDataWhenDeclaredInReverse) {
    GraphDecl decl;
    decl.resources = {texture("out", true), texture("a"), texture("b")};
    decl.passes = {
        pass("third", {reads(2, 1)}, {writes(0, 1)}),
        pass("second", {reads(1, 1)}, {writes(2, 1)}),
        pass("first", {}, {writes(1, 1)}),
    };
    const CompiledGraph compiled = compileGraph(decl);
    EXPECT_EQ(orderNames(decl, compiled), (std::vector<std::string>{"first", "second", "third"}));
    EXPECT_EQ(compiled.order, (std::vector<uint32_t>{2, 1, 0}));
}

TEST(GraphOrder, IndependentPassesKeepDeclarationOrder) {
    GraphDecl decl;
    decl.resources = {texture("x", true), texture("y", true), texture("z", true)};
    decl.passes = {pass("c", {}, {writes(2, 1)}), pass("a", {}, {writes(0, 1)}), pass("b", {}, {writes(1, 1)})};
    EXPECT_EQ(compileGraph(decl).order, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(GraphOrder, ReaderOfOldVersionRunsBeforeNextWriter) {
    GraphDecl decl;
    decl.resources = {texture("image", true), texture("stats", true)};
    decl.passes = {
        pass("overwrite", {}, {writes(0, 1)}),
        pass("inspect", {reads(0, 0)}, {writes(1, 1)}),
    };
    EXPECT_EQ(orderNames(decl, compileGraph(decl)), (std::vector<std::string>{"inspect", "overwrite"}));
}

TEST(GraphOrder, WritesOfSuccessiveVersionsAreOrdered) {
    GraphDecl decl;
    decl.resources = {texture("image", true)};
    decl.passes = {pass("later", {}, {writes(0, 2)}), pass("earlier", {}, {writes(0, 1)})};
    EXPECT_EQ(orderNames(decl, compileGraph(decl)), (std::vector<std::string>{"earlier", "later"}));
}

TEST(GraphOrder, OrderingSurvivesCulledPassesInBetween) {
    // reader (v1) → [culled mid writes v2] → last writes v3: reader must still precede last.
    GraphDecl decl;
    decl.resources = {texture("t"), texture("out", true), texture("out2", true)};
    decl.passes = {
        pass("last", {}, {writes(0, 3), writes(2, 1)}),
        pass("mid", {}, {writes(0, 2)}),
        pass("reader", {reads(0, 1)}, {writes(1, 1)}),
        pass("producer", {}, {writes(0, 1)}),
    };
    const CompiledGraph compiled = compileGraph(decl);
    EXPECT_EQ(compiled.passes[1].cullReason, CullReason::NoOutput);
    EXPECT_EQ(orderNames(decl, compiled), (std::vector<std::string>{"producer", "reader", "last"}));
}

TEST(GraphOrder, CycleNamesPassesAndResources) {
    GraphDecl decl;
    decl.resources = {texture("texX"), texture("texY")};
    decl.passes = {
        pass("a", {reads(1, 1)}, {writes(0, 1)}),
        pass("b", {reads(0, 1)}, {writes(1, 1)}),
    };
    EXPECT_EQ(compileError(decl), "cycle between passes 'a' -> 'b' -> 'a' (via 'texX', 'texY')");
}

TEST(GraphOrder, CycleBehindAnAcyclicPrefix) {
    GraphDecl decl;
    decl.resources = {texture("texZ"), texture("texU"), texture("texV"), texture("texW")};
    decl.passes = {
        pass("src", {}, {writes(0, 1)}),
        pass("x", {reads(0, 1), reads(3, 1)}, {writes(1, 1)}),
        pass("y", {reads(1, 1)}, {writes(2, 1)}),
        pass("z", {reads(2, 1)}, {writes(3, 1)}),
    };
    EXPECT_EQ(compileError(decl), "cycle between passes 'x' -> 'y' -> 'z' -> 'x' (via 'texU', 'texV', 'texW')");
}

TEST(GraphOrder, CycleThroughWriteAfterRead) {
    // "r" reads image v0 which "w" overwrites, but "r" also needs w's other output.
    GraphDecl decl;
    decl.resources = {texture("image", true), texture("mask")};
    decl.passes = {
        pass("r", {reads(0, 0), reads(1, 1)}, {}),
        pass("w", {}, {writes(0, 1), writes(1, 1)}),
    };
    EXPECT_EQ(compileError(decl), "cycle between passes 'r' -> 'w' -> 'r' (via 'image', 'mask')");
}

TEST(GraphOrder, ReadWithoutProducerNamesPassAndResource) {
    GraphDecl decl;
    decl.resources = {texture("target", true), texture("hdr")};
    decl.passes = {pass("tonemap", {reads(1, 1)}, {writes(0, 1)})};
    EXPECT_EQ(compileError(decl), "pass 'tonemap' reads 'hdr' (version 1), which no pass writes");

    decl.passes = {pass("tonemap", {reads(1, 0)}, {writes(0, 1)})};
    EXPECT_EQ(compileError(decl), "pass 'tonemap' reads 'hdr' (version 0), which no pass writes");

    // Version 0 of an import holds valid contents.
    decl.resources[1].imported = true;
    EXPECT_NO_THROW(compileGraph(decl));
}

TEST(GraphOrder, DuplicateProducerNamesBothPasses) {
    GraphDecl decl;
    decl.resources = {texture("out", true), texture("t")};
    decl.passes = {
        pass("one", {}, {writes(1, 1)}),
        pass("two", {}, {writes(1, 1)}),
        pass("use", {reads(1, 1)}, {writes(0, 1)}),
    };
    EXPECT_EQ(compileError(decl), "passes 'one' and 'two' both write 't' (version 1)");
}

TEST(GraphOrder, MalformedAccessesAreRejected) {
    GraphDecl decl;
    decl.resources = {texture("t", true)};
    decl.passes = {pass("p", {}, {writes(0, 0)})};
    EXPECT_EQ(compileError(decl), "pass 'p' writes 't' (version 0): a write produces a version > 0");

    decl.passes = {pass("p", {reads(7, 0)}, {})};
    EXPECT_EQ(compileError(decl), "pass 'p' reads resource index 7, which does not exist");

    decl.passes = {pass("p", {}, {writes(0, 1, WriteMode::Discard, Usage::Sampled)})};
    EXPECT_EQ(compileError(decl), "pass 'p' writes 't' with read-only usage Sampled");
}

}  // namespace
}  // namespace candela::graph
