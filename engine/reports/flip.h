#pragma once
// ꟻLIP, the perceptual difference between a reference image and a test image as a viewer flipping
// between them would see it (`candela diff`, docs/pipelines.md#candela-diff):
//   LDR-ꟻLIP: Andersson et al., "FLIP: A Difference Evaluator for Alternating Images", HPG 2020;
//   HDR-ꟻLIP: Andersson et al., "Visualizing Errors in Rendered High Dynamic Range Images",
//             Eurographics 2021 short papers.
// The error of each pixel is in [0, 1]: 0 where the images cannot be told apart, 1 for the largest
// difference (pure green against pure blue). Both images are filtered by the eye's contrast
// sensitivity at the viewing distance (pixels per degree), colours are compared in a Hunt-adjusted
// CIELab (HyAB distance), and differences at edges and points are emphasized. Filters are
// separable Gaussians (as in the authors' implementation); images are clamped to the edge.
// CPU only, single thread, float arithmetic.
//
//     const float ppd = reports::pixelsPerDegree({});              // 0.7 m, 0.7 m wide, 3840 px: ≈ 67
//     std::vector<float> error = reports::ldrFlip(reference, test, ppd);
//     reports::FlipStatistics stats = reports::flipStatistics(error);  // stats.mean: the usual summary

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace candela::reports {

// A linear RGB image: width × height × 3 floats, top row first.
struct RgbImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgb;
};

// Where the images are seen from. The defaults are the papers': a 0.7 m wide 3840-pixel monitor
// seen from 0.7 m.
struct ViewingConditions {
    float monitorDistance = 0.7f;       // metres
    float monitorWidth = 0.7f;          // metres
    float monitorResolution = 3840.0f;  // pixels across
};

// Pixels per degree of visual angle at the centre of the screen: distance × (resolution / width)
// × π / 180 (the papers' formula; ≈ 67.02 for the default conditions). Preconditions: all > 0.
float pixelsPerDegree(const ViewingConditions& viewing);

// LDR-ꟻLIP of two images of the same size holding linear RGB display values (values outside
// [0, 1] are clamped, non-finite ones read as 0): the error of each pixel, in [0, 1], width ×
// height, top row first. An 8-bit sRGB image is decoded with srgbToLinear first.
// Preconditions: the sizes are equal; ppd > 0. Throws std::invalid_argument otherwise.
std::vector<float> ldrFlip(const RgbImage& reference, const RgbImage& test, float ppd);

// The exposures HDR-ꟻLIP compares at, in stops (the images are scaled by 2^exposure).
struct FlipExposures {
    float start = 0.0f;
    float stop = 0.0f;
    uint32_t count = 2;  // ≥ 2, evenly spaced from start to stop
    float exposure(uint32_t i) const { return start + float(i) * ((stop - start) / float(count - 1)); }
};

// The exposure range the Eurographics 2021 paper derives from the reference: with x₀.₈₅ the
// radiance the tone mapper maps to 0.85, start = log2(x₀.₈₅ / largest luminance) (the brightest
// pixel is not clipped) and stop = log2(x₀.₈₅ / median luminance) (half the image is bright);
// count = max(2, ⌈stop − start⌉), about one exposure per stop. Luminance is Rec. 709
// (0.2126, 0.7152, 0.0722). Where the paper leaves it open: a median of 0 is replaced by the
// smallest positive luminance, an image without light gets start = stop = 0, and count is at
// most kMaxFlipExposures.
FlipExposures flipExposures(const RgbImage& reference);
inline constexpr uint32_t kMaxFlipExposures = 64;

// The tone mapper HDR-ꟻLIP assumes: Narkowicz's fit of ACES applied to 0.6 × x (the fit's own
// pre-exposure cancelled), per channel; not clamped.
float flipToneMap(float x);

// HDR-ꟻLIP: for each exposure e of `exposures`, both images scaled by 2^e, tone mapped
// (flipToneMap), clamped to [0, 1] and compared with LDR-ꟻLIP; each pixel's error is the largest
// over the exposures (computed on as many threads as the machine has cores, at most one per
// exposure). Preconditions as ldrFlip.
std::vector<float> hdrFlip(const RgbImage& reference, const RgbImage& test, float ppd, const FlipExposures& exposures);

// Summaries of an error map. The weighted percentiles are the reference tool's: the values sorted
// and each weighted by itself, the percentile p is the first value at which the running sum passes
// p × the total (so large errors count more than many tiny ones; 0 for a map of zeros).
struct FlipStatistics {
    double mean = 0.0;
    double min = 0.0;
    double max = 0.0;
    double weightedMedian = 0.0;
    double weightedQuartile1 = 0.0;  // 25th weighted percentile
    double weightedQuartile3 = 0.0;  // 75th weighted percentile
    std::array<uint64_t, 20> histogram{};  // pixels per error interval [i/20, (i+1)/20), 1 in the last
};
FlipStatistics flipStatistics(std::span<const float> error);

// sRGB-encoded 8-bit value → linear, the IEC 61966-2-1 curve.
float srgbToLinear(uint8_t value);

}  // namespace candela::reports
