// The error metrics of `candela ibl-report` (engine/reports/ibl_errors.h), on maps built on the CPU:
// maps holding the reference values themselves must measure ≈ 0 (only half-float rounding), and
// a single wrong texel, a wrong orientation or a NaN must show.
#include "reports/ibl_errors.h"
#include "reports/ibl_reference.h"
#include "shared/ibl.h"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>
#include <vector>

namespace candela::reports::test {
namespace {

namespace ref = reference;
constexpr double kPi = std::numbers::pi;
const double kY00 = std::sqrt(1.0 / (4.0 * kPi));
const double kY1 = std::sqrt(3.0 / (4.0 * kPi));

// ---- Building images ----

using TexelFn = std::function<glm::vec4(uint32_t mip, uint32_t layer, uint32_t x, uint32_t y)>;

void appendTexel(std::vector<std::byte>& data, uint32_t format, const glm::vec4& v) {
    const size_t at = data.size();
    if (format == kFormatRgba32Sfloat) {
        data.resize(at + 16);
        std::memcpy(data.data() + at, &v[0], 16);
        return;
    }
    const int channels = format == kFormatRg16Sfloat ? 2 : 4;
    for (int c = 0; c < channels; ++c) {
        const uint16_t h = glm::packHalf1x16(v[c]);
        data.resize(data.size() + 2);
        std::memcpy(data.data() + data.size() - 2, &h, 2);
    }
}

ibl::CachedImage makeImage(const char* name, uint32_t format, uint32_t width, uint32_t height, uint32_t layers,
                      uint32_t mips, const TexelFn& texel) {
    ibl::CachedImage image{.name = name,
                      .format = format,
                      .texelBytes = format == kFormatRg16Sfloat ? 4u : (format == kFormatRgba16Sfloat ? 8u : 16u),
                      .width = width,
                      .height = height,
                      .layers = layers,
                      .mips = mips};
    for (uint32_t m = 0; m < mips; ++m)
        for (uint32_t l = 0; l < layers; ++l)
            for (uint32_t y = 0; y < std::max(height >> m, 1u); ++y)
                for (uint32_t x = 0; x < std::max(width >> m, 1u); ++x)
                    appendTexel(image.data, format, texel(m, l, x, y));
    EXPECT_EQ(image.data.size(), image.expectedBytes());
    return image;
}

using DirectionFn = std::function<glm::dvec3(uint32_t mip, const glm::dvec3& direction)>;

// An RGBA16F cube whose texel (face, x, y) of mip m holds value(m, its centre direction).
ibl::CachedImage makeCube(const char* name, uint32_t faceSize, uint32_t mips, const DirectionFn& value) {
    return makeImage(name, kFormatRgba16Sfloat, faceSize, faceSize, 6, mips,
                     [&](uint32_t m, uint32_t face, uint32_t x, uint32_t y) {
                         const uint32_t s = std::max(faceSize >> m, 1u);
                         return glm::vec4(glm::vec3(value(m, cubeTexelDirection(face, x, y, s))), 1.0f);
                     });
}

// Overwrites texel (mip, layer, x, y) of an RGBA16F image.
void setTexel(ibl::CachedImage& image, uint32_t mip, uint32_t layer, uint32_t x, uint32_t y, const glm::vec4& v) {
    size_t offset = 0;
    for (uint32_t m = 0; m < mip; ++m)
        offset += size_t(std::max(image.width >> m, 1u)) * std::max(image.height >> m, 1u) * image.layers * 8;
    const uint32_t w = std::max(image.width >> mip, 1u), h = std::max(image.height >> mip, 1u);
    offset += ((size_t(layer) * h + y) * w + x) * 8;
    std::vector<std::byte> bytes;
    appendTexel(bytes, kFormatRgba16Sfloat, v);
    std::memcpy(image.data.data() + offset, bytes.data(), 8);
}

glm::dvec3 smoothRadiance(const glm::dvec3& d) {
    return {1.0 + 0.6 * d.x + 0.2 * d.y * d.y, 0.8 + 0.5 * d.y, 0.5 + 0.4 * d.z * d.x + 0.3};
}

glm::dvec3 linearRadiance(const glm::dvec3& d) { return glm::dvec3(1.0 + 0.5 * d.x); }

// The cube of reference values: mip 0 bilinear(original), mip m prefiltered(reference, r = m/(mips−1)).
ibl::CachedImage referenceCube(const assets::Environment& original, const assets::Environment& reference, uint32_t faceSize,
                          uint32_t mips) {
    return makeCube("specular", faceSize, mips, [&](uint32_t m, const glm::dvec3& d) {
        return m == 0 ? ref::bilinear(original, d) : ref::prefiltered(reference, d, double(m) / (mips - 1));
    });
}

glm::dvec3 meanRadiance(const assets::Environment& env) {
    glm::dvec3 sum(0.0);
    for (uint32_t y = 0; y < env.height; ++y)
        for (uint32_t x = 0; x < env.width; ++x) {
            const float* t = env.texel(x, y);
            sum += glm::dvec3(t[0], t[1], t[2]) * ref::texelSolidAngle(y, env.width, env.height);
        }
    return sum / (4.0 * kPi);
}

// ---- Texel decoding ----

TEST(IblErrorsTexelValue, DecodesKnownHalves) {
    ibl::CachedImage rgba{.name = "h", .format = kFormatRgba16Sfloat, .texelBytes = 8, .width = 1, .height = 1,
                     .layers = 1, .mips = 1};
    const uint16_t halves[4] = {0x3C00, 0xC000, 0x3800, 0x7C00};  // 1, −2, 0.5, +Inf
    rgba.data.resize(8);
    std::memcpy(rgba.data.data(), halves, 8);
    const glm::vec4 v = texelValue(rgba, 0, 0, 0, 0);
    EXPECT_EQ(v.x, 1.0f);
    EXPECT_EQ(v.y, -2.0f);
    EXPECT_EQ(v.z, 0.5f);
    EXPECT_EQ(v.w, std::numeric_limits<float>::infinity());

    ibl::CachedImage rg{.name = "rg", .format = kFormatRg16Sfloat, .texelBytes = 4, .width = 1, .height = 1,
                   .layers = 1, .mips = 1};
    const uint16_t rgHalves[2] = {0x3555, 0x0001};  // 0.333251953125, 2^−24 (smallest subnormal)
    rg.data.resize(4);
    std::memcpy(rg.data.data(), rgHalves, 4);
    EXPECT_EQ(texelValue(rg, 0, 0, 0, 0), glm::vec4(0.333251953125f, std::ldexp(1.0f, -24), 0.0f, 1.0f));

    rg.texelBytes = 8;
    EXPECT_THROW(texelValue(rg, 0, 0, 0, 0), std::invalid_argument);
    rg.format = 44;  // VK_FORMAT_B8G8R8A8_UNORM
    rg.texelBytes = 4;
    EXPECT_THROW(texelValue(rg, 0, 0, 0, 0), std::invalid_argument);
}

TEST(IblErrorsTexelValue, AddressesMipsLayersAndRows) {
    const ibl::CachedImage cube = makeImage("c", kFormatRgba32Sfloat, 4, 4, 6, 3, [](uint32_t m, uint32_t l, uint32_t x,
                                                                               uint32_t y) {
        return glm::vec4(float(m), float(l), float(x), float(y));
    });
    for (uint32_t m = 0; m < 3; ++m)
        for (uint32_t l = 0; l < 6; ++l)
            for (uint32_t y = 0; y < (4u >> m); ++y)
                for (uint32_t x = 0; x < (4u >> m); ++x)
                    ASSERT_EQ(texelValue(cube, m, l, x, y), glm::vec4(float(m), float(l), float(x), float(y)));
    EXPECT_THROW(texelValue(cube, 0, 0, 4, 0), std::out_of_range);
    EXPECT_THROW(texelValue(cube, 1, 0, 0, 2), std::out_of_range);
    EXPECT_THROW(texelValue(cube, 3, 0, 0, 0), std::out_of_range);
    EXPECT_THROW(texelValue(cube, 0, 6, 0, 0), std::out_of_range);
    ibl::CachedImage truncated = cube;
    truncated.data.resize(truncated.data.size() - 1);
    EXPECT_THROW(texelValue(truncated, 2, 5, 0, 0), std::out_of_range);
}

// ---- Statistics ----

TEST(IblErrorsStats, RelativeRmseAndFlooredMaximum) {
    const std::vector<double> ref{1.0, 1.0, 1.0}, gpu{1.0, 2.0, 3.0};
    const ErrorStats s = errorStats(gpu, ref);
    EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(5.0 / 3.0));
    EXPECT_DOUBLE_EQ(s.maxRelative, 2.0 / 1.01);
    EXPECT_DOUBLE_EQ(s.meanRelative, (0.0 + 1.0 / 1.01 + 2.0 / 1.01) / 3.0);
    EXPECT_EQ(s.count, 3u);
    EXPECT_TRUE(s.finite);

