#include "reports/ibl_errors.h"

#include "reports/ibl_reference.h"
#include "shared/ibl.h"

#include <glm/gtc/packing.hpp>
#include <vulkan/vulkan_core.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>

namespace candela::reports {

static_assert(kFormatRg16Sfloat == VK_FORMAT_R16G16_SFLOAT);
static_assert(kFormatRgba16Sfloat == VK_FORMAT_R16G16B16A16_SFLOAT);
static_assert(kFormatRgba32Sfloat == VK_FORMAT_R32G32B32A32_SFLOAT);

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxRelativeFloor = 1e-2;  // × mean(ref)
constexpr double kMinNoV = 1e-4;            // CANDELA_MIN_NOV of the LUT shader

uint32_t mipExtent(uint32_t extent, uint32_t mip) { return mip >= 32 ? 1u : std::max(extent >> mip, 1u); }

// a / b for errors: 0 when a = 0 (equal values), +Inf when only b = 0.
double ratio(double a, double b) { return a == 0.0 ? 0.0 : (b > 0.0 ? a / b : kInf); }

// ---- Texel decoding ----

uint32_t formatTexelBytes(uint32_t format) {
    switch (format) {
        case kFormatRg16Sfloat: return 4;
        case kFormatRgba16Sfloat: return 8;
        case kFormatRgba32Sfloat: return 16;
        default: throw std::invalid_argument("ibl errors: unsupported texel format " + std::to_string(format));
    }
}

void checkFormat(const ibl::CachedImage& image) {
    if (formatTexelBytes(image.format) != image.texelBytes)
        throw std::invalid_argument("ibl errors: " + image.name + ": texelBytes " + std::to_string(image.texelBytes) +
                                    " disagrees with format " + std::to_string(image.format));
}

size_t mipOffset(const ibl::CachedImage& image, uint32_t mip) {
    size_t offset = 0;
    for (uint32_t m = 0; m < mip; ++m)
        offset += size_t(mipExtent(image.width, m)) * mipExtent(image.height, m) * image.layers * image.texelBytes;
    return offset;
}

glm::vec4 decode(uint32_t format, const std::byte* texel) {
    if (format == kFormatRgba32Sfloat) {
        glm::vec4 value;
        std::memcpy(&value[0], texel, sizeof(value));
        return value;
    }
    std::array<uint16_t, 4> halves{};
    std::memcpy(halves.data(), texel, format == kFormatRg16Sfloat ? 4 : 8);
    const auto half = [&](size_t i) { return glm::unpackHalf1x16(halves[i]); };
    if (format == kFormatRg16Sfloat) return {half(0), half(1), 0.0f, 1.0f};
    return {half(0), half(1), half(2), half(3)};
}

glm::dvec3 rgb(const glm::vec4& v) { return {double(v.r), double(v.g), double(v.b)}; }

// ---- Image shapes ----

void checkCube(const ibl::CachedImage& image) {
    checkFormat(image);
    if (image.layers != 6 || image.width != image.height || image.width == 0 || image.mips == 0)
        throw std::invalid_argument("ibl errors: " + image.name + " is not a cube (6 square layers)");
}

void checkSh(const ibl::CachedImage& image) {
    checkFormat(image);
    if (image.format != kFormatRgba32Sfloat || image.width != 9 || image.height != 1 || image.layers != 1)
        throw std::invalid_argument("ibl errors: " + image.name + " is not 9 RGBA32F SH coefficients");
}

void checkLut(const ibl::CachedImage& image) {
    checkFormat(image);
    if (image.width < 2 || image.width != image.height || image.layers != 1)
        throw std::invalid_argument("ibl errors: " + image.name + " is not a square LUT of size ≥ 2");
}

// ---- Cube geometry ----

// Face and face coordinates (s, t) ∈ [−1, 1]² of a direction: the inverse of cubeFaceDirection.
struct FacePoint {
    uint32_t face;
    double s, t;
};

FacePoint facePoint(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x > 0.0 ? FacePoint{0, -d.z / a.x, -d.y / a.x} : FacePoint{1, d.z / a.x, -d.y / a.x};
    if (a.y >= a.z) return d.y > 0.0 ? FacePoint{2, d.x / a.y, d.z / a.y} : FacePoint{3, d.x / a.y, -d.z / a.y};
    return d.z > 0.0 ? FacePoint{4, d.x / a.z, -d.y / a.z} : FacePoint{5, -d.x / a.z, -d.y / a.z};
}

// Texel-space position of face coordinate c ∈ [−1, 1] on a face of `size` texels: the texel
// centres around it (i0 ∈ [−1, size − 1], i1 = i0 + 1 ≤ size) and the weight of i1.
struct Lerp {
    int64_t i0, i1;
    double f;
};

Lerp lerpAt(double c, uint32_t size) {
    const double p = (c + 1.0) * 0.5 * size - 0.5;
    const double i0 = std::floor(p);
    return {int64_t(i0), int64_t(i0) + 1, p - i0};
}

// The texel containing face coordinate c ∈ [−1, 1].
uint32_t texelIndex(double c, uint32_t size) {
    return uint32_t(std::clamp((c + 1.0) * 0.5 * size, 0.0, double(size - 1)));
}

// Texel (i, j) of `face`, where i or j may be one beyond the face (−1 or size): then the texel of
// the adjacent face that contains the extrapolated texel centre, as seamless cube filtering does.
glm::dvec4 cubeTexel(const ibl::CachedImage& image, uint32_t mip, uint32_t size, uint32_t face, int64_t i, int64_t j) {
    if (i >= 0 && j >= 0 && i < size && j < size) return texelValue(image, mip, face, uint32_t(i), uint32_t(j));
    const glm::vec2 uv((float(i) + 0.5f) / float(size), (float(j) + 0.5f) / float(size));
    const FacePoint p = facePoint(glm::dvec3(shading::cubeFaceDirection(face, uv)));
    return texelValue(image, mip, p.face, texelIndex(p.s, size), texelIndex(p.t, size));
}

// ---- Statistics ----

struct Accumulator {  // Σ and max of squared / absolute errors over finite values
    double sumSquares = 0.0, max = 0.0;
    void add(double error) {
        sumSquares += error * error;
        max = std::max(max, std::abs(error));
    }
    double rms(uint32_t n) const { return n > 0 ? std::sqrt(sumSquares / n) : 0.0; }
};

// ---- Reference environment ----

// The source cells of [0, n) that output cell i of m covers, [i·n/m, (i + 1)·n/m) in source units,
// each with the overlap's `measure(lo, hi)` (lo, hi in source units).
struct Overlap {
    uint32_t index;
    double weight;
};

template <class Measure>
std::vector<Overlap> overlaps(uint32_t i, uint32_t n, uint32_t m, Measure&& measure) {
    const double lo = double(i) * n / m, hi = double(i + 1) * n / m;
    std::vector<Overlap> cells;
    for (uint32_t j = uint32_t(std::floor(lo)); j < n && j < hi; ++j) {
        const double a = std::max(lo, double(j)), b = std::min(hi, double(j) + 1.0);
        if (b > a) cells.push_back({j, measure(a, b)});
    }
    return cells;
}

glm::dvec3 sourceTexel(const assets::Environment& env, uint32_t x, uint32_t y) {
    const float* t = env.texel(x, y);
    return {double(t[0]), double(t[1]), double(t[2])};
}

// Output row `row` of `out`: per source column the Ω-weighted sum over the covered rows (weight
// cos θ0 − cos θ1 of the overlap), then per output texel the width-weighted sum over columns.
void downsampleRow(const assets::Environment& env, assets::Environment& out, uint32_t row) {
    const double H = env.height;
    const std::vector<Overlap> rows = overlaps(row, env.height, out.height, [H](double a, double b) {
        return std::cos(std::numbers::pi * a / H) - std::cos(std::numbers::pi * b / H);
    });
    std::vector<glm::dvec3> columnSums(env.width, glm::dvec3(0.0));
    double rowWeight = 0.0;
    for (const Overlap& r : rows) {
        rowWeight += r.weight;
        for (uint32_t x = 0; x < env.width; ++x) columnSums[x] += r.weight * sourceTexel(env, x, r.index);
    }
    for (uint32_t X = 0; X < out.width; ++X) {
        glm::dvec3 sum(0.0);
        double weight = 0.0;
        for (const Overlap& c : overlaps(X, env.width, out.width, [](double a, double b) { return b - a; })) {
            sum += c.weight * columnSums[c.index];
            weight += c.weight;
        }
        const glm::dvec3 mean = sum / (weight * rowWeight);
        float* texel = out.texel(X, row);
        for (int k = 0; k < 3; ++k) texel[k] = float(mean[k]);
    }
}

// ---- Comparisons ----

LevelErrors specularLevel(const ibl::CachedImage& cube, uint32_t mip, const assets::Environment& original,
                          const assets::Environment& reference, uint32_t texelsPerLevel, ReferenceCache& cache) {
    const uint32_t size = mipExtent(cube.width, mip);
    const uint32_t denominator = std::max(cube.mips - 1, 1u);
    const uint32_t g = std::gcd(mip, denominator);
    const double roughness = double(mip) / denominator;
    std::vector<double> gpu, ref;
    for (uint32_t index : specularSampleTexels(size, texelsPerLevel)) {
        const uint32_t face = index / (size * size), x = index % size, y = index / size % size;
        gpu.push_back(luminance(rgb(texelValue(cube, mip, face, x, y))));
        const ReferenceCache::Key key{uint32_t(ReferenceCache::Kind::Specular), size, mip / g, denominator / g, index};
        const glm::dvec3 value = cache.get(key, [&] {
            const glm::dvec3 d = cubeTexelDirection(face, x, y, size);
            return mip == 0 ? reference::bilinear(original, d) : reference::prefiltered(reference, d, roughness);
        });
        ref.push_back(luminance(value));
    }
    return {float(roughness), size, errorStats(gpu, ref)};
}

glm::dvec3 evaluateSh(const ibl::CachedImage& sh, const glm::dvec3& n) {
    const std::array<double, 9> basis = reference::shBasis(n);
    glm::dvec3 e(0.0);
    for (uint32_t i = 0; i < 9; ++i) e += rgb(texelValue(sh, 0, 0, i, 0)) * basis[i];
    // max(e, 0) as the shader does, but a NaN stays NaN (to be reported).
    for (int k = 0; k < 3; ++k) e[k] = e[k] < 0.0 ? 0.0 : e[k];
    return e;
}

// Evaluates the irradiance map in a unit direction.
std::function<glm::dvec3(const glm::dvec3&)> irradianceEvaluator(const ibl::CachedImage& image) {
    if (image.name == "irradiance_sh") {
        checkSh(image);
        return [&image](const glm::dvec3& n) { return evaluateSh(image, n); };
    }
    if (image.name == "irradiance_cube") {
        checkCube(image);
        return [&image](const glm::dvec3& n) { return rgb(sampleCube(image, 0, n)); };
    }
    throw std::invalid_argument("ibl errors: not an irradiance map: " + image.name);
}

std::vector<uint32_t> lutGrid(uint32_t size, uint32_t stride) {
    std::vector<uint32_t> grid;
    for (uint64_t i = 0; i < size; i += stride) grid.push_back(uint32_t(i));
    if (grid.back() != size - 1) grid.push_back(size - 1);
    return grid;
}

}  // namespace

