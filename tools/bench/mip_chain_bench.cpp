// Times the CPU mip chains a texture gets on upload (geometry/image_mips.h, normal_map_mips.h) on a
// random square image: the box chain of a UNORM and of an sRGB image, and a normal map's chain,
// each written into levels allocated and touched beforehand (as a host-written texture's mapped
// levels are), on every core. Prints the median and minimum over the runs.
//
//   build/release/tools/bench/candela_mip_chain_bench [size=2048] [runs=15]

#include "geometry/image_mips.h"
#include "geometry/normal_map_mips.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace candela;

int main(int argc, char** argv) {
    const uint32_t size = argc > 1 ? uint32_t(std::max(1, std::atoi(argv[1]))) : 2048u;
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 15;
    scene::Image image{.name = "random", .width = size, .height = size};
    image.rgba8.resize(size_t(size) * size * 4);
    std::mt19937 random(1);
    for (uint8_t& b : image.rgba8) b = uint8_t(random() & 255u);
    std::vector<std::vector<uint8_t>> storage;
    const auto time = [&](const char* what, uint32_t first, auto&& write) {
        const std::vector<geometry::TexelLevel> levels = geometry::packedLevels(size, size, first, storage);
        std::vector<double> ms;
        for (int run = 0; run < runs; ++run) {
            const auto start = std::chrono::steady_clock::now();
            write(levels);
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        std::sort(ms.begin(), ms.end());
        std::printf("%-10s median %6.2f ms, min %6.2f ms\n", what, ms[ms.size() / 2], ms.front());
    };
    image.srgb = false;
    time("UNORM", 1, [&](const auto& levels) { geometry::writeBoxMipChain(image, levels); });
    image.srgb = true;
    time("sRGB", 1, [&](const auto& levels) { geometry::writeBoxMipChain(image, levels); });
    image.srgb = false;
    time("normal map", 0, [&](const auto& levels) { geometry::writeNormalMapMipChain(image, levels); });
    return 0;
}