    // A black reference texel is measured against 1% of the mean (0.5).
    const ErrorStats black = errorStats(std::vector<double>{0.5, 1.0}, std::vector<double>{0.0, 1.0});
    EXPECT_DOUBLE_EQ(black.maxRelative, 0.5 / 0.005);
    EXPECT_DOUBLE_EQ(black.rmse, std::sqrt(0.125) / 0.5);

    const std::vector<double> zeros{0.0, 0.0};
    EXPECT_EQ(errorStats(zeros, zeros).rmse, 0.0);
    EXPECT_EQ(errorStats(zeros, zeros).maxRelative, 0.0);
    EXPECT_TRUE(std::isinf(errorStats(std::vector<double>{0.0, 1e-3}, zeros).rmse));
    EXPECT_THROW(errorStats(zeros, std::vector<double>{0.0}), std::invalid_argument);
}

TEST(IblErrorsStats, LuminanceIsRec709) {
    EXPECT_DOUBLE_EQ(luminance({1.0, 0.0, 0.0}), 0.2126);
    EXPECT_DOUBLE_EQ(luminance({0.0, 1.0, 0.0}), 0.7152);
    EXPECT_DOUBLE_EQ(luminance({0.0, 0.0, 1.0}), 0.0722);
}

TEST(IblErrorsStats, NonFiniteValuesAreFlaggedAndLeftOut) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const ErrorStats s = errorStats(std::vector<double>{1.0, nan, 2.0}, std::vector<double>{1.0, 1.0, 2.0});
    EXPECT_FALSE(s.finite);
    EXPECT_EQ(s.count, 3u);
    EXPECT_EQ(s.rmse, 0.0);
    EXPECT_EQ(s.maxRelative, 0.0);
}

