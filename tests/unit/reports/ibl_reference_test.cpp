// The double-precision IBL reference (engine/reports/ibl_reference.h): the split-sum terms against
// their own refinement, a brute-force integral over light directions and the Khronos glTF Sample
// Viewer's LUT; the environment integrals against closed forms.
#include "brdf_reference.h"
#include "test_paths.h"
#include "reports/ibl_reference.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

namespace candela::reports::reference::test {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 constant(const glm::dvec3&) { return {0.25, 0.5, 2.0}; }

// Relative difference per channel, max over channels.
double relativeError(const glm::dvec3& got, const glm::dvec3& expected) {
    const glm::dvec3 e = glm::abs(got - expected) / glm::abs(expected);
    return std::max({e.x, e.y, e.z});
}

double schlickWeight(double VoH) { return std::pow(1.0 - VoH, 5.0); }

// ---- Split sum ----

TEST(IblReferenceSplitSum, NonNegativeAndAtMostOne) {
    for (int i = 0; i < 32; ++i) {
        for (int j = 0; j < 32; ++j) {
            const double NoV = (i + 0.5) / 32.0, roughness = j / 31.0;
            const SplitSum s = splitSum(NoV, roughness);
            EXPECT_GE(s.a, 0.0) << NoV << " " << roughness;
            EXPECT_GE(s.b, 0.0) << NoV << " " << roughness;
            EXPECT_LE(s.a + s.b, 1.0 + 1e-6) << NoV << " " << roughness;
            EXPECT_DOUBLE_EQ(directionalAlbedo(NoV, roughness), s.a + s.b);
        }
    }
}

TEST(IblReferenceSplitSum, MirrorAtRoughnessZero) {
    for (double NoV : {1e-4, 0.01, 0.1, 0.25, 0.5, 0.75, 1.0}) {
        const SplitSum s = splitSum(NoV, 0.0);
        EXPECT_NEAR(s.a + s.b, 1.0, 1e-12) << NoV;
        EXPECT_NEAR(s.b, schlickWeight(NoV), 1e-12) << NoV;
        // Continuity into the quadrature: r = 1e-3 (α = 1e-6) is still a mirror to 1e-5 — except at
        // the most grazing views, where masking (∝ α/NoV) takes 5e-5 at NoV = 1e-4.
        if (NoV >= 1e-3) {
            const SplitSum nearMirror = splitSum(NoV, 1e-3);
            EXPECT_NEAR(nearMirror.a, s.a, 1e-5) << NoV;
            EXPECT_NEAR(nearMirror.b, s.b, 1e-5) << NoV;
        }
        // At the mirror threshold (r = 1e-4) the two sides agree to 1e-8.
        const SplitSum below = splitSum(NoV, 0.99e-4), above = splitSum(NoV, 1.01e-4);
        EXPECT_NEAR(below.a, above.a, 1e-7) << NoV;
        EXPECT_NEAR(below.b, above.b, 1e-7) << NoV;
    }
    EXPECT_EQ(splitSum(1.0, 0.0).b, 0.0);
    EXPECT_EQ(splitSum(1.0, 0.0).a, 1.0);
    // NoV is clamped to ≥ 1e-4: grazing and back-facing views stay finite.
    EXPECT_EQ(splitSum(0.0, 0.5).a, splitSum(1e-4, 0.5).a);
    EXPECT_EQ(splitSum(-0.5, 0.5).b, splitSum(1e-4, 0.5).b);
}

// Doubling (and quadrupling) every quadrature grid changes a and b by < 1e-5, including narrow
// lobes at grazing views. Measured: ≤ 2.7e-6 over NoV ∈ [1e-4, 1] × r ∈ [1e-4, 1] (worst at NoV = 1,
// r ≈ 0.16, where the lobe's horizon cut is at θh = 45° for every azimuth).
TEST(IblReferenceSplitSum, ConvergedUnderRefinement) {
    for (double NoV : {1e-4, 0.01, 0.05, 0.2, 0.5, 0.9, 1.0}) {
        for (double roughness : {1e-4, 0.001, 0.01, 0.02, 0.05, 0.1, 0.16, 0.3, 0.6, 1.0}) {
            const SplitSum s1 = splitSum(NoV, roughness);
            const SplitSum s2 = splitSumRefined(NoV, roughness, 2);
            const SplitSum s4 = splitSumRefined(NoV, roughness, 4);
            EXPECT_NEAR(s1.a, s2.a, 1e-5) << NoV << " " << roughness;
            EXPECT_NEAR(s1.b, s2.b, 1e-5) << NoV << " " << roughness;
            EXPECT_NEAR(s1.a, s4.a, 1e-5) << NoV << " " << roughness;
            EXPECT_NEAR(s1.b, s4.b, 1e-5) << NoV << " " << roughness;
        }
    }
}

// An independent integral over the light direction l (no change of variables, no importance
// sampling): the midpoint rule on a (θl, φl) grid with the BRDF reference of brdf_reference.h.
SplitSum bruteForce(double NoV, double roughness, int thetaSteps, int phiSteps) {
    const double alpha = roughness * roughness;
    const glm::dvec3 n(0.0, 0.0, 1.0), v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const double dTheta = 0.5 * kPi / thetaSteps, dPhi = kPi / phiSteps;
    double a = 0.0, b = 0.0;
    for (int i = 0; i < thetaSteps; ++i) {
        const double theta = (i + 0.5) * dTheta;
        const double NoL = std::cos(theta), sinTheta = std::sin(theta);
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = (j + 0.5) * dPhi;
            const glm::dvec3 l(sinTheta * std::cos(phi), sinTheta * std::sin(phi), NoL);
            const glm::dvec3 h = glm::normalize(v + l);
            const double f = candela::test::reference::distributionGgx(glm::dot(n, h), alpha) *
                             candela::test::reference::visibilitySmithGgxCorrelated(NoV, NoL, alpha) * NoL;
            const double fc = schlickWeight(glm::dot(v, h));
            const double dOmega = 2.0 * sinTheta * dTheta * dPhi;  // φ ∈ [0, π] counted twice (symmetry)
            a += (1.0 - fc) * f * dOmega;
            b += fc * f * dOmega;
        }
    }
    return {a, b};
}