// ---- Statistics ----

double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

ErrorStats errorStats(std::span<const double> gpu, std::span<const double> ref) {
    if (gpu.size() != ref.size()) throw std::invalid_argument("errorStats: gpu and ref differ in length");
    ErrorStats stats;
    stats.count = uint32_t(gpu.size());
    double sumRef = 0.0, sumSquares = 0.0;
    uint32_t n = 0;
    for (size_t i = 0; i < gpu.size(); ++i) {
        if (!std::isfinite(gpu[i])) {
            stats.finite = false;
            continue;
        }
        sumRef += ref[i];
        sumSquares += (gpu[i] - ref[i]) * (gpu[i] - ref[i]);
        ++n;
    }
    if (n == 0) return stats;
    const double mean = sumRef / n;
    stats.rmse = ratio(std::sqrt(sumSquares / n), mean);
    double sumRelative = 0.0;
    for (size_t i = 0; i < gpu.size(); ++i) {
        if (!std::isfinite(gpu[i])) continue;
        const double relative = ratio(std::abs(gpu[i] - ref[i]), ref[i] + kMaxRelativeFloor * mean);
        stats.maxRelative = std::max(stats.maxRelative, relative);
        sumRelative += relative;
    }
    stats.meanRelative = sumRelative / n;
    return stats;
}

