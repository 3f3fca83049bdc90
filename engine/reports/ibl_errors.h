#pragma once
// The error metrics of `candela ibl-report`: how far the GPU's precomputed IBL maps (read back as
// CachedImages, see IblMaps::readBack) are from the converged double-precision reference of
// ibl_reference.h. Pure C++, no Vulkan calls (VkFormat values are plain numbers here).
//
//     const assets::Environment ref = referenceEnvironment(env);     // ≤ 512 texels wide
//     ReferenceCache cache;                                         // one per environment
//     for (const LevelErrors& level : specularErrors(specular, env, ref, 128, cache)) ...
//     const ErrorStats diffuse = irradianceErrors(irradianceSh, ref, 256, cache);
//     const LutErrors lut = lutErrors(brdfLut, 4);
//
// What is compared:
//   specular     mip m of the "specular" cube (roughness m/(mips−1)) against
//                reference::prefiltered(reference, texel-centre direction, roughness) at a fixed,
//                deterministic set of texels spread over all six faces (specularSampleTexels);
//                mip 0 (roughness 0, the environment itself) against reference::bilinear of the
//                ORIGINAL environment at the texel centre.
//   irradiance   "irradiance_sh" (evaluated as the forward shader does) or "irradiance_cube"
//                (sampled bilinearly, seamlessly across faces) against reference::irradiance at
//                spherical-Fibonacci directions.
//   BRDF LUT     (A, B) of "brdf_lut" against reference::splitSum at a grid of texels; absolute.
// Specular and irradiance compare the luminance (Rec. 709: 0.2126 R + 0.7152 G + 0.0722 B) of
// the GPU texel with that of the reference, as relative errors (ErrorStats).
//
// Why a downsampled reference: prefiltered() and irradiance() are sums over every texel of the map
// (O(texels) per value), so a 4096×2048 environment costs ≈ 8M texel visits per compared texel.
// referenceEnvironment box-filters it, energy-preservingly, to ≤ 512×256 (≈ 130k texels, ≈ 0.6 ms
// per prefiltered value; 6 levels × 128 texels ≈ 0.4 s on one core). The cost in accuracy is one
// more box blur of one reference texel (0.7° at 512 wide) on top of the lobe, which matters only
// where the lobe is not many texels wide. Measured on a 2048×1024 sky with a 2.3° sun of 2000×
// the sky's radiance, the 512 reference against the 2048 one: roughness 0.2 — 1e-4 relative RMS,
// 2.5e-4 max away from the sun, 1.1e-3 at the sun's centre; roughness 0.1 — 4.3e-3 at the sun;
// roughness ≥ 0.4 — ≤ 2e-4 everywhere; irradiance (a 90° cosine lobe) ≤ 5e-5. So errors the
// report shows above ~1e-3 are the GPU's, for roughness ≥ 0.2. Mip 0 (roughness 0), where the
// blur would dominate, compares against the original. A roughness below reference::prefiltered's
// narrow-lobe limit (r < 0.078 at 256 rows) compares against the downsampled map's bilinear
// value: such a level measures resolution rather than filtering.

#include "assets/environment.h"
#include "ibl/ibl_cache_file.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <vector>

