#include "geometry/normal_map_mips.h"

#include "core/parallel_for.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstring>

namespace candela::geometry {

namespace {

// The nearest code of value ∈ [0, 1] (clamped), halves rounded up: std::lround's result without its
// library call (v − ⌊v⌋ is exact for v ≥ 0).
uint8_t encode(float value) {
    const float v = std::clamp(value, 0.0f, 1.0f) * 255.0f;
    const uint32_t whole = uint32_t(v);
    return uint8_t(whole + (v - float(whole) >= 0.5f ? 1u : 0u));
}

// A normal map's code c decoded to c / 127.5 − 1, as a table (the same division, done once per code).
struct Decoded {
    std::array<float, 256> value{};
    Decoded() {
        for (int c = 0; c < 256; ++c) value[size_t(c)] = float(c) / 127.5f - 1.0f;
    }
};

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
        const glm::vec3 n(decoded.value[t[0]], decoded.value[t[1]], decoded.value[t[2]]);
        const float length = glm::length(n);
        return length > 1e-6f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
    };
    // The mean unit normal per texel of the level above (from mip 1 on; mip 0's is unitNormal).
    std::vector<glm::vec3> mean;
    uint32_t width = image.width, height = image.height;
    for (size_t level = 1; level < levels.size(); ++level) {
        const TexelLevel& mip = levels[level];
        const uint32_t w = mip.width, h = mip.height;
        std::vector<glm::vec3> next(size_t(w) * h);
        // Each row's texels depend on the level above alone: the result does not depend on the threads.
        parallelForRows(w, h, [&](uint32_t y) {
            uint8_t* out = mip.row(y);
            for (uint32_t x = 0; x < w; ++x) {
                glm::vec3 sum(0.0f);
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx) {
                        const uint32_t sx = std::min(2 * x + dx, width - 1), sy = std::min(2 * y + dy, height - 1);
                        sum += level == 1 ? unitNormal(sx, sy) : mean[size_t(sy) * width + sx];
                    }
                const glm::vec3 m = sum * 0.25f;
                next[size_t(y) * w + x] = m;
                const float length = glm::length(m);
                const glm::vec3 direction = length > 1e-6f ? m / length : glm::vec3(0.0f, 0.0f, 1.0f);
                uint8_t* texel = out + size_t(x) * 4;
                texel[0] = encode(direction.x * 0.5f + 0.5f);
                texel[1] = encode(direction.y * 0.5f + 0.5f);
                texel[2] = encode(direction.z * 0.5f + 0.5f);
                texel[3] = encode(length);
            }
        });
        mean = std::move(next);
        width = w, height = h;
    }
}

std::vector<std::vector<uint8_t>> normalMapMipChain(const scene::Image& image) {
    std::vector<std::vector<uint8_t>> mips;
    writeNormalMapMipChain(image, packedLevels(image.width, image.height, 0, mips));
    return mips;
}

}  // namespace candela::geometry
