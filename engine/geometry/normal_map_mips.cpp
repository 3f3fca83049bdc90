#include "geometry/normal_map_mips.h"

#include "core/parallel_for.h"
#include "core/process_memory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace candela::geometry {

namespace {

// Four floats (GCC/Clang vector extensions: SSE on x86-64, NEON on Arm, plain code elsewhere). Each
// lane's arithmetic is the scalar operation's, rounded the same: the chain's texels do not depend on
// whether the vectors are real.
using Floats4 = float __attribute__((vector_size(16)));
using Ints4 = int32_t __attribute__((vector_size(16)));

// A normal map's code c decoded to c / 127.5 − 1, as a table (the same division, done once per code).
struct Decoded {
    std::array<float, 256> value{};
    Decoded() {
        for (int c = 0; c < 256; ++c) value[size_t(c)] = float(c) / 127.5f - 1.0f;
    }
};

// The length of v's first three lanes, summed as (x² + y²) + z².
float length3(Floats4 v) { return std::sqrt((v[0] * v[0] + v[1] * v[1]) + v[2] * v[2]); }

// v's first three lanes over their length; (0, 0, 1) where that is 1e-6 or less.
Floats4 direction3(Floats4 v, float length) { return length > 1e-6f ? v / length : Floats4{0.0f, 0.0f, 1.0f, 0.0f}; }

// The texel of a mean normal m of length `length`: RGB its direction · 0.5 + 0.5 and A its length,
// each the nearest code of its value clamped to [0, 1], halves rounded up (std::lround's result).
void encodeTexel(Floats4 m, float length, uint8_t* texel) {
    const Floats4 direction = direction3(m, length);
    Floats4 v = direction * 0.5f + 0.5f;
    v[3] = length;
    v = v < 0.0f ? Floats4{} : v;
    v = v > 1.0f ? Floats4{1.0f, 1.0f, 1.0f, 1.0f} : v;
    v *= 255.0f;
    const Ints4 whole = __builtin_convertvector(v, Ints4);  // truncation: v ≥ 0
    const Ints4 code = whole - (v - __builtin_convertvector(whole, Floats4) >= 0.5f);  // a true lane is −1
    for (int c = 0; c < 4; ++c) texel[c] = uint8_t(code[c]);
}

}  // namespace

void writeNormalMapMipChain(const scene::Image& image, std::span<const TexelLevel> levels) {
    checkMipLevels(image.width, image.height, 0, levels, "writeNormalMapMipChain");
    static const Decoded decoded;
    const uint8_t* source = image.rgba8.data();
    const TexelLevel& top = levels[0];
    parallelForRows(image.width, image.height, [&](uint32_t y) {
        uint8_t* out = top.row(y);
        std::memcpy(out, source + size_t(y) * image.width * 4, size_t(image.width) * 4);
        for (uint32_t x = 0; x < image.width; ++x) out[size_t(x) * 4 + 3] = 255;
    });
    // Mip 0's unit normal at texel (x, y) of the image, decoded where it is read (the first level
    // reads each texel once, but at an odd size's clamped edge).
    const auto unitNormal = [&](uint32_t x, uint32_t y) {
        const uint8_t* t = source + (size_t(y) * image.width + x) * 4;
        const Floats4 n{decoded.value[t[0]], decoded.value[t[1]], decoded.value[t[2]], 0.0f};
        return direction3(n, length3(n));
    };
    // The mean unit normal per texel of the level above (from mip 1 on; mip 0's is unitNormal), in
    // two buffers taking turns: the level written and the one above it, each written before it is
    // read. In huge pages where they pay (a 2048² map's mip 1 is 16 MiB of means).
    const auto texels = [&](size_t level) { return level < levels.size() ? size_t(levels[level].width) * levels[level].height : 0; };
    const std::array<ScratchBuffer<Floats4>, 2> means{ScratchBuffer<Floats4>(texels(1)), ScratchBuffer<Floats4>(texels(2))};
    uint32_t width = image.width, height = image.height;
    for (size_t level = 1; level < levels.size(); ++level) {
        const TexelLevel& mip = levels[level];
        const uint32_t w = mip.width, h = mip.height;
        const Floats4* mean = means[level % 2].data();  // the level above's (unused for mip 1)
        Floats4* next = means[(level + 1) % 2].data();
        // Each row's texels depend on the level above alone: the result does not depend on the threads.
        parallelForRows(w, h, [&](uint32_t y) {
            uint8_t* out = mip.row(y);
            for (uint32_t x = 0; x < w; ++x) {
                Floats4 sum{};
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx) {
                        const uint32_t sx = std::min(2 * x + dx, width - 1), sy = std::min(2 * y + dy, height - 1);
                        sum += level == 1 ? unitNormal(sx, sy) : mean[size_t(sy) * width + sx];
                    }
                const Floats4 m = sum * 0.25f;
                next[size_t(y) * w + x] = m;
                encodeTexel(m, length3(m), out + size_t(x) * 4);
            }
        });
        width = w, height = h;
    }
}

std::vector<std::vector<uint8_t>> normalMapMipChain(const scene::Image& image) {
    std::vector<std::vector<uint8_t>> mips;
    writeNormalMapMipChain(image, packedLevels(image.width, image.height, 0, mips));
    return mips;
}

}  // namespace candela::geometry