// ---- Cube geometry and sampling ----

TEST(IblErrorsCube, FaceCentresAreTheAxesInVulkanOrder) {
    const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (uint32_t face = 0; face < 6; ++face) {
        const glm::dvec3 d = cubeTexelDirection(face, 1, 1, 3);
        EXPECT_NEAR(glm::length(d - axes[face]), 0.0, 1e-12) << face;
    }
    // Rows top first: row 0 of a side face looks up (+Y), of the +Y face towards −Z.
    EXPECT_GT(cubeTexelDirection(4, 1, 0, 3).y, 0.5);
    EXPECT_LT(cubeTexelDirection(2, 1, 0, 3).z, -0.5);
}

TEST(IblErrorsCube, SamplingAtTexelCentresReturnsTheTexel) {
    const uint32_t size = 4;
    const ibl::CachedImage cube = makeImage("c", kFormatRgba32Sfloat, size, size, 6, 1,
                                       [](uint32_t, uint32_t l, uint32_t x, uint32_t y) {
                                           return glm::vec4(float(l), float(x), float(y), 0.0f);
                                       });
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                const glm::vec4 v = sampleCube(cube, 0, cubeTexelDirection(face, x, y, size));
                EXPECT_NEAR(glm::length(v - glm::vec4(float(face), float(x), float(y), 0.0f)), 0.0f, 1e-5f)
                    << face << " " << x << " " << y;
            }
    // Halfway between the centres of texels (1, 2) and (2, 2) of face +Z.
    const glm::dvec3 mid = cubeTexelDirection(4, 1, 2, size) + cubeTexelDirection(4, 2, 2, size);
    const glm::vec4 between = sampleCube(cube, 0, glm::dvec3(mid.x / mid.z, mid.y / mid.z, 1.0));
    EXPECT_NEAR(between.y, 1.5f, 1e-5f);
    EXPECT_NEAR(between.z, 2.0f, 1e-5f);
    // On the edge between +Z's last column and +X's first (row 1): half of each, as seamless
    // filtering gives.
    const float t = -(1.5f / size * 2.0f - 1.0f);
    const glm::vec4 edge = sampleCube(cube, 0, glm::dvec3(1.0, t, 1.0));
    EXPECT_NEAR(glm::length(edge - 0.5f * (glm::vec4(4, 3, 1, 0) + glm::vec4(0, 0, 1, 0))), 0.0f, 1e-5f);
    // Just inside +X, a quarter texel from the edge: 3/4 of +X (0, 1), 1/4 of +Z (3, 1).
    const glm::vec4 inside = sampleCube(cube, 0, glm::dvec3(1.0, t, 1.0 - 0.25 * 2.0 / size));
    EXPECT_NEAR(glm::length(inside - (0.75f * glm::vec4(0, 0, 1, 0) + 0.25f * glm::vec4(4, 3, 1, 0))), 0.0f, 1e-5f);
}