// Agreement within 1e-4. Measured ≤ 7.2e-6 (at NoV = 1, r = 0.3: the lobe of r = 0.3 spans ≈ 100
// cells in θ). The grazing case (NoV = 0.02, where the Khronos LUT's a is 0.015 lower, see below)
// needs 2000 cells in φ — the lobe hugs the horizon — and agrees to 9e-6.
TEST(IblReferenceSplitSum, MatchesBruteForceOverLightDirections) {
    const struct { double NoV, roughness; int thetaSteps, phiSteps; } cases[] = {
        {1.0, 0.3, 1000, 1000}, {0.5, 0.5, 1000, 1000}, {0.2, 0.3, 1000, 1000},
        {0.9, 0.7, 1000, 1000}, {0.05, 1.0, 1000, 1000}, {0.02, 0.3, 500, 2000}};
    for (const auto& c : cases) {
        const SplitSum expected = bruteForce(c.NoV, c.roughness, c.thetaSteps, c.phiSteps);
        const SplitSum got = splitSum(c.NoV, c.roughness);
        EXPECT_NEAR(got.a, expected.a, 1e-4) << c.NoV << " " << c.roughness;
        EXPECT_NEAR(got.b, expected.b, 1e-4) << c.NoV << " " << c.roughness;
    }
}

TEST(IblReferenceSplitSum, AlbedoDecreasesWithRoughness) {
    double previous = directionalAlbedo(0.5, 0.2);
    for (double roughness = 0.25; roughness <= 1.0 + 1e-9; roughness += 0.05) {
        const double albedo = directionalAlbedo(0.5, roughness);
        EXPECT_LT(albedo, previous) << roughness;
        previous = albedo;
    }
    EXPECT_LT(directionalAlbedo(0.5, 1.0), 0.5);  // the single-scattering loss of the roughest lobe
}

