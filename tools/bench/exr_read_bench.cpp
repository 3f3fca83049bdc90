// Times reading OpenEXR environment maps through Candela's reader (OpenEXRCore header check +
// OpenEXR C++ decode, assets::decodeExr) against tinyexr 1.0.1 (the reader it replaced,
// LoadEXRFromMemory), alternating file by file within each round so that both see the same machine
// state; prints the median of the rounds per file and the ratio. Both decode from memory to float;
// file reading is not timed. No GPU.
//
// The inputs are written first into OUT_DIR: every given Radiance .hdr re-encoded as a half-float
// RGB EXR (ZIP, as environment maps are commonly distributed), and a 4096 x 2048 float RGB map
// (a smooth gradient with noise) under NONE, ZIP and PIZ, the compressions both readers have.
//
//   build/release/tools/bench/candela_exr_read_bench OUT_DIR [rounds=7] FILE.hdr...

#include "assets/environment.h"
#include "assets/exr_reader.h"

#include "exr_test_writer.h"

#include <tinyexr.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace candela;

namespace {

struct Input {
    std::string name;
    std::vector<uint8_t> bytes;
};

std::vector<float> bigMap(uint32_t width, uint32_t height) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> noise(0.9f, 1.1f);
    std::vector<float> rgb(size_t(width) * height * 3);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            float* t = &rgb[(size_t(y) * width + x) * 3];
            const float sky = 0.2f + 2.0f * float(height - y) / float(height);
            t[0] = sky * 0.6f * noise(rng);
            t[1] = sky * 0.8f * noise(rng);
            t[2] = sky * noise(rng);
        }
    return rgb;
}

std::vector<Input> writeInputs(const fs::path& out, const std::vector<std::string>& hdrs) {
    std::vector<Input> inputs;
    for (const std::string& hdr : hdrs) {
        const assets::Environment env = assets::loadEnvironment(hdr);
        inputs.push_back({fs::path(hdr).stem().string() + ".exr",
                          test::makeExr(env.width, env.height, test::rgbChannels(env.rgb, test::ExrType::Half))});
    }
    const std::vector<float> big = bigMap(4096, 2048);
    for (Imf::Compression compression : {Imf::NO_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION})
        inputs.push_back({"float_4096x2048_" + test::compressionName(compression) + ".exr",
                          test::makeExr(4096, 2048, test::rgbChannels(big, test::ExrType::Float), {compression})});
    fs::create_directories(out);
    for (const Input& input : inputs) {
        std::ofstream file(out / input.name, std::ios::binary);
        file.write(reinterpret_cast<const char*>(input.bytes.data()), std::streamsize(input.bytes.size()));
    }
    return inputs;
}

template <typename F>
double milliseconds(F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: candela_exr_read_bench OUT_DIR [rounds] FILE.hdr...\n");
        return 2;
    }
    int first = 2, rounds = 7;
    if (std::isdigit(static_cast<unsigned char>(argv[2][0]))) rounds = std::max(1, std::atoi(argv[first++]));
    try {
        const std::vector<Input> inputs = writeInputs(argv[1], std::vector<std::string>(argv + first, argv + argc));
        std::vector<std::vector<double>> ours(inputs.size()), theirs(inputs.size());
        for (int round = 0; round < rounds; ++round)
            for (size_t i = 0; i < inputs.size(); ++i) {
                const std::vector<uint8_t>& bytes = inputs[i].bytes;
                theirs[i].push_back(milliseconds([&] {
                    float* rgba = nullptr;
                    int w = 0, h = 0;
                    const char* error = nullptr;
                    if (LoadEXRFromMemory(&rgba, &w, &h, bytes.data(), bytes.size(), &error) != TINYEXR_SUCCESS)
                        throw std::runtime_error(inputs[i].name + ": tinyexr: " + (error ? error : "?"));
                    std::free(rgba);
                }));
                ours[i].push_back(milliseconds([&] { assets::decodeExr(bytes, inputs[i].name, {}); }));
            }
        std::printf("| file | size | tinyexr 1.0.1 (ms) | Candela/OpenEXR 3.1 (ms) | OpenEXR / tinyexr |\n|---|---|---|---|---|\n");
        for (size_t i = 0; i < inputs.size(); ++i) {
            const double t = median(theirs[i]), o = median(ours[i]);
            std::printf("| %s | %.1f MB | %.1f | %.1f | %.2f |\n", inputs[i].name.c_str(), double(inputs[i].bytes.size()) / 1e6, t, o, o / t);
        }
        std::printf("(median of %d alternated rounds)\n", rounds);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "candela_exr_read_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