TEST(IblErrorsCube, SampleTexelsAreDistinctAndCoverEveryFace) {
    const uint32_t size = 16;
    const std::vector<uint32_t> texels = specularSampleTexels(size, 128);
    ASSERT_EQ(texels.size(), 128u);
    EXPECT_EQ(std::set<uint32_t>(texels.begin(), texels.end()).size(), 128u);
    std::set<uint32_t> faces, rows, columns;
    for (uint32_t t : texels) {
        ASSERT_LT(t, 6 * size * size);
        faces.insert(t / (size * size));
        if (t / (size * size) == 0) {
            rows.insert(t / size % size);
            columns.insert(t % size);
        }
    }
    EXPECT_EQ(faces.size(), 6u);
    EXPECT_GE(rows.size(), 12u);  // face 0 has 22 samples over 16 rows and columns
    EXPECT_GE(columns.size(), 10u);
    // More than the mip has: every texel once.
    const std::vector<uint32_t> all = specularSampleTexels(2, 100);
    EXPECT_EQ(std::set<uint32_t>(all.begin(), all.end()).size(), 24u);
    EXPECT_EQ(all.size(), 24u);
}

// ---- Specular ----

class IblErrorsSpecular : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        original = new assets::Environment(ref::makeEnvironment(128, 64, smoothRadiance));
        reduced = new assets::Environment(referenceEnvironment(*original, 64));
        cube = new ibl::CachedImage(referenceCube(*original, *reduced, kFaceSize, kMips));
    }
    static void TearDownTestSuite() {
        delete original;
        delete reduced;
        delete cube;
    }
    static constexpr uint32_t kFaceSize = 8, kMips = 4, kTexels = 64;
    static inline assets::Environment* original = nullptr;
    static inline assets::Environment* reduced = nullptr;
    static inline ibl::CachedImage* cube = nullptr;
};

TEST_F(IblErrorsSpecular, ReferenceValuesMeasureOnlyHalfRounding) {
    ReferenceCache cache;
    const std::vector<LevelErrors> levels = specularErrors(*cube, *original, *reduced, kTexels, cache);
    ASSERT_EQ(levels.size(), kMips);
    for (uint32_t m = 0; m < kMips; ++m) {
        const uint32_t size = kFaceSize >> m;
        EXPECT_FLOAT_EQ(levels[m].roughness, float(m) / 3.0f);
        EXPECT_EQ(levels[m].faceSize, size);
        EXPECT_EQ(levels[m].stats.count, std::min(kTexels, 6 * size * size));
        EXPECT_TRUE(levels[m].stats.finite);
        EXPECT_LT(levels[m].stats.rmse, 1e-3) << m;
        EXPECT_LT(levels[m].stats.maxRelative, 1e-3) << m;
        EXPECT_GT(levels[m].stats.maxRelative, 0.0) << m;  // half rounding is there, so values were compared
    }
    // A second comparison at the same sizes computes nothing new.
    const size_t stored = cache.size();
    EXPECT_EQ(stored, size_t(64 + 64 + 24 + 6));
    specularErrors(*cube, *original, *reduced, kTexels, cache);
    EXPECT_EQ(cache.size(), stored);
    EXPECT_EQ(cache.hits(), stored);
}