// The Khronos glTF Sample Viewer's lut_ggx.png (1024², 8-bit RGB, R = a, G = b, u = NoV and v =
// roughness at texel centres, row 0 = roughness 0), sampled at 32 × 32 texel centres. Measured:
//   - b: max |b − G| 0.0022, mean 0.0009 — the 8-bit quantisation (±0.5/255 = 0.002).
//   - a for NoV ≥ 0.25: max |a − R| 0.0029.
//   - a for NoV < 0.25: max |a − R| 0.0165 (NoV = 0.016, r = 0.27), the LUT lower than the reference.
//     This is the LUT's bias, not the reference's error: cutting the reference's GGX tail off at
//     ξ1 > 1 − 1/2048 (what a ~1024-sample Hammersley set reaches) brings it to 0.0054, and a
//     brute-force integral over l agrees with the reference there (0.02, 0.3 above; 4e-6 at
//     0.0166, 0.27 with 2000² cells). At grazing views the term a lives in the far tail of D (h near
//     v, near the horizon), which the LUT's sample set does not reach.
//   - mean |a − R| 0.0016.
TEST(IblReferenceSplitSum, MatchesKhronosLut) {
    const std::filesystem::path path = ::candela::test::sharedAssets() / "reference" / "lut_ggx.png";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.string().c_str(), &width, &height, &channels, 3),
                                                           stbi_image_free);
    ASSERT_TRUE(pixels) << stbi_failure_reason();
    ASSERT_EQ(width, 1024);
    ASSERT_EQ(height, 1024);
    const auto channel = [&](int x, int y, int c) { return pixels.get()[(size_t(y) * width + x) * 3 + c] / 255.0; };

    // Row direction: at NoV = 1 the mirror (roughness 0) has b = Fc(1) = 0 and a = 1, the roughest
    // lobe b ≈ 6e-6 (also 0 in 8 bits) and a ≈ 0.3. So roughness 0 is the end row whose last texel
    // has b = 0 and the larger a: the top row (row 0), as measured.
    const bool roughnessZeroAtTop = channel(width - 1, 0, 0) > channel(width - 1, height - 1, 0);
    EXPECT_TRUE(roughnessZeroAtTop);
    EXPECT_EQ(channel(width - 1, roughnessZeroAtTop ? 0 : height - 1, 1), 0.0);

    double maxA = 0.0, maxGrazingA = 0.0, maxB = 0.0, sumA = 0.0, sumB = 0.0;
    for (int i = 0; i < 32; ++i) {
        for (int j = 0; j < 32; ++j) {
            const int x = i * 32 + 16, row = j * 32 + 16;
            const double NoV = (x + 0.5) / width, roughness = (row + 0.5) / height;
            const int y = roughnessZeroAtTop ? row : height - 1 - row;
            const SplitSum s = splitSum(NoV, roughness);
            const double da = std::abs(s.a - channel(x, y, 0)), db = std::abs(s.b - channel(x, y, 1));
            (NoV >= 0.25 ? maxA : maxGrazingA) = std::max(NoV >= 0.25 ? maxA : maxGrazingA, da);
            maxB = std::max(maxB, db);
            sumA += da;
            sumB += db;
        }
    }
    std::cout << "lut_ggx.png over 32×32 texel centres: max |a − R| " << maxA << " (NoV ≥ 0.25), " << maxGrazingA
              << " (NoV < 0.25); max |b − G| " << maxB << "; mean " << sumA / 1024 << ", " << sumB / 1024 << "\n";
    EXPECT_LE(maxA, 0.004);
    EXPECT_LE(maxGrazingA, 0.02);
    EXPECT_LE(maxB, 0.004);
    EXPECT_LE(sumA / 1024, 0.003);
    EXPECT_LE(sumB / 1024, 0.002);
}

// ---- Environment integrals ----

TEST(IblReferenceEnvironment, ConstantEnvironmentIsReproduced) {
    const glm::dvec3 c = constant({});
    const glm::dvec3 directions[] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0.3, -0.2, 0.9}, {-0.6, 0.7, -0.1}};
    for (const auto& [w, h] : {std::pair{64u, 32u}, std::pair{7u, 3u}}) {
        const assets::Environment env = makeEnvironment(w, h, constant);
        for (const glm::dvec3& d : directions) {
            EXPECT_LT(relativeError(irradiance(env, d), c), 1e-9) << w << "×" << h;
            for (double roughness : {0.0, 0.3, 1.0}) {
                EXPECT_LT(relativeError(prefiltered(env, d, roughness), c), 1e-9) << w << "×" << h << " r " << roughness;
            }
        }
    }
}

