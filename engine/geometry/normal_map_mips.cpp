#include "geometry/normal_map_mips.h"

#include "core/parallel_for.h"
#include "core/process_memory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

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

// Four texels' floats, channel by channel (a structure of arrays), for mip 1, whose texels are
// each the mean of four of mip 0's unit normals: most of a chain's work. Each lane's arithmetic is
// the scalar code's above, operation for operation, so the texels are the same (ImageMips pins them).
// A texel read as one 32-bit word has R in its low byte on little-endian machines only; elsewhere
// the one-texel code does the whole level.
using Uints4 = uint32_t __attribute__((vector_size(16)));
constexpr bool kTexelWordsLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
constexpr Floats4 kOnes{1.0f, 1.0f, 1.0f, 1.0f};

// Each lane's square root, correctly rounded (as std::sqrt).
Floats4 sqrt4(Floats4 v) {
#if defined(__SSE__)
    return _mm_sqrt_ps(v);
#else
    for (int i = 0; i < 4; ++i) v[i] = std::sqrt(v[i]);
    return v;
#endif
}

// Lanes 0, 2, 4, 6 (even) or 1, 3, 5, 7 (odd) of a and b taken together.
Uints4 evenLanes(Uints4 a, Uints4 b) { return __builtin_shufflevector(a, b, 0, 2, 4, 6); }
Uints4 oddLanes(Uints4 a, Uints4 b) { return __builtin_shufflevector(a, b, 1, 3, 5, 7); }

struct Vectors4 {
    Floats4 x, y, z;
};

Floats4 length4(const Vectors4& v) { return sqrt4((v.x * v.x + v.y * v.y) + v.z * v.z); }
// v over `length`, or (0, 0, 1) where that is 1e-6 or less (direction3, lane by lane).
Vectors4 direction4(const Vectors4& v, Floats4 length) {
    const Ints4 valid = length > 1e-6f;
    return {valid ? v.x / length : Floats4{}, valid ? v.y / length : Floats4{}, valid ? v.z / length : kOnes};
}

// The unit normals of four RGBA8 texels (decoded by the table, then direction3 of length3).
Vectors4 unitNormals4(const Decoded& decoded, Uints4 texels) {
    const auto channel = [&](uint32_t shift) {
        const Uints4 c = (texels >> shift) & 0xffu;
        return Floats4{decoded.value[c[0]], decoded.value[c[1]], decoded.value[c[2]], decoded.value[c[3]]};
    };
    const Vectors4 n{channel(0), channel(8), channel(16)};
    return direction4(n, length4(n));
}

// A channel's code as encodeTexel rounds it: clamped to [0, 1], times 255, halves up.
Uints4 code4(Floats4 v) {
    v = v < 0.0f ? Floats4{} : v;
    v = v > 1.0f ? kOnes : v;
    v *= 255.0f;
    const Ints4 whole = __builtin_convertvector(v, Ints4);
    return Uints4(whole - (v - __builtin_convertvector(whole, Floats4) >= 0.5f));
}

// Mip 1's texels [x0, x0 + 4) of a row, from the rows of mip 0 above it (row0, and row1: the next,
// or row0 again at the bottom edge): their texels into `out` (the row, RGBA8) and their means into
// `means` (the row's), as the scalar loop writes them. Precondition: 2 · x0 + 8 ≤ the image's width.
void meanTexels4(const Decoded& decoded, const uint8_t* row0, const uint8_t* row1, uint32_t x0, uint8_t* out, Floats4* means) {
    Vectors4 sum{};  // summed as the scalar loop sums: row 0's left, its right, row 1's left, its right
    for (const uint8_t* row : {row0, row1}) {
        Uints4 a, b;
        std::memcpy(&a, row + size_t(2 * x0) * 4, sizeof a);
        std::memcpy(&b, row + size_t(2 * x0 + 4) * 4, sizeof b);
        for (const Vectors4& n : {unitNormals4(decoded, evenLanes(a, b)), unitNormals4(decoded, oddLanes(a, b))})
            sum = {sum.x + n.x, sum.y + n.y, sum.z + n.z};
    }
    const Vectors4 m{sum.x * 0.25f, sum.y * 0.25f, sum.z * 0.25f};
    const Floats4 length = length4(m);
    const Vectors4 d = direction4(m, length);
    const Uints4 texels =
        code4(d.x * 0.5f + 0.5f) | code4(d.y * 0.5f + 0.5f) << 8 | code4(d.z * 0.5f + 0.5f) << 16 | code4(length) << 24;
    std::memcpy(out + size_t(x0) * 4, &texels, sizeof texels);
    for (int i = 0; i < 4; ++i) means[x0 + uint32_t(i)] = Floats4{m.x[i], m.y[i], m.z[i], 0.0f};
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
            uint32_t x = 0;
            if (level == 1 && kTexelWordsLittleEndian) {
                const uint8_t* row0 = source + size_t(2 * y) * image.width * 4;
                const uint8_t* row1 = source + size_t(std::min(2 * y + 1, height - 1)) * image.width * 4;
                for (; x + 4 <= image.width / 2; x += 4) meanTexels4(decoded, row0, row1, x, out, next + size_t(y) * w);
            }
            for (; x < w; ++x) {
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
