#include "reports/flip.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <thread>

namespace candela::reports {
namespace {

// The HPG 2020 paper's constants: colour pipeline exponent q_c and the error remapping (a colour
// difference of p_c × the largest one maps to p_t), the feature filter width w (degrees) and its
// exponent q_f.
constexpr float kQc = 0.7f, kPc = 0.4f, kPt = 0.95f, kW = 0.082f, kQf = 0.5f;
constexpr float kPi = std::numbers::pi_v<float>;

// The contrast sensitivity functions as Gaussians a·√(π/b)·exp(−π²x²/b), x in degrees: one for
// the achromatic channel, one for red-green and a sum of two for blue-yellow.
constexpr float kAY = 1.0f, kBY = 0.0047f;
constexpr float kACx = 1.0f, kBCx = 0.0053f;
constexpr float kACz1 = 34.1f, kBCz1 = 0.04f, kACz2 = 13.5f, kBCz2 = 0.025f;

// CIE D65 white, and its inverse, in XYZ.
constexpr float kWhite[3] = {0.950428545f, 1.0f, 1.088900371f};
constexpr float kInvWhite[3] = {1.052156925f, 1.0f, 0.918357670f};

struct Vec3 {
    float x, y, z;
};

// Linear sRGB (Rec. 709 primaries, D65) ↔ CIE XYZ.
Vec3 linearRgbToXyz(Vec3 c) {
    return {(10135552.0f / 24577794.0f) * c.x + (8788810.0f / 24577794.0f) * c.y + (4435075.0f / 24577794.0f) * c.z,
            (2613072.0f / 12288897.0f) * c.x + (8788810.0f / 12288897.0f) * c.y + (887015.0f / 12288897.0f) * c.z,
            (1425312.0f / 73733382.0f) * c.x + (8788810.0f / 73733382.0f) * c.y + (70074185.0f / 73733382.0f) * c.z};
}

Vec3 xyzToLinearRgb(Vec3 c) {
    return {3.241003275f * c.x - 1.537398934f * c.y - 0.498615861f * c.z,
            -0.969224334f * c.x + 1.875930071f * c.y + 0.041554224f * c.z,
            0.055639423f * c.x - 0.204011202f * c.y + 1.057148933f * c.z};
}

// YCxCz: the linearized CIELab of the paper (Lab without the cube root).
Vec3 xyzToYcxcz(Vec3 c) {
    const float x = c.x * kInvWhite[0], y = c.y * kInvWhite[1], z = c.z * kInvWhite[2];
    return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

Vec3 ycxczToXyz(Vec3 c) {
    const float y = (c.x + 16.0f) / 116.0f;
    return {(y + c.y / 500.0f) * kWhite[0], y * kWhite[1], (y - c.z / 200.0f) * kWhite[2]};
}

// The cube root as powf(t, 1/3), as the authors' implementation takes it: std::cbrt differs in the
// last bit now and then, and HyAB's cancellation between close colours magnifies that to 1e-5.
Vec3 xyzToLab(Vec3 c) {
    constexpr float delta = 6.0f / 29.0f, deltaCube = delta * delta * delta;
    constexpr float factor = 1.0f / (3.0f * delta * delta), term = 4.0f / 29.0f;
    const auto f = [&](float t) { return t > deltaCube ? std::pow(t, 1.0f / 3.0f) : factor * t + term; };
    const float x = f(c.x * kInvWhite[0]), y = f(c.y * kInvWhite[1]), z = f(c.z * kInvWhite[2]);
    return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

// Lab with a and b scaled by 0.01 L (the Hunt effect: chroma matters less in the dark).
Vec3 huntLab(Vec3 linearRgb) {
    const Vec3 lab = xyzToLab(linearRgbToXyz(linearRgb));
    return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z};
}

// HyAB: city-block in lightness, Euclidean in chroma.
float hyab(Vec3 a, Vec3 b) {
    return std::fabs(a.x - b.x) + std::sqrt((a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

// One-dimensional filter taps, centre at index radius.
struct Kernel {
    int radius = 0;
    std::vector<float> taps;
};

// The spatial (contrast sensitivity) filters, sampled at 1/ppd degrees: Y and Cx each sum to 1;
// the two blue-yellow ones are scaled together so that the 2D filter they make, g₁(x)g₁(y) +
// g₂(x)g₂(y), sums to 1 (each 1D tap is the square root of a·√(π/b) times the exponential).
struct SpatialKernels {
    Kernel y, cx, cz1, cz2;
};

SpatialKernels spatialKernels(float ppd) {
    const float largestB = std::max({kBY, kBCx, kBCz1, kBCz2});
    const int radius = int(std::ceil(3.0f * std::sqrt(largestB / (2.0f * kPi * kPi)) * ppd));
    SpatialKernels k;
    for (Kernel* kernel : {&k.y, &k.cx, &k.cz1, &k.cz2}) *kernel = {radius, std::vector<float>(size_t(2 * radius + 1))};
    const auto gaussian = [](float x2, float a, float b) { return a * std::sqrt(kPi / b) * std::exp(-kPi * kPi * x2 / b); };
    const auto gaussianRoot = [](float x2, float a, float b) { return std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x2 / b); };
    float sumY = 0.0f, sumCx = 0.0f, sumCz1 = 0.0f, sumCz2 = 0.0f;
    for (int i = 0; i <= 2 * radius; ++i) {
        const float x = float(i - radius) / ppd;
        const float x2 = x * x;
        sumY += k.y.taps[i] = gaussian(x2, kAY, kBY);
        sumCx += k.cx.taps[i] = gaussian(x2, kACx, kBCx);
        sumCz1 += k.cz1.taps[i] = gaussianRoot(x2, kACz1, kBCz1);
        sumCz2 += k.cz2.taps[i] = gaussianRoot(x2, kACz2, kBCz2);
    }
    const float czScale = 1.0f / std::sqrt(sumCz1 * sumCz1 + sumCz2 * sumCz2);
    for (int i = 0; i <= 2 * radius; ++i) {
        k.y.taps[i] *= 1.0f / sumY;
        k.cx.taps[i] *= 1.0f / sumCx;
        k.cz1.taps[i] *= czScale;
        k.cz2.taps[i] *= czScale;
    }
    return k;
}

// The feature filters: a Gaussian of standard deviation w/2 degrees and its first and second
// derivatives, in pixels. The Gaussian sums to 1; the derivatives' positive taps sum to 1 and
// their negative taps to −1.
struct FeatureKernels {
    Kernel g, dg, ddg;
};

FeatureKernels featureKernels(float ppd) {
    const float sigma = 0.5f * kW * ppd;
    const int radius = int(std::ceil(3.0f * sigma));
    FeatureKernels k;
    for (Kernel* kernel : {&k.g, &k.dg, &k.ddg}) *kernel = {radius, std::vector<float>(size_t(2 * radius + 1))};
    float sum = 0.0f, dgPositive = 0.0f, dgNegative = 0.0f, ddgPositive = 0.0f, ddgNegative = 0.0f;
    for (int i = 0; i <= 2 * radius; ++i) {
        const float x = float(i - radius);
        const float g = std::exp(-(x * x) / (2.0f * sigma * sigma));
        const float dg = -x * g;
        const float ddg = (x * x / (sigma * sigma) - 1.0f) * g;
        sum += g;
        (dg > 0.0f ? dgPositive : dgNegative) += std::fabs(dg);
        (ddg > 0.0f ? ddgPositive : ddgNegative) += std::fabs(ddg);
        k.g.taps[i] = g;
        k.dg.taps[i] = dg;
        k.ddg.taps[i] = ddg;
    }
    // Below about 1.7 pixels per degree the Gaussian's outer taps underflow to 0 and a derivative
    // has no taps of one sign: it stays 0 rather than dividing by 0.
    const auto normalize = [](float tap, float positive, float negative) {
        const float side = tap > 0.0f ? positive : negative;
        return side > 0.0f ? tap / side : 0.0f;
    };
    for (int i = 0; i <= 2 * radius; ++i) {
        k.g.taps[i] /= sum;
        k.dg.taps[i] = normalize(k.dg.taps[i], dgPositive, dgNegative);
        k.ddg.taps[i] = normalize(k.ddg.taps[i], ddgPositive, ddgNegative);
    }
    return k;
}

// One channel of an image, row after row.
struct Plane {
    uint32_t width = 0, height = 0;
    std::vector<float> values;
    Plane(uint32_t w, uint32_t h) : width(w), height(h), values(size_t(w) * h) {}
    float* row(uint32_t y) { return values.data() + size_t(y) * width; }
    const float* row(uint32_t y) const { return values.data() + size_t(y) * width; }
};

// Horizontal convolution, the image clamped to its edge. Each output sums its taps in order
// (loops over taps outside, pixels inside, so that the pixels vectorize).
Plane convolveRows(const Plane& in, const Kernel& kernel) {
    Plane out(in.width, in.height);
    const int r = kernel.radius;
    std::vector<float> padded(in.width + 2 * size_t(r));
    for (uint32_t y = 0; y < in.height; ++y) {
        const float* src = in.row(y);
        for (size_t i = 0; i < padded.size(); ++i)
            padded[i] = src[std::clamp<int64_t>(int64_t(i) - r, 0, int64_t(in.width) - 1)];
        float* dst = out.row(y);
        std::fill(dst, dst + in.width, 0.0f);
        for (int t = 0; t <= 2 * r; ++t) {
            const float weight = kernel.taps[t];
            const float* p = padded.data() + t;
            for (uint32_t x = 0; x < in.width; ++x) dst[x] += weight * p[x];
        }
    }
    return out;
}

// Row y of the vertical convolution of `in`, into `out` (width floats), the image clamped to its edge.
void convolveColumnsRow(const Plane& in, const Kernel& kernel, uint32_t y, float* out) {
    std::fill(out, out + in.width, 0.0f);
    for (int t = 0; t <= 2 * kernel.radius; ++t) {
        const float weight = kernel.taps[t];
        const float* src = in.row(uint32_t(std::clamp<int64_t>(int64_t(y) + t - kernel.radius, 0, int64_t(in.height) - 1)));
        for (uint32_t x = 0; x < in.width; ++x) out[x] += weight * src[x];
    }
}

// An image in YCxCz, one plane per channel.
struct YcxczImage {
    Plane y, cx, cz;
};

YcxczImage toYcxcz(const RgbImage& image) {
    YcxczImage out{Plane(image.width, image.height), Plane(image.width, image.height), Plane(image.width, image.height)};
    const auto unit = [](float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f; };
    for (size_t p = 0; p < out.y.values.size(); ++p) {
        const float* c = &image.rgb[p * 3];
        const Vec3 v = xyzToYcxcz(linearRgbToXyz({unit(c[0]), unit(c[1]), unit(c[2])}));
        out.y.values[p] = v.x;
        out.cx.values[p] = v.y;
        out.cz.values[p] = v.z;
    }
    return out;
}

// The colour difference of each pixel after spatial filtering, remapped to [0, 1].
Plane colorDifference(const YcxczImage& reference, const YcxczImage& test, float ppd) {
    const SpatialKernels k = spatialKernels(ppd);
    const float cmax = std::pow(hyab(huntLab({0.0f, 1.0f, 0.0f}), huntLab({0.0f, 0.0f, 1.0f})), kQc);
    const float pccmax = kPc * cmax;
    struct Horizontal {
        Plane y, cx, cz1, cz2;
    };
    const auto horizontal = [&](const YcxczImage& image) {
        return Horizontal{convolveRows(image.y, k.y), convolveRows(image.cx, k.cx), convolveRows(image.cz, k.cz1),
                          convolveRows(image.cz, k.cz2)};
    };
    const Horizontal ref = horizontal(reference), tst = horizontal(test);
    const uint32_t w = reference.y.width;
    Plane out(w, reference.y.height);
    std::vector<float> rows(size_t(w) * 8);
    float* r[4] = {&rows[0], &rows[w], &rows[2 * size_t(w)], &rows[3 * size_t(w)]};
    float* t[4] = {&rows[4 * size_t(w)], &rows[5 * size_t(w)], &rows[6 * size_t(w)], &rows[7 * size_t(w)]};
    for (uint32_t y = 0; y < out.height; ++y) {
        for (auto [h, o] : {std::pair{&ref, r}, std::pair{&tst, t}}) {
            convolveColumnsRow(h->y, k.y, y, o[0]);
            convolveColumnsRow(h->cx, k.cx, y, o[1]);
            convolveColumnsRow(h->cz1, k.cz1, y, o[2]);
            convolveColumnsRow(h->cz2, k.cz2, y, o[3]);
        }
        float* dst = out.row(y);
        for (uint32_t x = 0; x < w; ++x) {
            // Back to linear RGB, clamped to what a display shows, then into Hunt-adjusted Lab.
            const auto filtered = [x](float* const* c) {
                const Vec3 rgb = xyzToLinearRgb(ycxczToXyz({c[0][x], c[1][x], c[2][x] + c[3][x]}));
                return huntLab({std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f), std::clamp(rgb.z, 0.0f, 1.0f)});
            };
            const float difference = std::pow(hyab(filtered(r), filtered(t)), kQc);
            dst[x] = difference < pccmax ? difference * (kPt / pccmax)
                                         : kPt + ((difference - pccmax) / (cmax - pccmax)) * (1.0f - kPt);
        }
    }
    return out;
}

// Combines the colour difference with the edge and point feature difference of the
// achromatic channels: error = colour^(1 − feature). Writes into `error`.
void combineWithFeatures(const Plane& referenceY, const Plane& testY, float ppd, const Plane& color, std::vector<float>& error) {
    const FeatureKernels k = featureKernels(ppd);
    struct Horizontal {
        Plane dx, ddx, gx;
    };
    const auto horizontal = [&](const Plane& y) {
        Plane normalized(y.width, y.height);  // Y of YCxCz to [0, 1]
        for (size_t p = 0; p < y.values.size(); ++p) normalized.values[p] = y.values[p] * (1.0f / 116.0f) + 16.0f / 116.0f;
        return Horizontal{convolveRows(normalized, k.dg), convolveRows(normalized, k.ddg), convolveRows(normalized, k.g)};
    };
    const Horizontal ref = horizontal(referenceY), tst = horizontal(testY);
    const uint32_t w = referenceY.width;
    std::vector<float> rows(size_t(w) * 8);
    float* r[4] = {&rows[0], &rows[w], &rows[2 * size_t(w)], &rows[3 * size_t(w)]};
    float* t[4] = {&rows[4 * size_t(w)], &rows[5 * size_t(w)], &rows[6 * size_t(w)], &rows[7 * size_t(w)]};
    const float normalization = 1.0f / std::sqrt(2.0f);
    for (uint32_t y = 0; y < referenceY.height; ++y) {
        for (auto [h, o] : {std::pair{&ref, r}, std::pair{&tst, t}}) {
            convolveColumnsRow(h->dx, k.g, y, o[0]);   // edge, x
            convolveColumnsRow(h->gx, k.dg, y, o[1]);  // edge, y
            convolveColumnsRow(h->ddx, k.g, y, o[2]);  // point, x
            convolveColumnsRow(h->gx, k.ddg, y, o[3]); // point, y
        }
        const float* c = color.row(y);
        float* dst = error.data() + size_t(y) * w;
        for (uint32_t x = 0; x < w; ++x) {
            const float edge = std::fabs(std::sqrt(r[0][x] * r[0][x] + r[1][x] * r[1][x]) - std::sqrt(t[0][x] * t[0][x] + t[1][x] * t[1][x]));
            const float point = std::fabs(std::sqrt(r[2][x] * r[2][x] + r[3][x] * r[3][x]) - std::sqrt(t[2][x] * t[2][x] + t[3][x] * t[3][x]));
            const float feature = std::pow(normalization * std::max(edge, point), kQf);
            dst[x] = std::pow(c[x], 1.0f - feature);
        }
    }
}

void checkPair(const RgbImage& reference, const RgbImage& test, float ppd) {
    if (reference.width != test.width || reference.height != test.height)
        throw std::invalid_argument("flip: the images differ in size");
    if (reference.rgb.size() != size_t(reference.width) * reference.height * 3 || test.rgb.size() != reference.rgb.size())
        throw std::invalid_argument("flip: the pixel data does not match the size");
    if (!(ppd > 0.0f) || !std::isfinite(ppd)) throw std::invalid_argument("flip: pixels per degree must be > 0");
}

// Tone-mapper coefficients: (c₀x² + c₁x + c₂) / (c₃x² + c₄x + c₅).
constexpr float kTone[6] = {0.6f * 0.6f * 2.51f, 0.6f * 0.03f, 0.0f, 0.6f * 0.6f * 2.43f, 0.6f * 0.59f, 0.14f};

float luminance(const float* rgb) { return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]; }

}  // namespace

float pixelsPerDegree(const ViewingConditions& viewing) {
    return viewing.monitorDistance * (viewing.monitorResolution / viewing.monitorWidth) * (kPi / 180.0f);
}

std::vector<float> ldrFlip(const RgbImage& reference, const RgbImage& test, float ppd) {
    checkPair(reference, test, ppd);
    std::vector<float> error(size_t(reference.width) * reference.height);
    if (error.empty()) return error;
    const YcxczImage ref = toYcxcz(reference), tst = toYcxcz(test);
    const Plane color = colorDifference(ref, tst, ppd);
    combineWithFeatures(ref.y, tst.y, ppd, color, error);
    return error;
}

float flipToneMap(float x) {
    return ((x * x) * kTone[0] + x * kTone[1] + kTone[2]) / ((x * x) * kTone[3] + x * kTone[4] + kTone[5]);
}

FlipExposures flipExposures(const RgbImage& reference) {
    // The radiance the tone mapper maps to t = 0.85: the larger root of
    // (c₀ − t c₃)x² + (c₁ − t c₄)x + (c₂ − t c₅) = 0.
    constexpr float t = 0.85f;
    const float a = kTone[0] - t * kTone[3], b = kTone[1] - t * kTone[4], c = kTone[2] - t * kTone[5];
    const float half = -0.5f * (b / a);
    const float x85 = half + std::sqrt(half * half - c / a);

    std::vector<float> luminances(size_t(reference.width) * reference.height);
    float largest = 0.0f, smallestPositive = INFINITY;
    for (size_t p = 0; p < luminances.size(); ++p) {
        const float y = luminance(&reference.rgb[p * 3]);
        luminances[p] = std::isfinite(y) ? y : 0.0f;
        largest = std::max(largest, luminances[p]);
        if (luminances[p] > 0.0f) smallestPositive = std::min(smallestPositive, luminances[p]);
    }
    if (!(largest > 0.0f)) return {};
    const size_t middle = luminances.size() / 2;
    std::nth_element(luminances.begin(), luminances.begin() + ptrdiff_t(middle), luminances.end());
    const float median = luminances[middle] > 0.0f ? luminances[middle] : smallestPositive;
    FlipExposures exposures{float(std::log2(x85 / largest)), float(std::log2(x85 / median)), 2};
    exposures.count = uint32_t(std::clamp(std::ceil(exposures.stop - exposures.start), 2.0f, float(kMaxFlipExposures)));
    return exposures;
}

std::vector<float> hdrFlip(const RgbImage& reference, const RgbImage& test, float ppd, const FlipExposures& exposures) {
    checkPair(reference, test, ppd);
    if (exposures.count < 2) throw std::invalid_argument("flip: at least two exposures");
    const size_t pixels = size_t(reference.width) * reference.height;
    if (pixels == 0) return {};
    // The exposures are independent: each thread takes every T-th and keeps its own maximum.
    const uint32_t threads = std::clamp(std::thread::hardware_concurrency(), 1u, exposures.count);
    std::vector<std::vector<float>> errors(threads, std::vector<float>(pixels, 0.0f));
    const auto work = [&](uint32_t thread) {
        RgbImage exposedReference = reference, exposedTest = test;
        for (uint32_t i = thread; i < exposures.count; i += threads) {
            const float scale = std::pow(2.0f, exposures.exposure(i));
            for (auto [in, out] : {std::pair{&reference, &exposedReference}, std::pair{&test, &exposedTest}})
                for (size_t v = 0; v < in->rgb.size(); ++v) out->rgb[v] = std::clamp(flipToneMap(in->rgb[v] * scale), 0.0f, 1.0f);
            const std::vector<float> exposed = ldrFlip(exposedReference, exposedTest, ppd);
            for (size_t p = 0; p < pixels; ++p) errors[thread][p] = std::max(errors[thread][p], exposed[p]);
        }
    };
    {
        std::vector<std::jthread> workers;
        for (uint32_t t = 1; t < threads; ++t) workers.emplace_back(work, t);
        work(0);
    }
    for (uint32_t t = 1; t < threads; ++t)
        for (size_t p = 0; p < pixels; ++p) errors[0][p] = std::max(errors[0][p], errors[t][p]);
    return std::move(errors[0]);
}

FlipStatistics flipStatistics(std::span<const float> error) {
    FlipStatistics s;
    if (error.empty()) return s;
    // Non-negative floats order as their bit patterns: buckets by the top 16 bits hold ordered
    // ranges, so a weighted percentile needs only its own bucket sorted, not the whole map.
    constexpr size_t kBuckets = 1 << 16;
    std::vector<double> bucketSum(kBuckets, 0.0);
    const auto value = [](float e) { return std::isfinite(e) ? std::max(e, 0.0f) : 0.0f; };
    const auto bucket = [](float v) { return std::bit_cast<uint32_t>(v) >> 16; };
    double total = 0.0;
    s.min = INFINITY;
    for (float raw : error) {
        const float e = value(raw);
        total += e;
        bucketSum[bucket(e)] += e;
        s.min = std::min(s.min, double(e));
        s.max = std::max(s.max, double(e));
        ++s.histogram[std::min<size_t>(size_t(e * float(s.histogram.size())), s.histogram.size() - 1)];
    }
    s.mean = total / double(error.size());
    // The first value, in increasing order, at which the running sum passes fraction × total.
    const auto weightedPercentile = [&](double fraction) {
        double running = 0.0;
        for (uint32_t b = 0; b < kBuckets; ++b) {
            if (running + bucketSum[b] <= fraction * total) {
                running += bucketSum[b];
                continue;
            }
            std::vector<float> values;
            for (float raw : error)
                if (bucket(value(raw)) == b) values.push_back(value(raw));
            std::sort(values.begin(), values.end());
            for (float e : values)
                if ((running += e) > fraction * total) return double(e);
            return double(values.back());  // rounding left the crossing just past the bucket
        }
        return 0.0;
    };
    s.weightedQuartile1 = weightedPercentile(0.25);
    s.weightedMedian = weightedPercentile(0.5);
    s.weightedQuartile3 = weightedPercentile(0.75);
    return s;
}

float srgbToLinear(uint8_t value) {
    const float v = float(value) / 255.0f;
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace candela::reports
