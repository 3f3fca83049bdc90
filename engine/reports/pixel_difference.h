#pragma once
// The plain per-pixel numbers `candela diff` reports beside ꟻLIP (docs/pipelines.md#candela-diff):
// PSNR, the largest channel difference, and the pixels whose largest channel difference passes a
// threshold — the gate of Filament's renderdiff (a pixel fails when a channel differs by more
// than maxAbsDiff; an image fails when more than maxFailingPixelsFraction of its pixels fail).
// RGB only: alpha is not compared.

#include <cstdint>
#include <span>

namespace candela::reports {

struct PixelDifference {
    double psnr = 0.0;                  // dB; +∞ when the images are equal
    double maxChannelDifference = 0.0;  // the largest |reference − test| over every RGB value
    uint64_t pixelsOverThreshold = 0;   // pixels whose largest channel difference is > the threshold
    double fractionOverThreshold = 0.0; // pixelsOverThreshold / pixels (0 for an empty image)
};

// 8-bit RGB images (3 bytes a pixel): differences in levels 0…255, PSNR = 10 log10(255² / MSE)
// with MSE over every RGB value. Precondition: equal sizes, a multiple of 3 (std::invalid_argument).
PixelDifference pixelDifference(std::span<const uint8_t> reference, std::span<const uint8_t> test, double thresholdLevels);

// Linear float RGB images (3 floats a pixel): differences in linear units; PSNR = 10 log10(peak² /
// MSE) with peak the larger of 1 (display white) and the reference's largest RGB value.
// Non-finite values count as 0. Precondition as above.
PixelDifference pixelDifference(std::span<const float> reference, std::span<const float> test, double threshold);

}  // namespace candela::reports
