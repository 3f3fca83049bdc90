#pragma once
// Helpers shared by the render graph's unit tests.

#include "graph/render_graph.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace candela::graph {

struct NoData {};

// Adds a pass whose setup is `setup(PassBuilder&)` and whose execution does nothing.
template <class Setup>
void addPass(RenderGraph& graph, const std::string& name, PassType type, Setup setup) {
    graph.addPass<NoData>(
        name, type, [&](PassBuilder& b, NoData&) { setup(b); }, [](const NoData&, PassContext&) {});
}

// "p3" from ("p", 3). (Appending avoids GCC 12's -Wrestrict false positive on literal + temporary.)
inline std::string indexed(const char* prefix, int index) {
    std::string name = prefix;
    name += std::to_string(index);
    return name;
}

// Runs `fn`, expects a GraphError and returns its message.
template <class Fn>
std::string graphError(Fn fn) {
    try {
        fn();
    } catch (const GraphError& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected a GraphError";
    return {};
}

inline const TextureDesc kColor{.width = 64, .height = 64, .format = VK_FORMAT_R8G8B8A8_UNORM};

// Names of the passes that run, in execution order.
inline std::vector<std::string> orderNames(const RenderGraph& graph) {
    std::vector<std::string> names;
    for (uint32_t p : graph.compiled().order) names.push_back(graph.declaration().passes[p].name);
    return names;
}

}  // namespace candela::graph
