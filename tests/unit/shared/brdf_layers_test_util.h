#pragma once
// What the material layers' float tests share (brdf_layers_test.cpp, brdf_transmission_layers_test.cpp):
// the grid of inputs both the float evaluation (shaders/shared/brdf_layers.h compiled as C++) and
// the double-precision reference (brdf_reference.h) take, the comparison of their channels and the
// check of what it measured, and the neutral value of each layer.
//
// Metric (reference::ErrorStats): max relative error per channel where the reference is ≥ kFloor,
// max absolute error below. Tolerances: relative kTolerance (as for the core Cook-Torrance BRDF,
// brdf_test.cpp), absolute kAbsoluteTolerance.
#include "brdf_reference.h"
#include "shared/brdf_layers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace candela::test::layers {

namespace ref = reference;

inline constexpr double kTolerance = 1e-5;
inline constexpr double kAbsoluteTolerance = 1e-9;
inline constexpr double kFloor = 1e-6;

inline const std::vector<double> kCosines = {-0.5, 0.0, 1e-6, 1e-3, 0.05, 0.2, 0.5, 0.8, 0.99, 1.0};
inline const std::vector<float> kMetallics = {0.0f, 0.5f, 1.0f};
inline const std::vector<glm::vec3> kBaseColors = {glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0.955f, 0.638f, 0.538f)};

// The unit direction at cos θ = `cosTheta` from +Z and azimuth `phi`, computed in double and
// rounded to float. Not inlined: inlined into the tests' loops, GCC 12's vectorizer at -O2 kept
// some components unrounded (a float holding −0x1.ffffef390818fp-1), so the float evaluation and the
// reference saw different inputs (1% apart at a mirror peak).
[[gnu::noinline]] inline glm::vec3 direction(double cosTheta, double phi) {
    const double sinTheta = std::sqrt(std::max(1.0 - cosTheta * cosTheta, 0.0));
    return glm::vec3(glm::dvec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
}

// Prints what `stats` measured for `lobe` and checks it: relative error within `tolerance`,
// absolute error below the floor within kAbsoluteTolerance, and no NaN, Inf or negative value
// (`bad` counts them).
inline void expectWithinTolerance(const char* lobe, const ref::ErrorStats& stats, uint64_t bad, double tolerance) {
    std::cout << lobe << ": " << stats.compared << " values, max relative error " << stats.maxRelative
              << ", max absolute error below the floor " << stats.maxAbsolute << "\n  worst: " << stats.worstRelative << "\n";
    EXPECT_EQ(bad, 0u) << "NaN, Inf or negative values";
    EXPECT_LE(stats.maxRelative, tolerance) << stats.worstRelative;
    EXPECT_LE(stats.maxAbsolute, kAbsoluteTolerance) << stats.worstAbsolute;
}

// One input of the layers' float tests: what the float and the double evaluation both take.
struct LobeInput {
    glm::vec3 N, V, L, base;
    float metallic, roughness;
    uint32_t model;
};

// Calls `f(input)` over the grid the layers' float tests share: both Cook-Torrance models, N·V and
// N·L from kCosines — with `behindToo`, each L also mirrored below the surface — azimuths 0, π/2
// and π, roughness 0 (clamped), 0.3 and 1, kMetallics, kBaseColors.
template <class F>
void forEachLobeInput(bool behindToo, F&& f) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (uint32_t model : {uint32_t(ref::kPbr), uint32_t(ref::kPbrSchlickGgx)})
        for (double cv : kCosines)
            for (double cl : kCosines)
                for (double side : {1.0, -1.0})
                    for (double phi : {0.0, std::numbers::pi / 2, std::numbers::pi})
                        for (float roughness : {0.0f, 0.3f, 1.0f})
                            for (float metallic : kMetallics)
                                for (const glm::vec3& base : kBaseColors) {
                                    if (side < 0.0 && !behindToo) continue;
                                    f(LobeInput{N, direction(cv, 0.0), direction(side * cl, phi), base, metallic, roughness, model});
                                }
}

// The reference of `in` with `layers` (ref::brdfTimesCosineLayered).
inline glm::dvec3 referenceOf(const LobeInput& in, const ref::Layers& layers) {
    return ref::brdfTimesCosineLayered(glm::dvec3(in.N), glm::dvec3(in.V), glm::dvec3(in.L), glm::dvec3(in.base), in.metallic,
                                       in.roughness, in.model, layers);
}

// Adds the three channels of `got` against `expected` to `stats` and counts the non-finite or
// negative ones in `bad`; `layer` names the layer settings in the worst cases' descriptions.
inline void compareChannels(ref::ErrorStats& stats, uint64_t& bad, const LobeInput& in, glm::vec3 got, glm::dvec3 expected,
                            const std::string& layer) {
    for (int c = 0; c < 3; ++c) {
        bad += std::isfinite(got[c]) && got[c] >= 0.0f ? 0 : 1;
        stats.add(got[c], expected[c], [&] {
            std::ostringstream s;
            s.precision(9);
            s << layer << " model " << in.model << " V=(" << in.V.x << "," << in.V.y << "," << in.V.z << ") L=(" << in.L.x << ","
              << in.L.y << "," << in.L.z << ") metallic " << in.metallic << " roughness " << in.roughness << " channel " << c
              << ": float " << got[c] << ", double " << expected[c];
            return s.str();
        });
    }
}

// Each layer's neutral value (the layer present in the bits evaluates to nothing).
inline shading::Sheen noSheen() { return shading::sheenLayer(glm::vec3(0.0f), 0.0f, 0.0f); }
inline shading::Anisotropy noAnisotropy() {
    return shading::anisotropyLayer(0.0f, glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}
inline shading::Transmission noTransmission() { return shading::transmissionLayer(0.0f, 0.0f, 1.5f); }
inline shading::DiffuseTransmission noDiffuseTransmission() { return shading::diffuseTransmissionLayer(0.0f, glm::vec3(0.0f)); }

}  // namespace candela::test::layers
