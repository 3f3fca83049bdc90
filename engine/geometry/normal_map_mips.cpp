#include "geometry/normal_map_mips.h"

#include "core/parallel_for.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace candela::geometry {

namespace {

uint8_t encode(float value) { return uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

std::vector<std::vector<uint8_t>> normalMapMipChain(const scene::Image& image) {
    const uint32_t levels = std::bit_width(std::max(image.width, image.height));
    std::vector<std::vector<uint8_t>> mips;
    mips.push_back(image.rgba8);
    for (size_t i = 3; i < mips[0].size(); i += 4) mips[0][i] = 255;
    // The mean unit normal per texel of the current mip (mip 0: each texel's own, normalized).
    std::vector<glm::vec3> mean(size_t(image.width) * image.height);
    // Each row's texels depend on the level above alone: the result does not depend on the threads.
    parallelForRows(image.width, image.height, [&](uint32_t y) {
        for (size_t i = size_t(y) * image.width; i < size_t(y + 1) * image.width; ++i) {
            const glm::vec3 n = glm::vec3(image.rgba8[i * 4], image.rgba8[i * 4 + 1], image.rgba8[i * 4 + 2]) / 127.5f - 1.0f;
            const float length = glm::length(n);
            mean[i] = length > 1e-6f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
        }
    });
    uint32_t width = image.width, height = image.height;
    for (uint32_t level = 1; level < levels; ++level) {
        const uint32_t w = std::max(1u, width / 2), h = std::max(1u, height / 2);
        std::vector<glm::vec3> next(size_t(w) * h);
        std::vector<uint8_t> texels(next.size() * 4);
        parallelForRows(w, h, [&](uint32_t y) {
            for (uint32_t x = 0; x < w; ++x) {
                glm::vec3 sum(0.0f);
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx)
                        sum += mean[size_t(std::min(2 * y + dy, height - 1)) * width + std::min(2 * x + dx, width - 1)];
                const glm::vec3 m = sum * 0.25f;
                const size_t i = size_t(y) * w + x;
                next[i] = m;
                const float length = glm::length(m);
                const glm::vec3 direction = length > 1e-6f ? m / length : glm::vec3(0.0f, 0.0f, 1.0f);
                texels[i * 4 + 0] = encode(direction.x * 0.5f + 0.5f);
                texels[i * 4 + 1] = encode(direction.y * 0.5f + 0.5f);
                texels[i * 4 + 2] = encode(direction.z * 0.5f + 0.5f);
                texels[i * 4 + 3] = encode(length);
            }
        });
        mips.push_back(std::move(texels));
        mean = std::move(next);
        width = w, height = h;
    }
    return mips;
}

}  // namespace candela::geometry