// L(d) = max(d.y, 0): (1/π) ∫ cos² = 2/3 exactly at n = +Y. The 512 × 256 map's error is that of
// sampling at texel centres (measured −4.2e-6 at +Y, +4.0e-6 at +X; tolerance 2e-5).
TEST(IblReferenceEnvironment, SkyDomeIrradiance) {
    const assets::Environment env = makeEnvironment(512, 256, [](const glm::dvec3& d) { return glm::dvec3(std::max(d.y, 0.0)); });
    const glm::dvec3 up = irradiance(env, {0, 1, 0});
    std::cout << "sky dome irradiance at +Y: " << up.x << " (error " << up.x - 2.0 / 3.0 << ")\n";
    EXPECT_NEAR(up.x, 2.0 / 3.0, 2e-5);
    EXPECT_NEAR(irradiance(env, {0, -1, 0}).x, 0.0, 1e-12);
    // On the horizon (n = +X): (1/π) ∫ max(l.x, 0) max(l.y, 0) dl = (1/π)(1/3)(2) = 2/(3π).
    const glm::dvec3 side = irradiance(env, {1, 0, 0});
    std::cout << "sky dome irradiance at +X: " << side.x << " (error " << side.x - 2.0 / (3.0 * kPi) << ")\n";
    EXPECT_NEAR(side.x, 2.0 / (3.0 * kPi), 2e-5);
}

TEST(IblReferenceEnvironment, PrefilteredLinearEnvironment) {
    const assets::Environment env = makeEnvironment(128, 64, [](const glm::dvec3& d) { return glm::dvec3(1.0 + d.x); });
    const double plus = prefiltered(env, {1, 0, 0}, 0.5).x, minus = prefiltered(env, {-1, 0, 0}, 0.5).x;
    EXPECT_GT(plus, minus);
    EXPECT_GT(minus, 0.0);
    EXPECT_LT(plus, 2.0);
    // The lobe is symmetric about R, so its mean direction is k·R: plus + minus = 2 (exactly on a
    // map of even width, which x → −x maps onto itself; the texels are floats).
    EXPECT_NEAR(plus + minus, 2.0, 1e-5);
    // k = ∫ w(θ) cos θ / ∫ w(θ) with w(θ) = D(θ/2) cos θ sin θ (θ the angle of l from R = n = v,
    // θ/2 that of h), by a fine 1D midpoint rule. Measured on 128 × 64: −6.3e-6.
    const double alpha = 0.25;
    double weighted = 0.0, total = 0.0;
    for (int i = 0; i < 100000; ++i) {
        const double theta = (i + 0.5) / 100000.0 * 0.5 * kPi;
        const double w = candela::test::reference::distributionGgx(std::cos(0.5 * theta), alpha) * std::cos(theta) *
                         std::sin(theta);
        weighted += w * std::cos(theta);
        total += w;
    }
    const double k = weighted / total;
    std::cout << "prefiltered(1 + x) at ±X, r 0.5: " << plus << ", " << minus << "; 1 + k = " << 1.0 + k << "\n";
    EXPECT_NEAR(plus, 1.0 + k, 5e-5);
}

// The narrow-lobe rule: bilinear when 2α < π/H (64 × 32: r < 0.2215), the texel sum above.
TEST(IblReferenceEnvironment, PrefilteredFallsBackToBilinearForSubTexelLobes) {
    const assets::Environment env = makeEnvironment(64, 32, [](const glm::dvec3& d) {
        return glm::dvec3(1.0 + d.x + 0.5 * d.y * d.z, 2.0 + std::sin(5.0 * d.z), 1.5 + d.y);
    });
    const glm::dvec3 R = glm::normalize(glm::dvec3(0.3, 0.5, -0.8));
    EXPECT_EQ(prefiltered(env, R, 0.22), bilinear(env, R));
    EXPECT_NE(prefiltered(env, R, 0.223), bilinear(env, R));
    // Across the switch they differ by the lobe's blur over about one texel (5.6° here): measured
    // 2.6% in the channel 2 + sin 5z.
    EXPECT_LT(relativeError(prefiltered(env, R, 0.223), bilinear(env, R)), 0.05);
}

