#include "ibl_maps/bright_texels.h"

#include "reports/ibl_reference.h"
#include "shared/ibl.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>

namespace candela::ibl_maps {

double brightCandidateLuminance(uint32_t width, uint32_t height, const std::function<double(size_t)>& luminance) {
    double power = 0.0, solidAngle = 0.0;
    for (uint32_t y = 0; y < height; ++y) {
        const double rowAngle = reports::reference::texelSolidAngle(y, width, height);
        double row = 0.0;
        for (uint32_t x = 0; x < width; ++x) row += luminance(size_t(y) * width + x);
        power += row * rowAngle;
        solidAngle += rowAngle * width;
    }
    return kBrightTexelFactor * power / solidAngle;
}

BrightTexels findBrightTexels(std::span<const uint16_t> rgba, uint32_t width, uint32_t height, float scale,
                              uint32_t maxCount) {
    BrightTexels result;
    if (maxCount == 0) return result;
    const auto radiance = [&](size_t i) {
        return glm::vec3(glm::unpackHalf1x16(rgba[i * 4]), glm::unpackHalf1x16(rgba[i * 4 + 1]),
                         glm::unpackHalf1x16(rgba[i * 4 + 2]));
    };
    const auto luminance = [&](size_t i) { return shading::iblLuminance(radiance(i)); };
    const double candidate = brightCandidateLuminance(width, height, luminance);
    std::vector<uint32_t> bright;
    for (uint32_t i = 0; i < uint32_t(size_t(width) * height); ++i)
        if (luminance(i) > candidate) bright.push_back(i);
    if (bright.empty()) return result;
    const auto brighter = [&](uint32_t a, uint32_t b) { return luminance(a) > luminance(b); };
    float threshold = float(candidate);
    if (bright.size() > maxCount) {
        std::nth_element(bright.begin(), bright.begin() + maxCount, bright.end(), brighter);
        threshold = luminance(bright[maxCount]);
        bright.resize(maxCount);
        // Ties with the brightest texel left out are not over the threshold: nothing to split.
        std::erase_if(bright, [&](uint32_t i) { return !(luminance(i) > threshold); });
    }
    std::sort(bright.begin(), bright.end());
    result.threshold = threshold;
    result.buffer.front().x = float(bright.size());
    for (uint32_t i : bright) {
        const uint32_t x = i % width, y = i / width;
        const glm::vec3 excess = radiance(i) - shading::iblClampLuminance(radiance(i), threshold);
        const double texelAngle = reports::reference::texelSolidAngle(y, width, height);
        result.buffer.emplace_back(glm::vec3(reports::reference::texelDirection(x, y, width, height)), 0.0f);
        result.buffer.emplace_back(glm::vec3(glm::dvec3(excess) * (texelAngle / scale)), 0.0f);
    }
    return result;
}

}  // namespace candela::ibl_maps