namespace candela::reports {

// The VkFormat values of the read-back maps (vulkan_core.h; checked in ibl_errors.cpp).
inline constexpr uint32_t kFormatRg16Sfloat = 83;      // VK_FORMAT_R16G16_SFLOAT: "brdf_lut"
inline constexpr uint32_t kFormatRgba16Sfloat = 97;    // VK_FORMAT_R16G16B16A16_SFLOAT: cubes
inline constexpr uint32_t kFormatRgba32Sfloat = 109;   // VK_FORMAT_R32G32B32A32_SFLOAT: "irradiance_sh"

// Relative errors of one set of compared values (luminances: GPU g_i against reference r_i ≥ 0).
// Non-finite GPU values (NaN, ±Inf) are counted in `count`, clear `finite` and are left out of
// rmse and maxRelative (which then describe the finite values only).
struct ErrorStats {
    double rmse = 0;         // sqrt(mean((g − r)²)) / mean(r): relative RMSE. With mean(r) = 0: 0 if
                             // every g equals its r, else +Inf.
    double maxRelative = 0;  // max |g − r| / (r + floor), floor = 1e-2 · mean(r): near-black texels
                             // are measured against 1% of the level's mean instead of exploding.
                             // With mean(r) = 0: 0 if all equal, else +Inf.
    double meanRelative = 0; // mean of the same relative errors: robust where a few values near a
                             // small bright source dominate rmse and maxRelative
    uint32_t count = 0;      // values compared
    bool finite = true;      // false if any GPU value was NaN or ±Inf
};

// The stats of GPU values `gpu` against reference values `ref` (luminances, same length; throws
// std::invalid_argument otherwise). Empty input: all zero, finite.
ErrorStats errorStats(std::span<const double> gpu, std::span<const double> ref);

// One mip of the specular cube.
struct LevelErrors {
    float roughness = 0;    // m / (mips − 1) (0 for a single mip)
    uint32_t faceSize = 0;  // the mip's face size
    ErrorStats stats;
};

// Absolute errors of the BRDF LUT: |A_gpu − A_ref|, |B_gpu − B_ref| and |(A + B)_gpu − (A + B)_ref|
// (the latter is what the multiscatter compensation reads), max and RMS over the compared texels.
// Non-finite texels clear `finite` and are left out of the rest.
struct LutErrors {
    double maxA = 0, maxB = 0, maxSum = 0;
    double rmsA = 0, rmsB = 0, rmsSum = 0;
    uint32_t count = 0;  // texels compared
    bool finite = true;
};

// ---- Reference ------------------------------------------------------------------------------------

// A reference environment for the comparisons: `env` box-filtered so that its width is ≤ maxWidth.
// The output size is that of halving both dimensions (rounding up, never below 1) until the width
// is ≤ maxWidth; an environment already that small is returned unchanged. Each output texel is the
// solid-angle-weighted mean of the source texels it covers (fractionally, for odd sizes), computed
// in double in one pass, so Σ L Ω over the map — the mean radiance — is preserved to float
// rounding. `source` is kept; warnings are dropped. Throws std::invalid_argument for an empty
// environment or maxWidth = 0.
assets::Environment referenceEnvironment(const assets::Environment& env, uint32_t maxWidth = 512);

// A memo of reference values, so that a sweep comparing many settings at the same cube size (or
// irradiance direction count) computes each reference value once. Keyed by what determines the
// value apart from the environment: (kind, face size or direction count, roughness as the reduced
// fraction m/(mips − 1) — so roughness 0.5 at mip 1 of 3 and mip 2 of 5 is one value, and mip 0
// is one value whatever the mip count —, texel or direction index). Owned by the caller, one per
// (original, reference) environment pair: it remembers the reference environment's dimensions on
// first use and throws std::invalid_argument when called with other dimensions (a cheap guard, not
// a content check). Not thread-safe.
class ReferenceCache {
public:
    enum class Kind : uint32_t { Specular, Irradiance };
    using Key = std::array<uint32_t, 5>;  // kind, size, roughness numerator, denominator, index

    // The value stored under `key`, computing it with `compute` on the first request.
    glm::dvec3 get(const Key& key, const std::function<glm::dvec3()>& compute);
    // Records the reference environment's dimensions (first call) or checks them (later calls).
    void checkEnvironment(const assets::Environment& reference);

