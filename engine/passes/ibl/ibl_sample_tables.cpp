#include "passes/ibl/ibl_sample_tables.h"

#include "shared/brdf_sheen.h"
#include "shared/ibl.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace candela::passes {

using namespace shading;

namespace {
float texelSolidAngle(uint32_t faceSize) { return 4.0f * CANDELA_PI / (6.0f * float(faceSize) * float(faceSize)); }

// The sheen lobe f_sheen(n, n, l) · n·l for n = v at angle θ between n and l: D(θ_h = θ/2) /
// (4 (1 + Λ(1) + Λ(cos θ))), in double (D ~ 0.5^(1/2α) is below a float's range at small α).
double charlieLobe(double theta, double alpha) {
    const auto lambda = [&](double c) { return double(shading::sheenLambda(float(c), float(alpha))); };
    const double sin2h = std::pow(std::sin(0.5 * theta), 2.0);
    const double D = (2.0 + 1.0 / alpha) * std::pow(sin2h, 0.5 / alpha) / (2.0 * std::numbers::pi);
    return D / (4.0 * (1.0 + lambda(1.0) + lambda(std::cos(theta))));
}

// GGX D(h) (n·l) / 4 for n = v at angle θ between n and l (n·h = cos(θ/2)).
double ggxLobe(double theta, double alpha) {
    const double noh = std::cos(0.5 * theta);
    const double a2 = alpha * alpha;
    const double d = noh * noh * (a2 - 1.0) + 1.0;
    return a2 / (std::numbers::pi * d * d) * std::cos(theta) * 0.25;
}
}  // namespace

SampleTable prefilterSamples(float roughness, uint32_t count, uint32_t sourceFaceSize, uint32_t sourceMips,
                             bool filtered, float lodBias) {
    SampleTable table;
    const float alpha = roughness * roughness;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec4 h = sampleGgxHalfVector(hammersley(i, count), alpha);
        // n = v: l = reflect(−n, h), n·l = 2 (n·h)² − 1, pdf(l) = D / 4.
        const float NoL = 2.0f * h.w - 1.0f;
        if (NoL <= 0.0f) continue;
        const glm::vec3 l(2.0f * h.z * h.x, 2.0f * h.z * h.y, NoL);
        const float pdf = ggxD(h.w, 1.0f - h.w, alpha) * 0.25f;
        const float lod = filtered ? filteredLod(pdf, count, texelSolidAngle(sourceFaceSize), float(sourceMips - 1), lodBias) : 0.0f;
        table.samples.emplace_back(glm::normalize(l), lod);
        table.totalWeight += NoL;
    }
    return table;
}

SampleTable charlieSamples(float roughness, uint32_t count, uint32_t sourceFaceSize, uint32_t sourceMips,
                           bool filtered, float lodBias) {
    // The lobe over θ ∈ [0, π/2] for n = v: g(θ) = f·cos·sin θ (charlieLobe).
    const double alpha = shading::sheenAlpha(roughness);
    const auto lobe = [&](double theta) { return charlieLobe(theta, alpha) * std::sin(theta); };
    constexpr int kBins = 4096;
    const double dTheta = 0.5 * std::numbers::pi / kBins;
    std::vector<double> cdf(kBins + 1, 0.0);
    for (int b = 0; b < kBins; ++b) cdf[b + 1] = cdf[b] + lobe((b + 0.5) * dTheta) * dTheta;
    const double total = cdf[kBins];
    SampleTable table;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec2 xi = hammersley(i, count);
        const double target = double(xi.x) * total;
        const int b = int(std::upper_bound(cdf.begin(), cdf.end(), target) - cdf.begin()) - 1;
        const int bin = std::clamp(b, 0, kBins - 1);
        const double within = cdf[bin + 1] > cdf[bin] ? (target - cdf[bin]) / (cdf[bin + 1] - cdf[bin]) : 0.5;
        const double theta = (bin + std::clamp(within, 0.0, 1.0)) * dTheta;
        const double phi = 2.0 * std::numbers::pi * double(xi.y);
        const glm::vec3 l(glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
        // pdf(l) = g(θ) / (total · 2π sin θ), the density per steradian of this sampling.
        const double pdf = lobe((bin + 0.5) * dTheta) / (total * 2.0 * std::numbers::pi * std::max(std::sin(theta), 1e-6));
        const float lod =
            filtered ? filteredLod(float(pdf), count, texelSolidAngle(sourceFaceSize), float(sourceMips - 1), lodBias) : 0.0f;
        table.samples.emplace_back(glm::normalize(l), lod);
        table.totalWeight += 1.0f;
    }
    return table;
}

std::vector<float> lobeTable(FilterLobe lobe, float roughness) {
    const double ggxAlpha = double(roughness) * roughness;
    const double sheenAlpha = shading::sheenAlpha(roughness);
    const auto weight = [&](double theta) {
        switch (lobe) {
            case FilterLobe::Ggx: return ggxLobe(theta, ggxAlpha);
            case FilterLobe::Charlie: return charlieLobe(theta, sheenAlpha);
            case FilterLobe::Cosine: return std::cos(theta);
        }
        return 0.0;
    };
    constexpr double kHalfPi = 0.5 * std::numbers::pi;
    // ∫ weight dω = 2π ∫ weight(θ) sin θ dθ over θ = (π/2) t², dθ = π t dt: midpoints in t.
    constexpr int kSteps = 1 << 16;
    double total = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double t = (i + 0.5) / kSteps;
        const double theta = kHalfPi * t * t;
        total += weight(theta) * std::sin(theta) * std::numbers::pi * t / kSteps;
    }
    total *= 2.0 * std::numbers::pi;
    std::vector<float> table(CANDELA_IBL_LOBE_TABLE_SIZE, 0.0f);
    if (!(total > 0.0)) return table;
    for (uint32_t j = 0; j < table.size(); ++j) {
        const double t = double(j) / (table.size() - 1);
        table[j] = float(std::max(weight(kHalfPi * t * t), 0.0) / total);
    }
    return table;
}

SampleTable irradianceSamples(uint32_t count, uint32_t sourceFaceSize, uint32_t sourceMips, bool filtered,
                              float lodBias) {
    SampleTable table;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 l = sampleCosine(hammersley(i, count));
        const float pdf = l.z / CANDELA_PI;
        const float lod = filtered ? filteredLod(pdf, count, texelSolidAngle(sourceFaceSize), float(sourceMips - 1), lodBias) : 0.0f;
        table.samples.emplace_back(l, lod);
        table.totalWeight += 1.0f;
    }
    return table;
}

}  // namespace candela::passes