// ---- Reference ----

assets::Environment referenceEnvironment(const assets::Environment& env, uint32_t maxWidth) {
    if (env.width == 0 || env.height == 0 || env.rgb.size() != env.texelCount() * 3)
        throw std::invalid_argument("referenceEnvironment: empty environment");
    if (maxWidth == 0) throw std::invalid_argument("referenceEnvironment: maxWidth is 0");
    uint32_t width = env.width, height = env.height;
    while (width > maxWidth) {
        width = (width + 1) / 2;
        height = (height + 1) / 2;
    }
    if (width == env.width) return env;
    assets::Environment out;
    out.source = env.source;
    out.width = width;
    out.height = height;
    out.rgb.resize(out.texelCount() * 3);
    for (uint32_t y = 0; y < height; ++y) downsampleRow(env, out, y);
    return out;
}

glm::dvec3 ReferenceCache::get(const Key& key, const std::function<glm::dvec3()>& compute) {
    if (const auto found = mValues.find(key); found != mValues.end()) {
        ++mHits;
        return found->second;
    }
    return mValues.emplace(key, compute()).first->second;
}

void ReferenceCache::checkEnvironment(const assets::Environment& reference) {
    if (mWidth == 0) {
        mWidth = reference.width;
        mHeight = reference.height;
    } else if (reference.width != mWidth || reference.height != mHeight) {
        throw std::invalid_argument("ReferenceCache: used with a " + std::to_string(reference.width) + "×" +
                                    std::to_string(reference.height) + " environment, made for " +
                                    std::to_string(mWidth) + "×" + std::to_string(mHeight));
    }
}

