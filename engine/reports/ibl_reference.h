#pragma once
// Double-precision CPU reference of image-based lighting: the split-sum DFG terms, prefiltered
// radiance, irradiance and its SH9 approximation, written in textbook form independently of the GPU
// shaders. Used by the renderer's numerical tests (white furnace, LUT checks, prefilter/irradiance
// error) and by `candela ibl-report`. Deterministic (fixed quadratures, no random numbers), pure
// (no state, safe to call from several threads), and meant to be called per texel in loops.
//
// Conventions:
//   - roughness is perceptual roughness r ∈ [0, 1]; GGX α = r². Unlike shaders/shared/brdf.h there
//     is no roughness clamp: r = 0 is a perfect mirror (handled analytically, as a delta).
//   - D(h) = α² / (π ((n·h)² (α² − 1) + 1)²)            (GGX / Trowbridge-Reitz)
//     V    = 0.5 / (n·l √((n·v)² (1 − α²) + α²) + n·v √((n·l)² (1 − α²) + α²))
//                                                         (height-correlated Smith-GGX)
//     Fc   = (1 − v·h)⁵                                   (Schlick's Fresnel weight)
//   - directions: the equirectangular convention of shaders/shared/environment.h at rotation 0
//     (u = 0.5 + atan2(d.z, d.x)/2π, v = acos(d.y)/π, row 0 = top = +Y). Texel (x, y) stands for the
//     direction of its centre, uv = ((x + 0.5)/W, (y + 0.5)/H), and covers the exact solid angle
//     Ω = (2π/W)(cos θ0 − cos θ1), θ0 = πy/H, θ1 = π(y + 1)/H (the Ω of a map sum to 4π).
//   - radiance is in the environment's units (linear RGB, as stored).
//
//     namespace ref = candela::ibl::reference;
//     const ref::SplitSum dfg = ref::splitSum(NoV, roughness);       // f0·dfg.a + dfg.b
//     const glm::dvec3 specular = ref::prefiltered(env, R, roughness);
//     const glm::dvec3 diffuse = ref::irradiance(env, n);            // white Lambertian radiance

#include "assets/environment.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <functional>