TEST_F(IblErrorsSpecular, OneDoubledTexelShowsAtItsLevelOnly) {
    ReferenceCache cache;
    const std::vector<LevelErrors> before = specularErrors(*cube, *original, *reduced, kTexels, cache);
    const uint32_t mip = 1, size = kFaceSize >> mip;
    const uint32_t index = specularSampleTexels(size, kTexels)[7];
    const uint32_t face = index / (size * size), x = index % size, y = index / size % size;
    ibl::CachedImage changed = *cube;
    setTexel(changed, mip, face, x, y, 2.0f * texelValue(*cube, mip, face, x, y));
    const std::vector<LevelErrors> after = specularErrors(changed, *original, *reduced, kTexels, cache);
    // |2r − r| / (r + 0.01·mean) with r ≈ mean: just under 1.
    EXPECT_NEAR(after[mip].stats.maxRelative, 1.0, 0.05);
    EXPECT_GT(after[mip].stats.rmse, 0.05);
    for (uint32_t m = 0; m < kMips; ++m) {
        if (m == mip) continue;
        EXPECT_EQ(after[m].stats.rmse, before[m].stats.rmse) << m;
        EXPECT_EQ(after[m].stats.maxRelative, before[m].stats.maxRelative) << m;
    }
}

TEST_F(IblErrorsSpecular, MirroredCubeIsFarOff) {
    // The reference values of −d in direction d: what swapped faces would give.
    const ibl::CachedImage mirrored = makeCube("specular", kFaceSize, kMips, [&](uint32_t m, const glm::dvec3& d) {
        return m == 0 ? ref::bilinear(*original, -d) : ref::prefiltered(*reduced, -d, double(m) / (kMips - 1));
    });
    ReferenceCache cache;
    const std::vector<LevelErrors> levels = specularErrors(mirrored, *original, *reduced, kTexels, cache);
    for (uint32_t m = 0; m + 1 < kMips; ++m) EXPECT_GT(levels[m].stats.maxRelative, 0.3) << m;
}

TEST_F(IblErrorsSpecular, NanTexelIsReported) {
    ibl::CachedImage broken = *cube;
    const uint32_t index = specularSampleTexels(kFaceSize, kTexels)[0];
    setTexel(broken, 0, index / 64, index % 8, index / 8 % 8, glm::vec4(std::numeric_limits<float>::quiet_NaN()));
    ReferenceCache cache;
    const std::vector<LevelErrors> levels = specularErrors(broken, *original, *reduced, kTexels, cache);
    EXPECT_FALSE(levels[0].stats.finite);
    EXPECT_TRUE(levels[1].stats.finite);
    EXPECT_LT(levels[0].stats.maxRelative, 1e-3);  // the rest still measured
}

TEST_F(IblErrorsSpecular, CacheRefusesAnotherEnvironmentSize) {
    ReferenceCache cache;
    specularErrors(*cube, *original, *reduced, 8, cache);
    EXPECT_THROW(specularErrors(*cube, *original, *original, 8, cache), std::invalid_argument);
}

TEST(IblErrorsSpecularConstant, ConstantEnvironmentAndCubeMeasureZero) {
    const glm::dvec3 c(0.25, 0.5, 2.0);  // exact in half
    const assets::Environment env = ref::makeEnvironment(32, 16, [&](const glm::dvec3&) { return c; });
    const ibl::CachedImage cube = makeCube("specular", 8, 3, [&](uint32_t, const glm::dvec3&) { return c; });
    ReferenceCache cache;
    const std::vector<LevelErrors> levels = specularErrors(cube, env, env, 32, cache);
    ASSERT_EQ(levels.size(), 3u);
    for (const LevelErrors& level : levels) {
        EXPECT_LT(level.stats.rmse, 1e-12) << level.roughness;
        EXPECT_LT(level.stats.maxRelative, 1e-12) << level.roughness;
        EXPECT_EQ(level.stats.count, std::min(32u, 6 * level.faceSize * level.faceSize));
    }
    // Another mip count at the same face size shares mip 0 (roughness 0) and nothing else here.
    const ibl::CachedImage four = makeCube("specular", 8, 4, [&](uint32_t, const glm::dvec3&) { return c; });
    specularErrors(four, env, env, 32, cache);
    EXPECT_EQ(cache.hits(), 32u);
}

// ---- Irradiance ----

ibl::CachedImage shImage(const std::array<glm::vec3, 9>& sh) {
    return makeImage("irradiance_sh", kFormatRgba32Sfloat, 9, 1, 1, 1,
                     [&](uint32_t, uint32_t, uint32_t x, uint32_t) { return glm::vec4(sh[x], 0.0f); });
}

