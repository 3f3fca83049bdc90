#pragma once
// Sample tables of the IBL filtering passes (ibl_prefilter, ibl_irradiance_cube), built on the CPU
// once per setting and read by every texel: for each sample its direction in the texel's tangent
// frame (z = the texel's direction) and the source mip it reads (filtered importance sampling), so
// the shaders only rotate, fetch and sum.
// Uses the sampling functions of shaders/shared/ibl.h, so CPU and GPU agree by construction. Pure.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace candela::passes {

struct SampleTable {
    std::vector<glm::vec4> samples;  // xyz: unit direction in tangent space (z ≥ 0), w: source lod
    float totalWeight = 0.0f;        // prefilter: Σ z (the n·l weights); irradiance: sample count
};

// GGX-prefilter samples for perceptual roughness > 0 (n = v): `count` Hammersley half vectors,
// reflected, those below the horizon dropped. With `filtered`, lod = the source mip matching the
// sample's solid angle plus `lodBias` (Křivánek & Colbert use +1), else 0 (plain importance sampling).
// sourceFaceSize: face size of the source cube's mip 0; sourceMips: its mip count.
SampleTable prefilterSamples(float roughness, uint32_t count, uint32_t sourceFaceSize, uint32_t sourceMips,
                             bool filtered, float lodBias);

// Charlie (sheen) prefilter samples for perceptual sheen roughness r (n = v, as the split sum
// assumes): directions l distributed exactly as the sheen lobe f_sheen(n, n, l) · n·l
// (shared/brdf_sheen.h) — θ by inverting its marginal, tabulated in double (the lobe underflows a
// float at small roughness), φ uniform — so every sample weighs 1. Lods as for prefilterSamples.
SampleTable charlieSamples(float roughness, uint32_t count, uint32_t sourceFaceSize, uint32_t sourceMips,
                           bool filtered, float lodBias);

// The lobe a filter pass convolves with, as a function of the angle θ between the texel's direction
// n and a light direction l (n = v, as the split sum assumes), normalised to a weight per steradian
// that integrates to 1: the value a pass's sampled estimate converges to for a point source of flux
// Φ (radiance × solid angle) in direction l is Φ · lobe(θ). The bright texels
// (engine/ibl_maps/bright_texels.h) are added with it.
//   Ggx: D(h) (n·l) / 4 for perceptual roughness r (α = r²), h halfway between n and l — the
//     prefilter's n·l-weighted GGX samples;
//   Charlie: the sheen lobe f_sheen(n, n, l) n·l for sheen roughness r — charlieSamples' density;
//   Cosine: n·l / π, the irradiance cube's (r ignored).
// CANDELA_IBL_LOBE_TABLE_SIZE entries at θ_j = (π/2)(j / (size − 1))² (shaders/shared/ibl.h); the lobe
// is 0 beyond π/2. Computed in double. Pure.
enum class FilterLobe { Ggx, Charlie, Cosine };
std::vector<float> lobeTable(FilterLobe lobe, float roughness);

// Cosine-weighted hemisphere samples for irradiance (each weight 1).
SampleTable irradianceSamples(uint32_t count, uint32_t sourceFaceSize, uint32_t sourceMips, bool filtered,
                              float lodBias);

}  // namespace candela::passes
