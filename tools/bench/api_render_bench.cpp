// Times Device::render through the public C++ API: the reference for the Python module's overhead
// (tools/python-overhead.py, docs/python.md#overhead).
//   candela_api_render_bench SCENE|grid WIDTH HEIGHT RENDERS
// Renders the scene lit by the built-in sky RENDERS times after 5 warm-up renders and prints the
// median and lowest time of one render in milliseconds: "median_ms=… lowest_ms=…".
#include "candela/candela.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: %s SCENE|grid WIDTH HEIGHT RENDERS\n", argv[0]);
        return 2;
    }
    try {
        const std::string source = argv[1];
        const candela::Scene scene = source == "grid" ? candela::Scene::sphereGrid() : candela::Scene::fromFile(source);
        const candela::Environment sky = candela::Environment::sky();
        candela::Device device({.pipelineCache = "off"});
        candela::RenderOptions options;
        options.width = uint32_t(std::atoi(argv[2]));
        options.height = uint32_t(std::atoi(argv[3]));
        const int renders = std::atoi(argv[4]);
        for (int i = 0; i < 5; ++i) device.render(scene, options, &sky);
        std::vector<double> ms;
        for (int i = 0; i < renders; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const candela::Image image = device.render(scene, options, &sky);
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        std::sort(ms.begin(), ms.end());
        std::printf("median_ms=%.4f lowest_ms=%.4f\n", ms[ms.size() / 2], ms.front());
    } catch (const candela::Error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
