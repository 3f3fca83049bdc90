// KHR_materials_diffuse_transmission and KHR_materials_dispersion in float (shaders/shared/
// brdf_diffuse_transmission.h, brdf_transmission.h, combined by brdf_layers.h) against the
// double-precision reference written from the specifications (brdf_reference.h), the white
// furnace of the diffuse transmission under image-based light, and the extremes.
//
// Metric and tolerances of the layers' float tests (brdf_layers_test_util.h): relative 1e-5 where
// the reference is ≥ 1e-6, absolute 1e-9 below; no NaN, Inf or negative value.
#include "brdf_layers_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace candela::test {
namespace {

using namespace layers;

const glm::vec3 kOrange(1.0f, 0.35f, 0.05f);

// One diffuse transmission setting: its layer bits (CANDELA_LAYER_DIFFUSE_TRANSMISSION with the
// others it is combined with), weight and colour, and the transmission's weight.
struct DiffuseCase {
    uint32_t bits;
    float weight;
    glm::vec3 color;
    float transmission;
};

// Weights 1, 0.5 and 0 (the layer on but letting nothing through), white and orange; over the core
// Fresnel and the specular layer (IOR 1.33, colour (1, 0.5, 0.25)); with a transmission of 0.5
// (which overrides its share); under a sheen and a coat.
std::vector<DiffuseCase> diffuseCases() {
    const uint32_t dt = CANDELA_LAYER_DIFFUSE_TRANSMISSION;
    return {{dt, 1.0f, glm::vec3(1.0f), 0.0f},
            {dt, 0.5f, kOrange, 0.0f},
            {dt, 0.0f, kOrange, 0.0f},
            {dt | CANDELA_LAYER_SPECULAR, 1.0f, kOrange, 0.0f},
            {dt | CANDELA_LAYER_TRANSMISSION, 0.75f, kOrange, 0.5f},
            {dt | CANDELA_LAYER_TRANSMISSION | CANDELA_LAYER_SPECULAR, 1.0f, glm::vec3(1.0f), 1.0f},
            {dt | CANDELA_LAYER_SHEEN | CANDELA_LAYER_CLEARCOAT, 0.5f, kOrange, 0.0f}};
}

constexpr float kIor = 1.33f;
const glm::vec3 kSpecularColor(1.0f, 0.5f, 0.25f);

// The float layered lobes of `c` at `in`, all summed.
glm::vec3 diffuseFloat(const LobeInput& in, const DiffuseCase& c) {
    const shading::DielectricFresnel d = (c.bits & CANDELA_LAYER_SPECULAR) ? shading::dielectricFresnel(kIor, kSpecularColor, 1.0f)
                                                                           : shading::coreDielectricFresnel();
    const shading::LayeredLobes lobes = shading::layeredLobesTimesCosine(
        in.N, in.V, in.L, in.L, in.base, in.metallic, in.roughness, in.model, c.bits, d, noAnisotropy(),
        shading::transmissionLayer(c.transmission, in.roughness, kIor), shading::diffuseTransmissionLayer(c.weight, c.color),
        shading::sheenLayer(glm::vec3(0.8f, 0.3f, 0.1f), 0.3f, 0.5f), shading::clearcoatLayer(0.7f, 0.3f, in.N, in.V));
    return lobes.diffuse + lobes.specular + lobes.transmission + lobes.diffuseTransmission + lobes.sheen +
           glm::vec3(lobes.clearcoat);
}

ref::Layers diffuseReferenceLayers(const DiffuseCase& c) {
    return ref::Layers{.bits = c.bits, .ior = kIor, .specularColor = glm::dvec3(kSpecularColor), .clearcoat = 0.7,
                       .clearcoatRoughness = double(0.3f), .sheenColor = glm::dvec3(glm::vec3(0.8f, 0.3f, 0.1f)),
                       .sheenRoughness = double(0.3f), .sheenAlbedo = 0.5, .transmission = c.transmission,
                       .diffuseTransmission = c.weight, .diffuseTransmissionColor = glm::dvec3(c.color)};
}

// Every case over the shared grid, lights in front and mirrored behind the surface.
TEST(BrdfLayers, DiffuseTransmissionFloatMatchesDoubleReference) {
    ref::ErrorStats stats{.floor = kFloor};
    uint64_t bad = 0;
    for (const DiffuseCase& c : diffuseCases()) {
        std::ostringstream name;
        name << "diffuse transmission " << c.weight << " colour (" << c.color.x << "," << c.color.y << "," << c.color.z
             << ") transmission " << c.transmission << " bits " << c.bits;
        const ref::Layers layers = diffuseReferenceLayers(c);
        forEachLobeInput(true, [&](const LobeInput& in) {
            compareChannels(stats, bad, in, diffuseFloat(in, c), referenceOf(in, layers), name.str());
        });
    }
    expectWithinTolerance("diffuse transmission", stats, bad, kTolerance);
}

// The BTDF toward a light behind is the Lambert lobe toward that light mirrored to the front, in
// the colour of the transmission: with colour = base colour, diffuse transmission 1 moves the
// diffuse reflection to the back side unchanged — to float rounding (1e-6) where the specular layer
// gives the specification's dielectric; at metallic 0 and 1 the core's Lambert too, within 2e-4:
// its 1 − F is taken in float as 1 − (f0 + (1 − f0) x⁵), which keeps fewer digits where V·H is
// small than the BTDF's cancellation-free form.
TEST(BrdfLayers, DiffuseTransmissionBehindIsTheMirroredLambertLobe) {
    double worst[2] = {0.0, 0.0};
    forEachLobeInput(false, [&](const LobeInput& in) {
        if (in.L.z <= 0.0f || in.metallic == 0.5f) return;
        const glm::vec3 behind(in.L.x, in.L.y, -in.L.z);
        for (bool specular : {false, true}) {
            const uint32_t bits = CANDELA_LAYER_DIFFUSE_TRANSMISSION | (specular ? CANDELA_LAYER_SPECULAR : 0u);
            const shading::DielectricFresnel d =
                specular ? shading::dielectricFresnel(kIor, kSpecularColor, 1.0f) : shading::coreDielectricFresnel();
            const shading::LayeredLobes opaque = shading::layeredLobesTimesCosine(
                in.N, in.V, in.L, in.L, in.base, in.metallic, in.roughness, in.model, bits & ~CANDELA_LAYER_DIFFUSE_TRANSMISSION, d,
                noAnisotropy(), noTransmission(), noDiffuseTransmission(), noSheen(), shading::clearcoatLayer(0.0f, 0.0f, in.N, in.V));
            const shading::LayeredLobes back = shading::layeredLobesTimesCosine(
                in.N, in.V, behind, behind, in.base, in.metallic, in.roughness, in.model, bits, d, noAnisotropy(), noTransmission(),
                shading::diffuseTransmissionLayer(1.0f, in.base), noSheen(), shading::clearcoatLayer(0.0f, 0.0f, in.N, in.V));
            EXPECT_EQ(back.diffuse + back.specular, glm::vec3(0.0f)) << "nothing reflected from behind";
            for (int c = 0; c < 3; ++c) {
                const double expected = opaque.diffuse[c];
                const double difference = std::abs(double(back.diffuseTransmission[c]) - expected);
                worst[specular] = std::max(worst[specular], expected > 1e-6 ? difference / expected : difference);
            }
        }
    });
    std::cout << "diffuse transmission from behind vs the mirrored Lambert lobe: max relative difference " << worst[1]
              << " (specular layer), " << worst[0] << " (core)\n";
    EXPECT_LE(worst[1], 1e-6);
    EXPECT_LE(worst[0], 2e-4);
}

// The extremes: weight 0 is the material without the layer (bit for bit, front and back);
// weight 1 reflects no diffuse light; a black colour lets nothing through; a light grazing from
// behind (N·L = −1e-6) and from exactly in the plane (N·L = 0) stay finite and non-negative.
TEST(BrdfLayers, DiffuseTransmissionAtTheExtremes) {
    uint64_t bad = 0;
    forEachLobeInput(true, [&](const LobeInput& in) {
        const shading::DielectricFresnel d = shading::coreDielectricFresnel();
        const auto lobes = [&](uint32_t bits, float weight, glm::vec3 color) {
            return shading::layeredLobesTimesCosine(in.N, in.V, in.L, in.L, in.base, in.metallic, in.roughness, in.model, bits, d,
                                                    noAnisotropy(), noTransmission(), shading::diffuseTransmissionLayer(weight, color),
                                                    noSheen(), shading::clearcoatLayer(0.0f, 0.0f, in.N, in.V));
        };
        const uint32_t dt = CANDELA_LAYER_DIFFUSE_TRANSMISSION;
        const shading::LayeredLobes none = lobes(0u, 0.0f, glm::vec3(1.0f)), zero = lobes(dt, 0.0f, kOrange);
        EXPECT_EQ(zero.diffuse, none.diffuse);
        EXPECT_EQ(zero.specular, none.specular);
        EXPECT_EQ(zero.diffuseTransmission, glm::vec3(0.0f));
        const shading::LayeredLobes full = lobes(dt, 1.0f, kOrange), black = lobes(dt, 1.0f, glm::vec3(0.0f));
        EXPECT_EQ(full.diffuse, glm::vec3(0.0f));
        EXPECT_EQ(full.specular, none.specular);
        EXPECT_EQ(black.diffuseTransmission, glm::vec3(0.0f));
        for (const glm::vec3& v : {full.diffuseTransmission, zero.diffuse})
            for (int c = 0; c < 3; ++c) bad += std::isfinite(v[c]) && v[c] >= 0.0f ? 0 : 1;
    });
    EXPECT_EQ(bad, 0u);
}

// The white furnace of the diffuse transmission under image-based light, as the forward pass
// combines it (shading/lighting.glsl): the Lambert part keeps (1 − transmission)(1 − dt) of its
// weight and the diffuse transmission takes (1 − transmission) · dt of it, lit by the irradiance
// from behind. With a white base colour and colour and a uniform environment (irradiance 1 on both
// sides) the material returns exactly what it returns without the layer, for any (A, B), Fresnel,
// weight, transmission and metallic; with a darker colour or a volume that absorbs, less, never
// more. Tolerance 1e-6: float rounding of sums of terms ≤ 1.
TEST(BrdfLayers, DiffuseTransmissionUnderImageBasedLightKeepsTheWhiteFurnace) {
    double worst = 0.0, above = -1.0;
    const glm::vec3 one(1.0f);
    for (float a = 0.0f; a <= 1.0f; a += 0.125f)
        for (float b = 0.0f; a + b <= 1.0f; b += 0.125f)
            for (const shading::DielectricFresnel& d :
                 {shading::coreDielectricFresnel(), shading::dielectricFresnel(1.0f, one, 1.0f),
                  shading::dielectricFresnel(10.0f, glm::vec3(1.0f, 0.5f, 0.25f), 0.5f)})
                for (float weight : {0.0f, 0.3f, 1.0f})
                    for (float transmission : {0.0f, 0.5f, 1.0f})
                        for (float metallic : {0.0f, 0.5f, 1.0f})
                            for (const glm::vec3& behind : {one, glm::vec3(0.5f, 0.8f, 1.0f)}) {
                                const glm::vec2 lut(a, b);
                                const auto total = [&](float dt, glm::vec3 irradianceBehind) {
                                    const shading::BrdfLobes lobes = shading::iblShadeLobesDielectric(
                                        one, one, lut, one, metallic, d, true, 1.0f, 1.0f, (1.0f - transmission) * (1.0f - dt));
                                    const glm::vec3 diffuse = (1.0f - transmission) *
                                                              shading::iblDiffuseTransmission(shading::diffuseTransmissionLayer(dt, one),
                                                                                              irradianceBehind, lut, metallic, d, true, 1.0f);
                                    return lobes.diffuse + lobes.specular + diffuse;
                                };
                                const glm::vec3 opaque = total(0.0f, one), with = total(weight, behind);
                                for (int c = 0; c < 3; ++c) {
                                    const double difference = double(with[c]) - double(opaque[c]);
                                    above = std::max(above, difference);
                                    if (behind == one) worst = std::max(worst, std::abs(difference));
                                }
                            }
    std::cout << "diffuse transmission IBL furnace: max |with - without| " << worst << ", max with - without " << above << "\n";
    EXPECT_LE(worst, 1e-6);
    EXPECT_LE(above, 1e-6);
}

// ---- Dispersion ----

// The per-channel IORs in float against the Abbe-number reference, over IORs 1 … 10 and the
// dispersions of the specification's table (0.33 crown glass, 0.36 diamond, 0.625 polycarbonate,
// 2.04 rutile), 1, 0 and the extremes 100 and 1e6; relative 1e-5. Dispersion 0 gives the IOR three
// times, bit for bit.
TEST(BrdfLayers, DispersionIorsMatchDoubleReference) {
    ref::ErrorStats stats{.floor = kFloor};
    for (float ior : {0.0f, 1.0f, 1.33f, 1.5f, 2.42f, 10.0f})
        for (float dispersion : {0.0f, 0.33f, 0.36f, 0.625f, 1.0f, 2.04f, 100.0f, 1e6f}) {
            const glm::vec3 got = shading::dispersionIors(ior, dispersion);
            const glm::dvec3 expected = ref::dispersionIors(ior, dispersion);
            for (int c = 0; c < 3; ++c)
                stats.add(got[c], expected[c], [&] {
                    std::ostringstream s;
                    s << "ior " << ior << " dispersion " << dispersion << " channel " << c << ": " << got[c] << " vs " << expected[c];
                    return s.str();
                });
            EXPECT_GE(got.r, 1.0f);
            EXPECT_LE(got.r, got.g);
            EXPECT_LE(got.g, got.b);
            if (dispersion == 0.0f) {
                EXPECT_EQ(got, glm::vec3(std::max(ior, 1.0f)));
            }
        }
    expectWithinTolerance("dispersion IORs", stats, 0, kTolerance);
}

// The reference's IORs are the specification's Cauchy equation
// n(λ) = max(n_d + (n_d − 1)/V_d · (523655/λ² − 1.5168), 1) at the Fraunhofer lines: n_F − n_C
// between 486.1 and 656.3 nm is the reference's spread (to 5e-4: the equation's printed constants
// give 1.000385 (n_d − 1)/V_d), and its own sample code's halfSpread (ior − 1) · 0.025 · dispersion
// is half of it.
TEST(BrdfLayers, DispersionReferenceIsTheSpecificationsCauchyEquation) {
    for (double ior : {1.33, 1.5, 2.42})
        for (double dispersion : {0.33, 1.0, 2.04}) {
            const double abbe = 20.0 / dispersion;
            const auto cauchy = [&](double nm) { return std::max(ior + (ior - 1.0) / abbe * (523655.0 / (nm * nm) - 1.5168), 1.0); };
            const glm::dvec3 iors = ref::dispersionIors(ior, dispersion);
            EXPECT_NEAR(iors.b - iors.r, cauchy(486.1) - cauchy(656.3), 5e-4 * (iors.b - iors.r)) << ior << " " << dispersion;
            EXPECT_NEAR(cauchy(587.6), ior, 1e-4) << "n_d";
            EXPECT_NEAR(iors.b - ior, (ior - 1.0) * 0.025 * dispersion, 1e-12);
        }
}

// The refracted rays in float against Snell's law in double: the view from N·V 1 down to 1e-4 in
// two azimuths, the normal tilted off the axes, the three IORs of dispersions 0, 1, 100 and 1e6
// (blue IOR 4.1 at IOR 1.5 and dispersion 100, 12501.5 at 1e6): each direction within 1e-6 (unit
// vectors, 8 float ulps), and the angle between red and blue (the debug view `dispersion`) within
// 1e-6 rad — except for an IOR of exactly 1 (the red, clamped, at large dispersions) at grazing
// views, where GLSL's refract (k = 1 − η²(1 − (N·V)²)) loses the ray's normal component N·V in
// float: an error of N·V radians at most (measured separately).
TEST(BrdfLayers, DispersionRefractedRaysMatchDoubleReference) {
    double worstDirection = 0.0, worstAngle = 0.0, worstAtIorOne = 0.0;
    uint64_t bad = 0;
    const glm::vec3 N = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));
    for (double cosine : {1.0, 0.9, 0.5, 0.1, 1e-2, 1e-4})
        for (double phi : {0.0, 2.0})
            for (float ior : {1.0f, 1.5f, 2.42f})
                for (float dispersion : {0.0f, 1.0f, 100.0f, 1e6f}) {
                    // V at angle acos(cosine) from N (in N's own frame).
                    const glm::dvec3 n(N), t = glm::normalize(glm::cross(n, glm::dvec3(1.0, 0.0, 0.0))), b = glm::cross(n, t);
                    const double sine = std::sqrt(1.0 - cosine * cosine);
                    const glm::vec3 V(glm::normalize(cosine * n + sine * (std::cos(phi) * t + std::sin(phi) * b)));
                    const glm::vec3 iors = shading::dispersionIors(ior, dispersion);
                    glm::vec3 got[3];
                    glm::dvec3 expected[3];
                    const bool iorOne = iors.r == 1.0f;
                    for (int c = 0; c < 3; ++c) {
                        got[c] = shading::refractedDirection(V, N, iors[c]);
                        expected[c] = ref::refractedDirection(glm::dvec3(V), glm::dvec3(N), double(iors[c]));
                        for (int k = 0; k < 3; ++k) {
                            bad += std::isfinite(got[c][k]) ? 0 : 1;
                            const double error = std::abs(double(got[c][k]) - expected[c][k]);
                            if (iors[c] == 1.0f) {
                                EXPECT_LE(error, cosine + 1e-6) << "IOR 1, N·V " << cosine;
                                worstAtIorOne = std::max(worstAtIorOne, error);
                            }
                            if (iors[c] != 1.0f) worstDirection = std::max(worstDirection, error);
                        }
                    }
                    const double angle = std::atan2(glm::length(glm::cross(expected[0], expected[2])), glm::dot(expected[0], expected[2]));
                    const double gotAngle = shading::angleBetween(got[0], got[2]);
                    bad += std::isfinite(gotAngle) ? 0 : 1;
                    if (!iorOne) worstAngle = std::max(worstAngle, std::abs(gotAngle - angle));
                    if (dispersion == 0.0f) {
                        EXPECT_TRUE(got[0] == got[1] && got[1] == got[2]) << "dispersion 0: one ray";
                    }
                }
    std::cout << "dispersion rays: max direction error " << worstDirection << ", max red-blue angle error " << worstAngle
              << " rad; at IOR 1, max direction error " << worstAtIorOne << "\n";
    EXPECT_EQ(bad, 0u);
    EXPECT_LE(worstDirection, 1e-6);
    EXPECT_LE(worstAngle, 1e-6);
}

}  // namespace
}  // namespace candela::test