namespace candela::reports::reference {

// ---- Split sum ---------------------------------------------------------------------------------

// The split-sum DFG terms of the GGX specular lobe for a view at n·v = NoV:
//     a = ∫ (1 − Fc) D V (n·l) dl        b = ∫ Fc D V (n·l) dl
// over the hemisphere of light directions l (dimensionless), so the single-scattering directional
// albedo of a specular colour f0 is f0·a + b.
struct SplitSum {
    double a = 0.0;  // scale of f0
    double b = 0.0;  // bias
};

// The split-sum terms for NoV ∈ (0, 1] (clamped to [1e-4, 1]) and perceptual roughness ∈ [0, 1]
// (clamped). Converged to ≤ 2e-5 absolute for all inputs (tests/unit/reports/ibl_reference_test.cpp).
// Roughness < 1e-4 (α < 1e-8) is the mirror: a = 1 − Fc(NoV), b = Fc(NoV).
//
// Method: the integral over the half vector h with the GGX change of variables, h drawn by the
// inverse CDF of D(h)(n·h) — the integrand becomes V·4(n·l)(v·h)/(n·h) for l = reflect(−v, h) — in
// the variable s = ln(tan θh / α) (dξ = ds / (2 cosh² s), so narrow lobes need no special case),
// by composite Gauss-Legendre quadrature in s and in the azimuth φ of h. The region n·l > 0 is
// resolved analytically (for θh < π/4 − θv/2 every φ; up to θh < π/4 + θv/2 the φ with
// cos φ > −cot θv cot 2θh), so the quadrature never integrates across the horizon's kink.
// A few thousand integrand evaluations: ≈ 60 µs per call.
SplitSum splitSum(double NoV, double roughness);

// The same with every quadrature grid refined `refinement` times (≥ 1) in each dimension: the
// convergence check of the tests (splitSum(NoV, r) is splitSumRefined(NoV, r, 1)).
SplitSum splitSumRefined(double NoV, double roughness, int refinement);

// a + b: the directional albedo E(NoV) of a white metal (F = 1) — the single-scattering energy of
// the GGX lobe, ≤ 1 (the white furnace). Same preconditions as splitSum.
double directionalAlbedo(double NoV, double roughness);

// ---- Environment integrals (O(texels) each) -----------------------------------------------------

// The environment bilinearly interpolated at unit `direction`: texel centres at ((x + 0.5)/W,
// (y + 0.5)/H), wrapping in u and clamping in v (the rows at the poles are held). A direction
// within 1e-9 texel of a texel centre returns that texel's value exactly. At the poles
// (d.x = d.z = 0) u = 0.5, as in shaders/shared/environment.h. Preconditions: env is not empty;
// direction is non-zero (it is normalised).
glm::dvec3 bilinear(const assets::Environment& env, const glm::dvec3& direction);

// Split-sum prefiltered radiance along unit reflection direction R (with n = v = R):
//     Σ L(l) D(h) max(n·l, 0) Ω  /  Σ D(h) max(n·l, 0) Ω,     h = normalize(R + l),
// over the texels l of the map. Normalised by the discrete weight, so a constant environment gives
// exactly that constant at any resolution. Rows entirely below R's horizon (n·l ≤ 0, weight exactly
// 0) are skipped; nothing else is (GGX's tails are not negligible anywhere above the horizon).
//
// Narrow lobes: when 2α < π/H — the lobe's angular radius in l (2θh, where D has fallen to 1/4 of
// its peak at θh = α) is smaller than one texel's height — the texel sum would return the nearest
// texel; the reference then returns bilinear(env, R) instead (and always for roughness 0, the
// mirror). H = 256: r < 0.078; H = 512: r < 0.055; H = 1024: r < 0.039.
// Preconditions: env is not empty; roughness ∈ [0, 1] (clamped).
glm::dvec3 prefiltered(const assets::Environment& env, const glm::dvec3& R, double roughness);

// The outgoing radiance of a white Lambertian surface with unit normal n:
//     (1/π) ∫ L(l) max(n·l, 0) dl   ≈   Σ L(l) max(n·l, 0) Ω  /  Σ max(n·l, 0) Ω.
// The discrete cosine weight Σ max(n·l, 0) Ω (→ π as the map is refined) normalises it, so a
// constant environment c gives exactly c at any resolution. Precondition: env is not empty.
glm::dvec3 irradiance(const assets::Environment& env, const glm::dvec3& n);

// ---- Spherical harmonics (order 2, 9 coefficients) ----------------------------------------------

// RGB coefficients L_lm in the order of shBasis.
using Sh9 = std::array<glm::dvec3, 9>;

// The real SH basis at unit direction d, in this order (constants in closed form, in double):
//     Y00  = √(1/4π)                    = 0.282095
//     Y1−1 = √(3/4π) y,  Y10 = √(3/4π) z,  Y11 = √(3/4π) x                      (0.488603)
//     Y2−2 = √(15/4π) x y,  Y2−1 = √(15/4π) y z                                 (1.092548)
//     Y20  = √(5/16π) (3z² − 1)                                                  (0.315392)
//     Y21  = √(15/4π) x z,  Y22 = √(15/16π) (x² − y²)                            (1.092548, 0.546274)
std::array<double, 9> shBasis(const glm::dvec3& d);

// The projection L_lm = Σ L(l) Y_lm(l) Ω over the texels of the map (point-sampled at the texel
// centres). Precondition: env is not empty.
Sh9 projectSh9(const assets::Environment& env);

// The white Lambertian radiance of an SH9 environment at unit normal n:
//     (1/π) Σ Â_l L_lm Y_lm(n),   Â0 = π, Â1 = 2π/3, Â2 = π/4
// (the clamped cosine's zonal coefficients), so a constant environment c gives c.
glm::dvec3 irradianceFromSh9(const Sh9& sh, const glm::dvec3& n);

// ---- Test environments ---------------------------------------------------------------------------

// A width × height equirectangular map whose texel (x, y) holds radiance(d) at its centre direction
// d, stored as float; source "reference". Preconditions: width, height ≥ 1; radiance returns finite
// values ≥ 0 (as every Environment holds; not checked).
assets::Environment makeEnvironment(uint32_t width, uint32_t height,
                                   const std::function<glm::dvec3(const glm::dvec3& direction)>& radiance);

// The centre direction of texel (x, y) of a width × height map, and its solid angle (steradians).
glm::dvec3 texelDirection(uint32_t x, uint32_t y, uint32_t width, uint32_t height);
double texelSolidAngle(uint32_t y, uint32_t width, uint32_t height);

}  // namespace candela::reports::reference