TEST(IblErrorsIrradiance, ShOfAConstantEnvironmentIsExact) {
    const glm::dvec3 c(0.3, 1.7, 0.05);
    const assets::Environment env = ref::makeEnvironment(32, 16, [&](const glm::dvec3&) { return c; });
    std::array<glm::vec3, 9> sh{};
    sh[0] = glm::vec3(c / kY00);
    ReferenceCache cache;
    const ErrorStats s = irradianceErrors(shImage(sh), env, 64, cache);
    EXPECT_EQ(s.count, 64u);
    EXPECT_TRUE(s.finite);
    EXPECT_LT(s.rmse, 1e-6);
    EXPECT_LT(s.maxRelative, 1e-6);
}

// L = 1 + 0.5 x has irradiance/π = 1 + x/3 (band 1 scaled by 2/3): sh[0] = 1/Y00, sh[3] = 1/(3·Y1).
TEST(IblErrorsIrradiance, ShOfALinearEnvironmentAndAWrongBasisOrder) {
    const assets::Environment env = ref::makeEnvironment(128, 64, linearRadiance);
    std::array<glm::vec3, 9> sh{};
    sh[0] = glm::vec3(float(1.0 / kY00));
    sh[3] = glm::vec3(float(1.0 / (3.0 * kY1)));
    ReferenceCache cache;
    const ErrorStats right = irradianceErrors(shImage(sh), env, 64, cache);
    EXPECT_LT(right.maxRelative, 1e-3);
    std::swap(sh[3], sh[1]);  // the x coefficient stored as y
    const ErrorStats wrong = irradianceErrors(shImage(sh), env, 64, cache);
    EXPECT_GT(wrong.maxRelative, 0.2);
    EXPECT_EQ(cache.size(), 64u);
}

// The forward shader clamps SH irradiance at 0: a negative band 0 over a black environment is exact.
TEST(IblErrorsIrradiance, ShIsClampedAtZeroLikeTheShader) {
    const assets::Environment black = ref::makeEnvironment(16, 8, [](const glm::dvec3&) { return glm::dvec3(0.0); });
    std::array<glm::vec3, 9> sh{};
    sh[0] = glm::vec3(-1.0f);
    ReferenceCache cache;
    const ErrorStats s = irradianceErrors(shImage(sh), black, 16, cache);
    EXPECT_EQ(s.rmse, 0.0);
    EXPECT_EQ(s.maxRelative, 0.0);
    sh[0] = glm::vec3(1e-3f);
    EXPECT_TRUE(std::isinf(irradianceErrors(shImage(sh), black, 16, cache).maxRelative));
}

TEST(IblErrorsIrradiance, CubeOfALinearEnvironment) {
    const assets::Environment env = ref::makeEnvironment(128, 64, linearRadiance);
    const auto exact = [](uint32_t, const glm::dvec3& n) { return glm::dvec3(1.0 + n.x / 3.0); };
    ReferenceCache cache;
    const ErrorStats s = irradianceErrors(makeCube("irradiance_cube", 16, 1, exact), env, 128, cache);
    EXPECT_LT(s.maxRelative, 3e-3);
    EXPECT_LT(s.rmse, 1e-3);
    const auto flipped = [](uint32_t, const glm::dvec3& n) { return glm::dvec3(1.0 - n.x / 3.0); };
    EXPECT_GT(irradianceErrors(makeCube("irradiance_cube", 16, 1, flipped), env, 128, cache).maxRelative, 0.3);
    EXPECT_THROW(irradianceErrors(makeCube("specular", 16, 1, exact), env, 128, cache), std::invalid_argument);
}

// ---- BRDF LUT ----

class IblErrorsLut : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        lut = new ibl::CachedImage(makeImage("brdf_lut", kFormatRg16Sfloat, kSize, kSize, 1, 1,
                                        [](uint32_t, uint32_t, uint32_t x, uint32_t y) {
                                            const double NoV = std::max(double(x) / (kSize - 1), 1e-4);
                                            const ref::SplitSum s = ref::splitSum(NoV, double(y) / (kSize - 1));
                                            return glm::vec4(float(s.a), float(s.b), 0.0f, 0.0f);
                                        }));
    }
    static void TearDownTestSuite() { delete lut; }
    static ibl::CachedImage offBy(uint32_t x, uint32_t y, float delta) {
        ibl::CachedImage changed = *lut;
        const glm::vec4 v = texelValue(*lut, 0, 0, x, y);
        const uint16_t a = glm::packHalf1x16(v.x + delta);
        std::memcpy(changed.data.data() + (size_t(y) * kSize + x) * 4, &a, 2);
        return changed;
    }
    static constexpr uint32_t kSize = 32;
    static inline ibl::CachedImage* lut = nullptr;
};

