// Times RenderGraph::compile() on a synthetic 50-pass graph (no GPU): a main chain of graphics
// passes with side branches of compute passes, transients of several sizes, one imported output
// and one dead branch that is culled. Prints the median of many runs.
//
//   build/release/tools/bench/candela_graph_compile_bench [passes=50] [runs=2000]

#include "graph/render_graph.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace candela::graph;

namespace {

struct Data {
    TextureId out;
};

void buildGraph(RenderGraph& graph, int passCount) {
    const TextureId output = graph.importTexture("swapchain", {.width = 1920, .height = 1080, .format = VK_FORMAT_B8G8R8A8_SRGB},
                                                 {}, ResourceState{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                                                                   VK_IMAGE_LAYOUT_PRESENT_SRC_KHR});
    TextureId current;
    std::vector<TextureId> side;
    for (int i = 0; i < passCount - 1; ++i) {
        const bool compute = i % 3 == 1;
        const uint32_t size = 256u << (i % 3);
        const TextureId previous = current;
        const std::vector<TextureId> inputs = side;
        const Data& d = graph.addPass<Data>(
            "pass" + std::to_string(i), compute ? PassType::Compute : PassType::Graphics,
            [&](PassBuilder& b, Data& data) {
                if (previous.valid()) b.read(previous, Usage::Sampled);
                for (const TextureId& s : inputs) b.read(s, Usage::Sampled);
                const TextureId t = b.createTexture("t" + std::to_string(i),
                                                    {.width = size, .height = size, .format = VK_FORMAT_R16G16B16A16_SFLOAT});
                data.out = compute ? b.write(t, Usage::StorageWrite, WriteMode::Discard)
                                   : b.writeColor(t, VkClearColorValue{});
            },
            [](const Data&, PassContext&) {});
        if (compute) {
            side = {d.out};
        } else {
            side.clear();
            current = d.out;
        }
        if (i == passCount / 2) {
            // A dead branch: written, never read.
            graph.addPass<Data>("dead", PassType::Compute,
                                [&](PassBuilder& b, Data& data) {
                                    data.out = b.write(b.createTexture("unused", {.width = 64, .height = 64,
                                                                                  .format = VK_FORMAT_R8G8B8A8_UNORM}),
                                                       Usage::StorageWrite, WriteMode::Discard);
                                },
                                [](const Data&, PassContext&) {});
        }
    }
    graph.addPass<Data>("present", PassType::Graphics,
                        [&](PassBuilder& b, Data& data) {
                            b.read(current, Usage::Sampled);
                            data.out = b.writeColor(output, VkClearColorValue{});
                        },
                        [](const Data&, PassContext&) {});
}

}  // namespace

int main(int argc, char** argv) {
    const int passes = argc > 1 ? std::atoi(argv[1]) : 50;
    const int runs = argc > 2 ? std::atoi(argv[2]) : 2000;
    std::vector<double> buildUs, compileUs;
    size_t kept = 0, barriers = 0;
    unsigned long long requested = 0, allocated = 0;
    for (int r = 0; r < runs; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        RenderGraph graph;
        buildGraph(graph, passes);
        const auto t1 = std::chrono::steady_clock::now();
        const CompiledGraph& compiled = graph.compile();
        const auto t2 = std::chrono::steady_clock::now();
        buildUs.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
        compileUs.push_back(std::chrono::duration<double, std::micro>(t2 - t1).count());
        kept = compiled.order.size();
        barriers = compiled.finalBarriers.size();
        for (const auto& b : compiled.barriers) barriers += b.size();
        requested = compiled.bytesRequested;
        allocated = compiled.bytesAllocated;
    }
    const auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    std::printf("%d declared passes (%zu kept), %zu barriers, transients %.1f MiB requested / %.1f MiB after aliasing\n",
                passes + 1, kept, barriers, requested / 1048576.0, allocated / 1048576.0);
    std::printf("median over %d runs: build %.1f us, compile %.1f us\n", runs, median(buildUs), median(compileUs));
    return 0;
}