    size_t size() const { return mValues.size(); }  // values stored
    uint64_t hits() const { return mHits; }         // requests answered from the memo

private:
    std::map<Key, glm::dvec3> mValues;
    uint64_t mHits = 0;
    uint32_t mWidth = 0, mHeight = 0;
};

// ---- Comparisons ----------------------------------------------------------------------------------

// The "specular" cube (RGBA16F, 6 layers, `mips` mips) against the reference, one LevelErrors per
// mip: at min(texelsPerLevel, 6·s²) texels of each mip (specularSampleTexels), direction = texel
// centre, roughness = m/(mips − 1); mip 0 against reference::bilinear(original, ·), the others
// against reference::prefiltered(reference, ·, roughness). Throws std::invalid_argument if the
// image is not a 6-layer cube of a supported format.
std::vector<LevelErrors> specularErrors(const ibl::CachedImage& specular, const assets::Environment& original,
                                        const assets::Environment& reference, uint32_t texelsPerLevel,
                                        ReferenceCache& cache);

// The irradiance map ("irradiance_sh": 9×1 RGBA32F texels of coefficients, irradiance/π =
// Σ sh[i].rgb · Y_i(n) with Y = reference::shBasis, clamped at 0 per channel as the forward shader
// does; or "irradiance_cube": a 6-layer cube read by sampleCube at mip 0) against
// reference::irradiance(reference, n) at `directions` spherical-Fibonacci directions
// (fibonacciDirection). Throws std::invalid_argument for another name or a wrong shape.
ErrorStats irradianceErrors(const ibl::CachedImage& irradiance, const assets::Environment& reference, uint32_t directions,
                            ReferenceCache& cache);

// The "brdf_lut" (RG16F, size × size, size ≥ 2) against reference::splitSum at every `stride`-th
// texel in x and y (stride ≥ 1) plus always the last column and row: texel (x, y) stands for
// N·V = max(x/(size−1), 1e-4) and perceptual roughness y/(size−1). Throws std::invalid_argument
// for a wrong shape or stride 0.
LutErrors lutErrors(const ibl::CachedImage& lut, uint32_t stride);

// ---- Helpers (exposed for the tests and the report) ----------------------------------------------

// Rec. 709 luminance.
double luminance(const glm::dvec3& rgb);

// Texel (x, y) of `layer` of `mip` decoded as RGBA float: RGBA16F, RG16F (B = 0, A = 1) or RGBA32F.
// Throws std::invalid_argument for another format or a texelBytes that disagrees with it,
// std::out_of_range for coordinates outside the image or data too short for them.
glm::vec4 texelValue(const ibl::CachedImage& image, uint32_t mip, uint32_t layer, uint32_t x, uint32_t y);

// The unit direction through the centre of texel (x, y) of `face` of a cube mip of face size s
// (shared/ibl.h's cubeFaceDirection: faces +X −X +Y −Y +Z −Z, rows top first).
glm::dvec3 cubeTexelDirection(uint32_t face, uint32_t x, uint32_t y, uint32_t faceSize);

// The cube `image` at `mip` in non-zero `direction`, bilinear between texel centres as the GPU
// samples a cube (seamless): the face of the largest |component| (ties: x, then y, then z); a
// footprint texel beyond that face's edge is the adjacent face's texel containing the extrapolated
// texel centre. At the eight corners (a 2×2 footprint over three faces) the GPU averages the three
// texels instead; here the missing one is an edge texel of a neighbour face.
glm::vec4 sampleCube(const ibl::CachedImage& image, uint32_t mip, const glm::dvec3& direction);

// The texels compared at a cube mip of face size s: min(count, 6·s²) distinct linear indices
// face·s² + y·s + x. Sample k is on face k mod 6 (all faces equally); within a face, sample
// j = k div 6 is texel (c + j·a) mod s², c = the centre texel (s/2)·s + s/2 and a the first integer
// ≥ round(0.618·s²) coprime to s² (a golden-ratio stride), so the samples are distinct and spread
// over rows and columns. Deterministic.
std::vector<uint32_t> specularSampleTexels(uint32_t faceSize, uint32_t count);

// Point i of n ≥ 1 on the spherical Fibonacci lattice: y = 1 − (2i + 1)/n, azimuth 2π·i·(φ − 1).
glm::dvec3 fibonacciDirection(uint32_t i, uint32_t n);

}  // namespace candela::reports