TEST_F(IblErrorsLut, ReferenceValuesMeasureOnlyHalfRounding) {
    const LutErrors e = lutErrors(*lut, 1);
    EXPECT_EQ(e.count, kSize * kSize);
    EXPECT_TRUE(e.finite);
    EXPECT_LT(e.maxA, 1e-3);
    EXPECT_LT(e.maxB, 1e-3);
    EXPECT_LT(e.maxSum, 1e-3);
    EXPECT_GT(e.maxA, 0.0);
    EXPECT_LT(e.rmsA, 5e-4);
    EXPECT_LT(e.rmsB, 5e-4);
    EXPECT_EQ(lutErrors(*lut, 4).count, 9u * 9u);  // 0, 4, …, 28 and 31
}

TEST_F(IblErrorsLut, OneTexelOffByATenth) {
    const LutErrors onGrid = lutErrors(offBy(8, 12, 0.1f), 4);
    EXPECT_GE(onGrid.maxA, 0.099);
    EXPECT_LT(onGrid.maxA, 0.102);
    EXPECT_GE(onGrid.maxSum, 0.099);
    EXPECT_LT(onGrid.maxB, 1e-3);
    EXPECT_GE(lutErrors(offBy(kSize - 1, kSize - 1, -0.1f), 4).maxA, 0.099);  // the last row and column
    EXPECT_LT(lutErrors(offBy(1, 1, 0.1f), 4).maxA, 1e-3);                     // between grid texels
}

TEST_F(IblErrorsLut, BadShapes) {
    EXPECT_THROW(lutErrors(*lut, 0), std::invalid_argument);
    ibl::CachedImage one = makeImage("brdf_lut", kFormatRg16Sfloat, 1, 1, 1, 1,
                                [](uint32_t, uint32_t, uint32_t, uint32_t) { return glm::vec4(0.0f); });
    EXPECT_THROW(lutErrors(one, 1), std::invalid_argument);
}

// ---- Reference environment ----

glm::dvec3 busyRadiance(const glm::dvec3& d) {
    return {1.0 + std::sin(40.0 * d.x) * std::cos(23.0 * d.y), 2.0 + std::sin(17.0 * d.z + 3.0 * d.y),
            std::exp(4.0 * d.y)};
}

TEST(IblErrorsReferenceEnvironment, PreservesTheMeanAndHalvesSizes) {
    const assets::Environment env = ref::makeEnvironment(100, 50, busyRadiance);
    const assets::Environment odd = referenceEnvironment(env, 32);  // 100 → 50 → 25; 50 → 25 → 13
    EXPECT_EQ(odd.width, 25u);
    EXPECT_EQ(odd.height, 13u);
    const glm::dvec3 mean = meanRadiance(env), reducedMean = meanRadiance(odd);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(reducedMean[c] / mean[c], 1.0, 1e-6) << c;

    const assets::Environment even = ref::makeEnvironment(64, 32, busyRadiance);
    const assets::Environment quarter = referenceEnvironment(even, 16);
    EXPECT_EQ(quarter.width, 16u);
    EXPECT_EQ(quarter.height, 8u);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(meanRadiance(quarter)[c] / meanRadiance(even)[c], 1.0, 1e-6) << c;
    // Texel (5, 2) is the solid-angle-weighted mean of source texels x 20..23, y 8..11.
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (uint32_t y = 8; y < 12; ++y)
        for (uint32_t x = 20; x < 24; ++x) {
            const double omega = ref::texelSolidAngle(y, 64, 32);
            sum += omega * glm::dvec3(even.texel(x, y)[0], even.texel(x, y)[1], even.texel(x, y)[2]);
            weight += omega;
        }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(quarter.texel(5, 2)[c], sum[c] / weight, 1e-6 * sum[c] / weight);
}

TEST(IblErrorsReferenceEnvironment, SmallMapsAreKept) {
    const assets::Environment env = ref::makeEnvironment(16, 8, busyRadiance);
    const assets::Environment same = referenceEnvironment(env, 16);
    EXPECT_EQ(same.width, 16u);
    EXPECT_EQ(same.rgb, env.rgb);
    EXPECT_THROW(referenceEnvironment(env, 0), std::invalid_argument);
    EXPECT_THROW(referenceEnvironment(assets::Environment{}, 16), std::invalid_argument);
}

}  // namespace
}  // namespace candela::reports::test
