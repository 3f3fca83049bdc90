// How far KHR_materials_anisotropy's image-based approximation (shared/brdf_anisotropy.h
// anisotropicBentNormal: the split sum read about a normal bent across the brushing, as the
// specification's implementation notes and the Khronos sample viewer do) is from the anisotropic
// lobe integrated against the environment — docs/materials.md quotes these figures.
//
// Everything here is double-precision quadrature, so only the approximation is measured, not the
// cube map's or the LUT's discretization:
//   truth  = ∫ f_aniso(V, L) L_env(L) (N·L) dL  (tests/unit/brdf_reference.h, metal of colour 1:
//            F = 1, single scattering),
//   approx = P(R_b, r) · E(N·V, r')  with R_b = reflect(−V, bent normal at r), P the GGX-prefiltered
//            environment at the material's roughness r (Karis: ∫ L_env D(H) (R·L) / ∫ D(H) (R·L),
//            N = V = R) — the streak as sharp as the lobe's narrow axis — and E = A + B the isotropic
//            lobe's directional albedo at r' = anisotropicIblRoughness, the stretched lobe's mean
//            roughness (its energy),
//   and, for comparison, E at r too (what the forward pass did before, and what the Khronos sample
//   viewer does), everything at r' (P and the bend too: lower error, but the streak blurred across
//   the brushing as much as along it, which renders strongly brushed metal as a uniform sheen), and
//   no bending (the isotropic split sum).
// Three environments: a broad gradient (radiance 1 + 2 ((1 + g·L)/2)², a sky-like light), a
// stress case — a uniform 1 plus a soft bright patch (1 + 40 (s·L)⁸ where s·L > 0) 25° off the
// mirror direction along the brushing, where the stretched lobe's highlight is — and a small bright
// light (0.05 + 200 (s·L)²⁰⁰, ≈ 6° wide) at the same place, the highlight of a studio lamp.
#include "brdf_reference.h"
#include "sphere_quadrature.h"
#include "shared/brdf_anisotropy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace candela::test {
namespace {

namespace ref = reference;

constexpr double kPi = std::numbers::pi;

struct Environment {
    int kind;              // 0 gradient, 1 patch, 2 small light
    glm::dvec3 direction;  // the patch's or light's centre, or the gradient's brightest direction
    double radiance(const glm::dvec3& l) const {
        const double c = glm::dot(l, direction);
        if (kind == 2) return 0.05 + 200.0 * std::pow(std::max(c, 0.0), 200.0);
        return kind == 1 ? 1.0 + 40.0 * std::pow(std::max(c, 0.0), 8.0) : 1.0 + 2.0 * std::pow(0.5 + 0.5 * c, 2.0);
    }
};
constexpr const char* kEnvironmentNames[] = {"gradient", "patch", "small light"};

// The GGX-prefiltered environment in direction R at perceptual roughness r (N = V = R).
double prefiltered(const Environment& env, const glm::dvec3& R, double roughness) {
    const double a = std::pow(std::clamp(roughness, 0.045, 1.0), 2.0);
    const glm::dvec2 sums = integrateSphere<glm::dvec2>(R, 400, [&](const glm::dvec3& l) {
        const double RoL = glm::dot(R, l);
        if (RoL <= 0.0) return glm::dvec2(0.0);
        const double w = ref::distributionGgx(std::clamp(glm::dot(R, glm::normalize(R + l)), 0.0, 1.0), a) * RoL;
        return glm::dvec2(w * env.radiance(l), w);
    });
    return sums.x / sums.y;
}

// E = A + B: the isotropic lobe's directional albedo with F = 1 at perceptual roughness r.
double isotropicAlbedo(const glm::dvec3& N, const glm::dvec3& V, double roughness) {
    return integrateSphere<double>(N, 300, [&](const glm::dvec3& l) {
        return ref::brdfTimesCosine(N, V, l, glm::dvec3(1.0), 1.0, roughness, ref::kPbr).x;
    });
}

TEST(AnisotropyIbl, BentNormalApproximationErrorIsMeasured) {
    const glm::dvec3 N(0.0, 0.0, 1.0), T(1.0, 0.0, 0.0);
    double worstBent[3] = {}, worstBefore[3] = {}, worstIsotropic[3] = {}, worstStrengthZero[3] = {};
    double sumBent[3] = {}, sumBefore[3] = {}, sumMeanRoughness[3] = {};
    int count[3] = {};
    for (int kind : {0, 1, 2})
        for (double roughness : {0.3, 0.6})
            for (double NoV : {0.9, 0.4}) {
                const glm::dvec3 V(std::sqrt(1.0 - NoV * NoV) * 0.6, std::sqrt(1.0 - NoV * NoV) * 0.8, NoV);
                const glm::dvec3 R = glm::reflect(-V, N);
                // The patch 25° off the mirror direction, rotated about N toward the brushing (T).
                const glm::dvec3 toward = glm::normalize(T - R * glm::dot(T, R));
                const Environment env{kind, kind > 0 ? glm::normalize(R * std::cos(0.436) + toward * std::sin(0.436))
                                                     : glm::normalize(glm::dvec3(0.3, 0.5, 0.8))};
                const double albedo = isotropicAlbedo(N, V, roughness);
                const double isotropic = prefiltered(env, R, roughness) * albedo;
                for (double strength : {0.0, 0.5, 1.0}) {
                    const ref::Layers layers{.bits = ref::kLayerAnisotropy, .anisotropy = strength, .anisotropyDirection = T};
                    // The truth, and the anisotropic lobe's own directional albedo (what the isotropic E stands for).
                    const glm::dvec2 truthAndAlbedo = integrateSphere<glm::dvec2>(R, 500, [&](const glm::dvec3& l) {
                        if (glm::dot(N, l) <= 0.0) return glm::dvec2(0.0);
                        const double f =
                            ref::brdfTimesCosineLayered(N, V, l, glm::dvec3(1.0), 1.0, roughness, ref::kPbr, layers).x;
                        return glm::dvec2(f * env.radiance(l), f);
                    });
                    const double truth = truthAndAlbedo.x;
                    const shading::Anisotropy an =
                        shading::anisotropyLayer(float(strength), glm::vec3(T), glm::vec3(glm::cross(N, T)));
                    // The split sum about the bent normal at roughness r (before) and at r' (now).
                    const auto bentSplitSum = [&](double r, double E) {
                        const glm::dvec3 bent =
                            glm::dvec3(shading::anisotropicBentNormal(glm::vec3(N), glm::vec3(V), float(r), an));
                        return prefiltered(env, glm::reflect(-V, glm::normalize(bent)), r) * E;
                    };
                    const double before = bentSplitSum(roughness, albedo);
                    const double iblRoughness = shading::anisotropicIblRoughness(float(roughness), float(strength));
                    const double approximation = bentSplitSum(roughness, isotropicAlbedo(N, V, iblRoughness));
                    // The same at r' throughout: blurred across the brushing as along it (measured, not used).
                    const double meanRoughness = bentSplitSum(iblRoughness, isotropicAlbedo(N, V, iblRoughness));
                    const double bentError = std::abs(approximation - truth) / truth;
                    const double beforeError = std::abs(before - truth) / truth;
                    const double isotropicError = std::abs(isotropic - truth) / truth;
                    std::printf("%s roughness %.1f N.V %.1f strength %.1f: truth %.5f, now %.5f (%.1f%%), before (bent normal at "
                                "r) %.5f (%.1f%%), isotropic %.5f (%.1f%%); albedo: anisotropic lobe %.3f, split sum E %.3f\n",
                                kEnvironmentNames[kind], roughness, NoV, strength, truth, approximation, 100.0 * bentError, before,
                                100.0 * beforeError, isotropic, 100.0 * isotropicError, truthAndAlbedo.y, albedo);
                    EXPECT_TRUE(std::isfinite(approximation));
                    if (strength == 0.0) {
                        worstStrengthZero[kind] = std::max(worstStrengthZero[kind], bentError);
                        EXPECT_NEAR(approximation, before, 1e-6 * before) << "strength 0 reads the material's roughness";
                    } else {
                        worstBent[kind] = std::max(worstBent[kind], bentError);
                        worstBefore[kind] = std::max(worstBefore[kind], beforeError);
                        worstIsotropic[kind] = std::max(worstIsotropic[kind], isotropicError);
                        sumBent[kind] += bentError, sumBefore[kind] += beforeError, ++count[kind];
                        sumMeanRoughness[kind] += std::abs(meanRoughness - truth) / truth;
                    }
                }
            }
    for (int kind : {0, 1, 2})
        std::printf("[ measured ] anisotropyIblRelativeError %s: now mean %.4g max %.4g; before (E at r) mean %.4g max %.4g; "
                    "all at r' mean %.4g; isotropic split sum max %.4g; strength 0: %.4g\n",
                    kEnvironmentNames[kind], sumBent[kind] / count[kind], worstBent[kind], sumBefore[kind] / count[kind],
                    worstBefore[kind], sumMeanRoughness[kind] / count[kind], worstIsotropic[kind], worstStrengthZero[kind]);
    // Strength 0 is the split sum's own error (no bending, the material's roughness); the rest is
    // what the approximation of the anisotropic lobe adds. Bounds a little above the measured
    // values (docs/materials.md), so a change that makes the approximation worse shows here; and
    // the stretched lobe's energy keeps the approximation below the one with E at r.
    EXPECT_LE(worstStrengthZero[0], 0.25);
    EXPECT_LE(worstStrengthZero[1], 0.10);
    EXPECT_LE(sumBent[0], 0.4 * sumBefore[0]);
    EXPECT_LE(sumBent[1], 0.75 * sumBefore[1]);
    EXPECT_LE(sumBent[2], 0.8 * sumBefore[2]);
    EXPECT_LE(worstBent[0], 0.4);
    EXPECT_LE(worstBent[1], 1.5);
    EXPECT_LE(worstBent[2], 4.5);
}

}  // namespace
}  // namespace candela::test
