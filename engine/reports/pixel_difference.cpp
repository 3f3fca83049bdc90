#include "reports/pixel_difference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace candela::reports {
namespace {

template <class T, class Value>
PixelDifference difference(std::span<const T> reference, std::span<const T> test, double threshold, double peak, Value value) {
    if (reference.size() != test.size() || reference.size() % 3)
        throw std::invalid_argument("pixelDifference: the images differ in size");
    PixelDifference d;
    double squares = 0.0;
    for (size_t i = 0; i < reference.size(); i += 3) {
        double pixel = 0.0;
        for (size_t c = 0; c < 3; ++c) {
            const double delta = std::fabs(value(reference[i + c]) - value(test[i + c]));
            squares += delta * delta;
            pixel = std::max(pixel, delta);
        }
        d.maxChannelDifference = std::max(d.maxChannelDifference, pixel);
        if (pixel > threshold) ++d.pixelsOverThreshold;
    }
    const size_t pixels = reference.size() / 3;
    d.fractionOverThreshold = pixels ? double(d.pixelsOverThreshold) / double(pixels) : 0.0;
    d.psnr = squares > 0.0 ? 10.0 * std::log10(peak * peak / (squares / double(reference.size()))) : INFINITY;
    return d;
}

double finite(float v) { return std::isfinite(v) ? double(v) : 0.0; }

}  // namespace

PixelDifference pixelDifference(std::span<const uint8_t> reference, std::span<const uint8_t> test, double thresholdLevels) {
    return difference(reference, test, thresholdLevels, 255.0, [](uint8_t v) { return double(v); });
}

PixelDifference pixelDifference(std::span<const float> reference, std::span<const float> test, double threshold) {
    double peak = 1.0;
    for (float v : reference) peak = std::max(peak, finite(v));
    return difference(reference, test, threshold, peak, finite);
}

}  // namespace candela::reports