TEST(IblReferenceEnvironment, RoughnessZeroReturnsTexelAtItsCentre) {
    const assets::Environment env = makeEnvironment(37, 19, [](const glm::dvec3& d) {
        return glm::dvec3(1.0 + d.x + 0.5 * d.y * d.z, 2.0 + std::sin(5.0 * d.z), 1.5 + d.y);
    });
    for (uint32_t y = 0; y < env.height; y += 3) {
        for (uint32_t x = 0; x < env.width; x += 4) {
            const float* t = env.texel(x, y);
            const glm::dvec3 got = prefiltered(env, texelDirection(x, y, env.width, env.height), 0.0);
            EXPECT_EQ(got, glm::dvec3(t[0], t[1], t[2])) << x << " " << y;
        }
    }
}

TEST(IblReferenceEnvironment, BilinearWrapsInUAndClampsInV) {
    // Texel value = column index: halfway between the last column's centre and the first's (the
    // seam, −X) is their average.
    assets::Environment env = makeEnvironment(8, 4, [](const glm::dvec3&) { return glm::dvec3(0.0); });
    for (uint32_t y = 0; y < env.height; ++y)
        for (uint32_t x = 0; x < env.width; ++x) env.texel(x, y)[0] = float(x);
    EXPECT_NEAR(bilinear(env, {-1, 0, 0}).x, 3.5, 1e-9);
    EXPECT_NEAR(bilinear(env, {1, 0, 0}).x, 3.5, 1e-9);  // image centre: between columns 3 and 4
    // The poles hold the top and bottom rows (no wrap in v).
    for (uint32_t x = 0; x < env.width; ++x) env.texel(x, 0)[1] = 7.0f;
    EXPECT_EQ(bilinear(env, {0, 1, 0}).y, 7.0);
    EXPECT_EQ(bilinear(env, {0, -1, 0}).y, 0.0);
}

// ---- SH9 ----

// Closed-form projection of the clamped cosine max(d·a, 0) (zonal): L_lm = z_l √(4π/(2l + 1)) Y_lm(a)
// with z_0 = √π/2, z_1 = √(π/3), z_2 = √(5π)/8 its coefficients about +Z.
Sh9 clampedCosineSh9(const glm::dvec3& axis) {
    const std::array<double, 9> y = shBasis(axis);
    const double z[3] = {std::sqrt(kPi) / 2.0, std::sqrt(kPi / 3.0), std::sqrt(5.0 * kPi) / 8.0};
    const int band[9] = {0, 1, 1, 1, 2, 2, 2, 2, 2};
    Sh9 sh{};
    for (size_t i = 0; i < 9; ++i) sh[i] = glm::dvec3(z[band[i]] * std::sqrt(4.0 * kPi / (2 * band[i] + 1)) * y[i]);
    return sh;
}

TEST(IblReferenceSh9, ClampedCosineLobe) {
    // +Z gives the textbook values (and zero elsewhere).
    const Sh9 zAxis = clampedCosineSh9({0, 0, 1});
    EXPECT_NEAR(zAxis[0].x, std::sqrt(kPi) / 2.0, 1e-15);
    EXPECT_NEAR(zAxis[2].x, std::sqrt(kPi / 3.0), 1e-15);
    EXPECT_NEAR(zAxis[6].x, std::sqrt(5.0 * kPi) / 8.0, 1e-15);
    // Measured error of the 1024 × 512 projection: ≤ 4.2e-6 (texel-centre sampling, the kink at the
    // lobe's horizon); tolerance 1e-5.
    for (const glm::dvec3& axis : {glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0.4, -0.5, 0.77))}) {
        const assets::Environment env =
            makeEnvironment(1024, 512, [axis](const glm::dvec3& d) { return glm::dvec3(std::max(glm::dot(d, axis), 0.0)); });
        const Sh9 got = projectSh9(env), expected = clampedCosineSh9(axis);
        double maxError = 0.0;
        for (size_t i = 0; i < 9; ++i) {
            EXPECT_NEAR(got[i].x, expected[i].x, 1e-5) << "coefficient " << i << " axis " << axis.x << " " << axis.y << " " << axis.z;
            maxError = std::max(maxError, std::abs(got[i].x - expected[i].x));
        }
        std::cout << "clamped cosine SH9, axis (" << axis.x << ", " << axis.y << ", " << axis.z << "): max error " << maxError << "\n";
    }
}