// ---- Comparisons ----

std::vector<LevelErrors> specularErrors(const ibl::CachedImage& specular, const assets::Environment& original,
                                        const assets::Environment& reference, uint32_t texelsPerLevel,
                                        ReferenceCache& cache) {
    checkCube(specular);
    cache.checkEnvironment(reference);
    std::vector<LevelErrors> levels;
    for (uint32_t mip = 0; mip < specular.mips; ++mip)
        levels.push_back(specularLevel(specular, mip, original, reference, texelsPerLevel, cache));
    return levels;
}

ErrorStats irradianceErrors(const ibl::CachedImage& irradiance, const assets::Environment& reference, uint32_t directions,
                            ReferenceCache& cache) {
    const auto evaluate = irradianceEvaluator(irradiance);
    cache.checkEnvironment(reference);
    std::vector<double> gpu, ref;
    for (uint32_t i = 0; i < directions; ++i) {
        const glm::dvec3 d = fibonacciDirection(i, directions);
        gpu.push_back(luminance(evaluate(d)));
        const ReferenceCache::Key key{uint32_t(ReferenceCache::Kind::Irradiance), directions, 0, 1, i};
        ref.push_back(luminance(cache.get(key, [&] { return reference::irradiance(reference, d); })));
    }
    return errorStats(gpu, ref);
}

