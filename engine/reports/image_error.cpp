#include "reports/image_error.h"

#include "shared/tonemap.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace candela::reports {

FloatImage boxDownsample(const FloatImage& image, uint32_t factor) {
    if (factor == 0 || image.width % factor || image.height % factor)
        throw std::invalid_argument("boxDownsample: the size is not a multiple of the factor");
    FloatImage out{image.width / factor, image.height / factor, {}};
    out.rgba.assign(size_t(out.width) * out.height * 4, 0.0f);
    const float weight = 1.0f / float(factor * factor);
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const float* in = &image.rgba[(size_t(y) * image.width + x) * 4];
            float* o = &out.rgba[(size_t(y / factor) * out.width + x / factor) * 4];
            for (int c = 0; c < 4; ++c) o[c] += in[c] * weight;
        }
    return out;
}

std::vector<uint8_t> displayEncode(const FloatImage& image) {
    std::vector<uint8_t> out(size_t(image.width) * image.height * 3);
    for (size_t p = 0; p < size_t(image.width) * image.height; ++p) {
        const float* in = &image.rgba[p * 4];
        const glm::vec3 display = shading::srgbEncode(shading::tonemapPbrNeutral(glm::max(glm::vec3(in[0], in[1], in[2]), 0.0f)));
        for (int c = 0; c < 3; ++c) out[p * 3 + c] = uint8_t(std::lround(std::clamp(display[c], 0.0f, 1.0f) * 255.0f));
    }
    return out;
}

DisplayError displayError(const std::vector<std::vector<uint8_t>>& a, const std::vector<std::vector<uint8_t>>& b) {
    if (a.size() != b.size()) throw std::invalid_argument("displayError: different frame counts");
    std::vector<int> worst;
    double sum = 0.0;
    size_t values = 0;
    for (size_t f = 0; f < a.size(); ++f) {
        if (a[f].size() != b[f].size()) throw std::invalid_argument("displayError: different sizes");
        for (size_t i = 0; i < a[f].size(); i += 3) {
            int pixel = 0;
            for (size_t c = 0; c < 3; ++c) {
                const int d = std::abs(int(a[f][i + c]) - int(b[f][i + c]));
                sum += d;
                pixel = std::max(pixel, d);
            }
            worst.push_back(pixel);
        }
        values += a[f].size();
    }
    if (worst.empty()) return {};
    std::nth_element(worst.begin(), worst.begin() + worst.size() * 99 / 100, worst.end());
    return {sum / double(values), double(worst[worst.size() * 99 / 100])};
}

DisplayError displayError(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    return displayError(std::vector<std::vector<uint8_t>>{a}, std::vector<std::vector<uint8_t>>{b});
}

double meanFrameToFrameDifference(const std::vector<std::vector<uint8_t>>& frames) {
    if (frames.size() < 2) return 0.0;
    double sum = 0.0;
    for (size_t f = 1; f < frames.size(); ++f) sum += displayError(frames[f - 1], frames[f]).mean;
    return sum / double(frames.size() - 1);
}

double meanTemporalError(const std::vector<std::vector<uint8_t>>& frames, const std::vector<std::vector<uint8_t>>& reference) {
    if (frames.size() != reference.size()) throw std::invalid_argument("meanTemporalError: different frame counts");
    double sum = 0.0;
    size_t values = 0;
    for (size_t f = 1; f < frames.size(); ++f) {
        if (frames[f].size() != reference[f].size() || frames[f - 1].size() != frames[f].size())
            throw std::invalid_argument("meanTemporalError: different sizes");
        for (size_t i = 0; i < frames[f].size(); ++i) {
            const int change = int(frames[f][i]) - int(frames[f - 1][i]);
            const int referenceChange = int(reference[f][i]) - int(reference[f - 1][i]);
            sum += std::abs(change - referenceChange);
        }
        values += frames[f].size();
    }
    return values ? sum / double(values) : 0.0;
}

}  // namespace candela::reports