// L00 is exact (the Ω sum to 4π); the point-sampled Σ Y_lm Ω of bands 1–2 is not exactly 0 on a
// grid (Y20 and Y22 leak O(1/H²)): measured relative error 5.0e-4 at 64 × 32, 3.1e-5 at 256 × 128.
TEST(IblReferenceSh9, ConstantEnvironment) {
    const glm::dvec3 c = constant({});
    const std::array<glm::dvec3, 3> normals = {glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(0.3, -0.2, 0.9))};
    for (const auto& [w, h, tolerance] : {std::tuple{64u, 32u, 1e-3}, std::tuple{256u, 128u, 1e-4}}) {
        const Sh9 sh = projectSh9(makeEnvironment(w, h, constant));
        EXPECT_LT(relativeError(sh[0] / std::sqrt(4.0 * kPi), c), 1e-9);  // L00 = c √(4π)
        double maxError = 0.0;
        for (const glm::dvec3& n : normals) maxError = std::max(maxError, relativeError(irradianceFromSh9(sh, n), c));
        std::cout << "SH9 of a constant, " << w << "×" << h << ": max relative error " << maxError << "\n";
        EXPECT_LT(maxError, tolerance) << w << "×" << h;
    }
}

// A polynomial of degree ≤ 2 has only bands 0–2, so SH9 holds it exactly, and the Lambertian
// convolution scales band l by Â_l/π (1, 2/3, 1/4). Every basis function appears:
//     L(d) = 1.5 + [0.5 x − 0.3 y + 0.2 z] + [0.25 y z + 0.2 (x² − y²) + 0.1 (3z² − 1) + 0.15 x y + 0.1 x z]
// (≥ 0.3 everywhere), so E(n) = 1.5 + (2/3)[band 1 at n] + (1/4)[band 2 at n]. Measured on
// 512 × 256 over 40 normals: SH9 9.5e-6, direct 6.3e-6, between them 1.2e-5 (tolerance 1e-4; the
// errors are texel-centre sampling, ∝ 1/H²: 3.8e-5, 2.5e-5, 4.7e-5 at 256 × 128).
double band1(const glm::dvec3& d) { return 0.5 * d.x - 0.3 * d.y + 0.2 * d.z; }
double band2(const glm::dvec3& d) {
    return 0.25 * d.y * d.z + 0.2 * (d.x * d.x - d.y * d.y) + 0.1 * (3.0 * d.z * d.z - 1.0) + 0.15 * d.x * d.y +
           0.1 * d.x * d.z;
}

TEST(IblReferenceSh9, MatchesIrradianceForQuadraticEnvironment) {
    const assets::Environment env =
        makeEnvironment(512, 256, [](const glm::dvec3& d) { return glm::dvec3(1.5 + band1(d) + band2(d)); });
    const Sh9 sh = projectSh9(env);
    double maxSh = 0.0, maxDirect = 0.0, maxBetween = 0.0;
    for (int i = 0; i < 40; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / 40.0, r = std::sqrt(1.0 - y * y), phi = i * 2.39996323;
        const glm::dvec3 n(r * std::cos(phi), y, r * std::sin(phi));
        const double expected = 1.5 + (2.0 / 3.0) * band1(n) + 0.25 * band2(n);
        const double fromSh = irradianceFromSh9(sh, n).x, direct = irradiance(env, n).x;
        maxSh = std::max(maxSh, std::abs(fromSh - expected));
        maxDirect = std::max(maxDirect, std::abs(direct - expected));
        maxBetween = std::max(maxBetween, std::abs(fromSh - direct));
    }
    std::cout << "quadratic env: SH " << maxSh << ", direct " << maxDirect << ", between " << maxBetween << "\n";
    EXPECT_LT(maxBetween, 1e-4);
    EXPECT_LT(maxSh, 1e-4);
    EXPECT_LT(maxDirect, 1e-4);
}

}  // namespace
}  // namespace candela::reports::reference::test
