#include "geometry/image_mips.h"

#include "core/parallel_for.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
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
    const int linearLightChannels = image.srgb ? 3 : 0;  // RGB of sRGB images are averaged in linear light
    const uint8_t* above = image.rgba8.data();
    size_t abovePitch = size_t(image.width) * 4;
    uint32_t width = image.width, height = image.height;
    for (const TexelLevel& mip : mips) {
        const uint32_t w = mip.width, h = mip.height;
        // An exact halving: each texel the box of the 2 × 2 above it.
        const auto halvedTexel = [&](uint32_t x, uint32_t y, uint8_t* out) {
            const uint8_t* top = above + size_t(2 * y) * abovePitch + size_t(2 * x) * 4;
            const uint8_t* bottom = top + abovePitch;
            int c = 0;
            for (; c < linearLightChannels; ++c)
                out[c] = tables.encode(0.25f * (tables.linear[top[c]] + tables.linear[top[4 + c]] + tables.linear[bottom[c]] +
                                                tables.linear[bottom[4 + c]]));
            for (; c < 4; ++c) out[c] = quarterRoundedToEven(uint32_t(top[c]) + top[4 + c] + bottom[c] + bottom[4 + c]);
        };
        // Otherwise (an odd size): where a texel's centre falls in the level above (texel units,
        // centres at i + 0.5), the pair of texels a linear filter mixes there and the second one's
        // weight, clamped at the edges.
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
        const bool halved = 2 * w == width && 2 * h == height;
        const std::vector<Tap> columns = halved ? std::vector<Tap>{} : taps(w, width);
        const std::vector<Tap> rows = halved ? std::vector<Tap>{} : taps(h, height);
        const auto filteredTexel = [&](uint32_t x, uint32_t y, uint8_t* out) {
            const Tap& tx = columns[x];
            const Tap& ty = rows[y];
            const std::array<const uint8_t*, 4> source = {
                above + ty.first * abovePitch + size_t(tx.first) * 4, above + ty.first * abovePitch + size_t(tx.second) * 4,
                above + ty.second * abovePitch + size_t(tx.first) * 4, above + ty.second * abovePitch + size_t(tx.second) * 4};
            const std::array<float, 4> weight = {(1.0f - tx.weight) * (1.0f - ty.weight), tx.weight * (1.0f - ty.weight),
                                                 (1.0f - tx.weight) * ty.weight, tx.weight * ty.weight};
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
        };
        parallelForRows(w, h, [&](uint32_t y) {
            for (uint32_t x = 0; x < w; ++x) {
                uint8_t* out = mip.row(y) + size_t(x) * 4;
                halved ? halvedTexel(x, y, out) : filteredTexel(x, y, out);
            }
        });
        above = mip.data;
        abovePitch = mip.rowPitch;
        width = w, height = h;
    }
}

std::vector<std::vector<uint8_t>> boxMipChain(const scene::Image& image) {
    std::vector<std::vector<uint8_t>> mips;
    writeBoxMipChain(image, packedLevels(image.width, image.height, 1, mips));
    return mips;
}

}  // namespace candela::geometry