LutErrors lutErrors(const ibl::CachedImage& lut, uint32_t stride) {
    checkLut(lut);
    if (stride == 0) throw std::invalid_argument("lutErrors: stride is 0");
    const uint32_t size = lut.width;
    const std::vector<uint32_t> grid = lutGrid(size, stride);
    Accumulator a, b, sum;
    LutErrors errors;
    uint32_t finite = 0;
    for (uint32_t y : grid) {
        for (uint32_t x : grid) {
            const glm::vec4 gpu = texelValue(lut, 0, 0, x, y);
            ++errors.count;
            if (!std::isfinite(gpu.x) || !std::isfinite(gpu.y)) {
                errors.finite = false;
                continue;
            }
            ++finite;
            const double NoV = std::max(double(x) / (size - 1), kMinNoV);
            const reference::SplitSum ref = reference::splitSum(NoV, double(y) / (size - 1));
            a.add(gpu.x - ref.a);
            b.add(gpu.y - ref.b);
            sum.add(double(gpu.x) + gpu.y - (ref.a + ref.b));
        }
    }
    errors.maxA = a.max, errors.maxB = b.max, errors.maxSum = sum.max;
    errors.rmsA = a.rms(finite), errors.rmsB = b.rms(finite), errors.rmsSum = sum.rms(finite);
    return errors;
}

// ---- Helpers ----

glm::vec4 texelValue(const ibl::CachedImage& image, uint32_t mip, uint32_t layer, uint32_t x, uint32_t y) {
    checkFormat(image);
    if (mip >= image.mips || layer >= image.layers) throw std::out_of_range("texelValue: no such mip or layer");
    const uint32_t w = mipExtent(image.width, mip), h = mipExtent(image.height, mip);
    if (x >= w || y >= h) throw std::out_of_range("texelValue: texel outside " + image.name);
    const size_t offset = mipOffset(image, mip) + ((size_t(layer) * h + y) * w + x) * image.texelBytes;
    if (offset + image.texelBytes > image.data.size())
        throw std::out_of_range("texelValue: " + image.name + " is too short");
    return decode(image.format, image.data.data() + offset);
}

glm::dvec3 cubeTexelDirection(uint32_t face, uint32_t x, uint32_t y, uint32_t faceSize) {
    const glm::vec2 uv((float(x) + 0.5f) / float(faceSize), (float(y) + 0.5f) / float(faceSize));
    return glm::normalize(glm::dvec3(shading::cubeFaceDirection(face, uv)));
}

glm::vec4 sampleCube(const ibl::CachedImage& image, uint32_t mip, const glm::dvec3& direction) {
    if (direction == glm::dvec3(0.0)) throw std::invalid_argument("sampleCube: zero direction");
    const FacePoint p = facePoint(direction);
    const uint32_t size = mipExtent(image.width, mip);
    const Lerp u = lerpAt(p.s, size), v = lerpAt(p.t, size);
    const auto at = [&](int64_t x, int64_t y) { return cubeTexel(image, mip, size, p.face, x, y); };
    const glm::dvec4 top = at(u.i0, v.i0) * (1.0 - u.f) + at(u.i1, v.i0) * u.f;
    const glm::dvec4 bottom = at(u.i0, v.i1) * (1.0 - u.f) + at(u.i1, v.i1) * u.f;
    return glm::vec4(top * (1.0 - v.f) + bottom * v.f);
}

std::vector<uint32_t> specularSampleTexels(uint32_t faceSize, uint32_t count) {
    if (faceSize == 0) return {};
    const uint64_t faceTexels = uint64_t(faceSize) * faceSize;
    const uint64_t n = std::min<uint64_t>(count, 6 * faceTexels);
    uint64_t stride = uint64_t(std::llround(0.6180339887498949 * double(faceTexels)));
    while (std::gcd(stride, faceTexels) != 1) ++stride;
    const uint64_t centre = uint64_t(faceSize / 2) * faceSize + faceSize / 2;
    std::vector<uint32_t> texels;
    texels.reserve(size_t(n));
    for (uint64_t k = 0; k < n; ++k)
        texels.push_back(uint32_t((k % 6) * faceTexels + (centre + (k / 6) * stride) % faceTexels));
    return texels;
}

glm::dvec3 fibonacciDirection(uint32_t i, uint32_t n) {
    const double goldenFraction = 0.6180339887498949;  // φ − 1
    const double y = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double turns = std::fmod(double(i) * goldenFraction, 1.0);
    const double phi = 2.0 * std::numbers::pi * turns;
    return {r * std::cos(phi), y, r * std::sin(phi)};
}

}  // namespace candela::reports
