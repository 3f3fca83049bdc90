#include "geometry/image_mips.h"

#include "core/parallel_for.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela::geometry {

namespace {

// sRGB code → linear, and the linear values halfway between consecutive codes: the nearest code of
// a linear value is the number of midpoints at or below it. `start` holds that number at the start
// of each of kCells equal cells of [0, 1]; a cell (6.1e-5 wide) holds at most one midpoint (the
// closest two lie 3.0e-4 apart), so a lookup and one comparison find the code.
struct SrgbTables {
    static constexpr uint32_t kCells = 1u << 14;
    std::array<float, 256> linear{};
    std::array<float, 256> midpoints{};  // [255]: +∞
    std::array<uint8_t, kCells + 1> start{};
    SrgbTables() {
        const auto decode = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
        for (int c = 0; c < 256; ++c) linear[size_t(c)] = float(decode(c / 255.0));
        for (int c = 0; c < 255; ++c) midpoints[size_t(c)] = float(decode((c + 0.5) / 255.0));
        midpoints[255] = std::numeric_limits<float>::infinity();
        for (uint32_t i = 0; i <= kCells; ++i)
            start[i] = uint8_t(std::upper_bound(midpoints.begin(), midpoints.begin() + 255, float(i) / float(kCells)) - midpoints.begin());
    }
    uint8_t encode(float value) const {
        if (!(value > 0.0f)) return 0;
        if (value >= 1.0f) return 255;
        const uint32_t code = start[uint32_t(value * float(kCells))];
        // At most one midpoint lies in the cell: one comparison, without a branch (midpoints[255] is
        // past every value).
        return uint8_t(code + (midpoints[code] <= value ? 1u : 0u));
    }
};

// The nearest integer to sum / 4, ties to even (no bias): up when the remainder is 3, or 2 with q
// odd — without a branch (texture data makes it unpredictable).
uint8_t quarterRoundedToEven(uint32_t sum) {
    const uint32_t q = sum >> 2, r = sum & 3u;
    return uint8_t(q + uint32_t(r + (q & 1u) > 2u));
}

const SrgbTables& srgbTables() {
    static const SrgbTables tables;
    return tables;
}

// Vectors of 16 bytes and of 16 × 16 bits (GCC/Clang vector extensions: SSE2 on x86-64, NEON on
// Arm, plain code elsewhere).
using Bytes16 = uint8_t __attribute__((vector_size(16)));
using Shorts16 = uint16_t __attribute__((vector_size(32)));

// One row of an exactly halved UNORM level: out's w texels, each the 2 × 2 box of texels 2x and
// 2x + 1 of the rows `top` and `bottom` above, every channel rounded as quarterRoundedToEven. Four
// texels at a time in vectors: (s + 1 + ⌊s/4⌋ mod 2) / 4, truncated, is that rounding.
void halveRowUnorm(const uint8_t* top, const uint8_t* bottom, uint8_t* out, uint32_t w) {
    uint32_t x = 0;
    for (; x + 4 <= w; x += 4) {
        Bytes16 t0, t1, b0, b1;
        std::memcpy(&t0, top + size_t(x) * 8, 16);
        std::memcpy(&t1, top + size_t(x) * 8 + 16, 16);
        std::memcpy(&b0, bottom + size_t(x) * 8, 16);
        std::memcpy(&b1, bottom + size_t(x) * 8 + 16, 16);
        // Columns summed: texels 2x … 2x + 3 in v0, 2x + 4 … 2x + 7 in v1, 4 channels each.
        const Shorts16 v0 = __builtin_convertvector(t0, Shorts16) + __builtin_convertvector(b0, Shorts16);
        const Shorts16 v1 = __builtin_convertvector(t1, Shorts16) + __builtin_convertvector(b1, Shorts16);
        const Shorts16 even = __builtin_shufflevector(v0, v1, 0, 1, 2, 3, 8, 9, 10, 11, 16, 17, 18, 19, 24, 25, 26, 27);
        const Shorts16 odd = __builtin_shufflevector(v0, v1, 4, 5, 6, 7, 12, 13, 14, 15, 20, 21, 22, 23, 28, 29, 30, 31);
        const Shorts16 sum = even + odd;
        const Bytes16 rounded = __builtin_convertvector((sum + 1 + ((sum >> 2) & 1)) >> 2, Bytes16);
        std::memcpy(out + size_t(x) * 4, &rounded, 16);
    }
    for (; x < w; ++x) {
        const uint8_t* t = top + size_t(x) * 8;
        const uint8_t* b = bottom + size_t(x) * 8;
        for (int c = 0; c < 4; ++c) out[size_t(x) * 4 + size_t(c)] = quarterRoundedToEven(uint32_t(t[c]) + t[4 + c] + b[c] + b[4 + c]);
    }
}

// The same for an sRGB level: RGB averaged in linear light (the sum in this order, then the
// quarter), A as halveRowUnorm's.
void halveRowSrgb(const SrgbTables& tables, const uint8_t* top, const uint8_t* bottom, uint8_t* out, uint32_t w) {
    const float* linear = tables.linear.data();
    for (uint32_t x = 0; x < w; ++x) {
        const uint8_t* t = top + size_t(x) * 8;
        const uint8_t* b = bottom + size_t(x) * 8;
        uint8_t* o = out + size_t(x) * 4;
        for (int c = 0; c < 3; ++c) o[c] = tables.encode(0.25f * (linear[t[c]] + linear[t[4 + c]] + linear[b[c]] + linear[b[4 + c]]));
        o[3] = quarterRoundedToEven(uint32_t(t[3]) + t[7] + b[3] + b[7]);
    }
}

// A level of an odd size from the one above: each texel the bilinear sample of `above` at its
// centre, clamped at the edges, RGB in linear light when srgb, as writeBoxMipChain says.
void writeFilteredLevel(const SrgbTables& tables, bool srgb, const TexelLevel& above, const TexelLevel& mip) {
    // Where a texel's centre falls in the level above (texel units, centres at i + 0.5): the pair
    // of texels a linear filter mixes there and the second one's weight, clamped at the edges.
    struct Tap {
        uint32_t first, second;
        float weight;
    };
    const auto taps = [](uint32_t to, uint32_t from) {
        std::vector<Tap> out(to);
        for (uint32_t i = 0; i < to; ++i) {
            const double u = (i + 0.5) * double(from) / double(to) - 0.5;
            const double base = std::floor(u);
            const auto clampTo = [&](double v) { return uint32_t(std::clamp(v, 0.0, double(from - 1))); };
            out[i] = {clampTo(base), clampTo(base + 1.0), float(u - base)};
        }
        return out;
    };
    const std::vector<Tap> columns = taps(mip.width, above.width);
    const std::vector<Tap> rows = taps(mip.height, above.height);
    const int linearLightChannels = srgb ? 3 : 0;
    parallelForRows(mip.width, mip.height, [&](uint32_t y) {
        const Tap& ty = rows[y];
        for (uint32_t x = 0; x < mip.width; ++x) {
            const Tap& tx = columns[x];
            const std::array<const uint8_t*, 4> source = {above.row(ty.first) + size_t(tx.first) * 4, above.row(ty.first) + size_t(tx.second) * 4,
                                                          above.row(ty.second) + size_t(tx.first) * 4, above.row(ty.second) + size_t(tx.second) * 4};
            const std::array<float, 4> weight = {(1.0f - tx.weight) * (1.0f - ty.weight), tx.weight * (1.0f - ty.weight),
                                                 (1.0f - tx.weight) * ty.weight, tx.weight * ty.weight};
            uint8_t* out = mip.row(y) + size_t(x) * 4;
            for (int c = 0; c < 4; ++c) {
                float sum = 0.0f;
                if (c < linearLightChannels) {
                    for (int k = 0; k < 4; ++k) sum += weight[size_t(k)] * tables.linear[source[size_t(k)][c]];
                    out[c] = tables.encode(sum);
                } else {
                    for (int k = 0; k < 4; ++k) sum += weight[size_t(k)] * float(source[size_t(k)][c]);
                    out[c] = uint8_t(std::nearbyint(sum));  // ties to even: no bias
                }
            }
        }
    });
}
}  // namespace

