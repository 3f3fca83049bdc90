// The texture-decode term of a render's floor (docs/measurements.md, "The floor of one render"):
// loads a glTF file with the glTF loader alone, in this fresh process, with no device starting and
// nothing else on the cores (the decode before the rest of the load: LoadOptions::decodeBesideTheLoad
// false), and prints the wall time of decoding its textures (every image the materials use, on every
// core, by the code a render runs) and of the whole load. Run it several times: each run is one
// fresh process, as a render is.
//
//   build/release/tools/bench/candela_decode_floor_bench FILE.glb

#include "assets/gltf_loader.h"

#include <chrono>
#include <cstdio>
#include <exception>

using namespace candela;

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: candela_decode_floor_bench FILE\n");
        return 2;
    }
    try {
        const auto start = std::chrono::steady_clock::now();
        const scene::Scene scene = assets::loadGltf(argv[1], {.decodeBesideTheLoad = false});
        const double loadMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const auto& decoding = scene.report.textureDecoding;
        size_t files = 0;
        for (const auto& [format, count] : decoding.formats) files += count;
        std::printf("texture decode %.1f ms (%zu files, %.1f MB to %.1f MB); whole load %.1f ms\n", decoding.milliseconds, files,
                    double(decoding.encodedBytes) / 1e6, double(decoding.decodedBytes) / 1e6, loadMs);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", argv[1], e.what());
        return 1;
    }
    return 0;
}
