#pragma once
// Image error for reports and tests (`candela quality-report`): linear HDR images (RGBA float,
// premultiplied, top row first) box-downsampled and display-encoded the way the tonemap pass
// encodes them (PBR Neutral at exposure 0, sRGB, 8 bits), and compared in display values.

#include <cstdint>
#include <vector>

namespace candela::reports {

struct FloatImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // width × height × 4
};

// The mean of each factor × factor block (linear, premultiplied: what a supersampled reference
// averages). Precondition: width and height are multiples of factor ≥ 1.
FloatImage boxDownsample(const FloatImage& image, uint32_t factor);

// RGB display values 0..255 (3 per pixel): PBR Neutral tone mapping of the premultiplied colour
// over black, then the sRGB transfer function, rounded.
std::vector<uint8_t> displayEncode(const FloatImage& image);

struct DisplayError {
    double mean = 0.0;  // mean absolute difference over every RGB value, in levels of 255
    double p99 = 0.0;   // 99th percentile over pixels of the largest channel difference
};

// Differences between two display images of the same size (displayEncode's layout).
DisplayError displayError(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b);

// The same over several pairs (frames of a sequence): the mean over every value, the 99th
// percentile over every pixel of every pair. Precondition: a.size() == b.size().
DisplayError displayError(const std::vector<std::vector<uint8_t>>& a, const std::vector<std::vector<uint8_t>>& b);

// Mean absolute difference between consecutive frames of a sequence (levels of 255, over every RGB
// value): over a slow camera orbit, motion plus shimmer. 0 for fewer than 2 frames.
double meanFrameToFrameDifference(const std::vector<std::vector<uint8_t>>& frames);

// The flicker a sequence has and its reference does not: the mean absolute difference between the
// frame-to-frame changes of `frames` and of `reference` (levels of 255, over every RGB value of
// every consecutive pair). Motion both share cancels; shimmer and crawling edges remain.
// Precondition: as many frames as the reference, of its size.
double meanTemporalError(const std::vector<std::vector<uint8_t>>& frames, const std::vector<std::vector<uint8_t>>& reference);

}  // namespace candela::reports