uint32_t mipLevelCount(uint32_t width, uint32_t height) { return std::bit_width(std::max({width, height, 1u})); }

std::vector<TexelLevel> packedLevels(uint32_t width, uint32_t height, uint32_t first, std::vector<std::vector<uint8_t>>& storage) {
    const uint32_t levels = mipLevelCount(width, height);
    storage.assign(levels > first ? levels - first : 0, {});
    std::vector<TexelLevel> views;
    for (uint32_t level = first; level < levels; ++level) {
        const uint32_t w = std::max(1u, width >> level), h = std::max(1u, height >> level);
        std::vector<uint8_t>& texels = storage[level - first];
        texels.resize(size_t(w) * h * 4);
        views.push_back({texels.data(), size_t(w) * 4, w, h});
    }
    return views;
}

void checkMipLevels(uint32_t width, uint32_t height, uint32_t first, std::span<const TexelLevel> levels, const char* what) {
    const uint32_t count = mipLevelCount(width, height);
    if (levels.size() + first != count)
        throw std::invalid_argument(std::string(what) + ": " + std::to_string(levels.size()) + " level views for " +
                                    std::to_string(count - first) + " levels");
    for (uint32_t i = 0; i < levels.size(); ++i) {
        const TexelLevel& l = levels[i];
        const uint32_t level = first + i;
        if (l.width != std::max(1u, width >> level) || l.height != std::max(1u, height >> level) || l.rowPitch < size_t(l.width) * 4 ||
            !l.data)
            throw std::invalid_argument(std::string(what) + ": level " + std::to_string(level) + "'s view does not fit it");
    }
}

void writeBoxMipChain(const scene::Image& image, std::span<const TexelLevel> mips) {
    checkMipLevels(image.width, image.height, 1, mips, "writeBoxMipChain");
    const SrgbTables& tables = srgbTables();
    TexelLevel above{const_cast<uint8_t*>(image.rgba8.data()), size_t(image.width) * 4, image.width, image.height};
    for (const TexelLevel& mip : mips) {
        if (2 * mip.width == above.width && 2 * mip.height == above.height) {
            // An exact halving: each texel the box of the 2 × 2 above it.
            parallelForRows(mip.width, mip.height, [&](uint32_t y) {
                const uint8_t* top = above.row(2 * y);
                image.srgb ? halveRowSrgb(tables, top, top + above.rowPitch, mip.row(y), mip.width)
                           : halveRowUnorm(top, top + above.rowPitch, mip.row(y), mip.width);
            });
        } else {
            writeFilteredLevel(tables, image.srgb, above, mip);
        }
        above = mip;
    }
}

std::vector<std::vector<uint8_t>> boxMipChain(const scene::Image& image) {
    std::vector<std::vector<uint8_t>> mips;
    writeBoxMipChain(image, packedLevels(image.width, image.height, 1, mips));
    return mips;
}

}  // namespace candela::geometry
