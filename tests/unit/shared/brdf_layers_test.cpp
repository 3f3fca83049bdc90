// The material layers' BRDF (shaders/shared/brdf_layers.h, compiled as C++ float) against the
// double-precision reference written from the specifications (brdf_reference.h), the reference
// against the core BRDF where the two must agree, and the extremes the layer parameters allow.
//
// Metric (reference::ErrorStats): max relative error per channel where the reference is ≥ 1e-6,
// max absolute error below. Tolerance: relative 1e-5 (as for the core Cook-Torrance BRDF,
// brdf_test.cpp), absolute 1e-9.
#include "brdf_layers_test_util.h"
#include "reports/ibl_reference.h"
#include "shared/brdf_layers.h"

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

struct Layer {
    float ior, specular;
    glm::vec3 color;
};

const std::vector<float> kRoughnesses = {0.0f, 0.045f, 0.1f, 0.3f, 0.7f, 1.0f};

// The core values, the extremes and values in between (IOR 0 is the specular-glossiness conversion).
const std::vector<Layer> kLayers = {{1.5f, 1.0f, glm::vec3(1.0f)},  {1.0f, 1.0f, glm::vec3(1.0f)},
                                    {10.0f, 1.0f, glm::vec3(1.0f)}, {0.0f, 1.0f, glm::vec3(2.0f, 1.0f, 0.25f)},
                                    {1.33f, 0.5f, glm::vec3(1.0f, 0.5f, 0.0f)}, {1.5f, 0.0f, glm::vec3(1.0f)},
                                    {1e6f, 1.0f, glm::vec3(1.0f)},  {1.5f, 1.0f, glm::vec3(1e30f)}};

glm::vec3 layeredFloat(glm::vec3 N, glm::vec3 V, glm::vec3 L, glm::vec3 base, float metallic, float roughness, uint32_t model,
                       const Layer& layer) {
    const shading::BrdfLobes lobes = shading::brdfLobesTimesCosineDielectric(
        N, V, L, base, metallic, roughness, model, shading::dielectricFresnel(layer.ior, layer.color, layer.specular));
    return lobes.diffuse + lobes.specular;
}

glm::dvec3 layeredReference(glm::vec3 N, glm::vec3 V, glm::vec3 L, glm::vec3 base, float metallic, float roughness,
                            uint32_t model, const Layer& layer) {
    const ref::Layers layers{.bits = ref::kLayerSpecular, .ior = layer.ior, .specular = layer.specular,
                             .specularColor = glm::dvec3(layer.color)};
    return ref::brdfTimesCosineDielectric(glm::dvec3(N), glm::dvec3(V), glm::dvec3(L), glm::dvec3(base), metallic, roughness,
                                          model, layers);
}

// Calls `f(N, V, L, base, metallic, roughness, model, layer)` over the grid.
template <class F>
void forEachCombination(F&& f) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (const Layer& layer : kLayers)
        for (uint32_t model : {uint32_t(ref::kPbr), uint32_t(ref::kPbrSchlickGgx)})
            for (double cv : kCosines)
                for (double cl : kCosines)
                    for (double phi : {0.0, std::numbers::pi / 2, std::numbers::pi})
                        for (float roughness : kRoughnesses)
                            for (float metallic : kMetallics)
                                for (const glm::vec3& base : kBaseColors)
                                    f(N, direction(cv, 0.0), direction(cl, phi), base, metallic, roughness, model, layer);
}

TEST(BrdfLayers, FloatMatchesDoubleReference) {
    ref::ErrorStats stats{.floor = kFloor};
    forEachCombination([&](glm::vec3 N, glm::vec3 V, glm::vec3 L, glm::vec3 base, float metallic, float roughness,
                           uint32_t model, const Layer& layer) {
        const glm::vec3 got = layeredFloat(N, V, L, base, metallic, roughness, model, layer);
        const glm::dvec3 expected = layeredReference(N, V, L, base, metallic, roughness, model, layer);
        for (int c = 0; c < 3; ++c)
            stats.add(got[c], expected[c], [&] {
                std::ostringstream s;
                s.precision(9);
                s << "ior " << layer.ior << " specular " << layer.specular << " colour (" << layer.color.x << ","
                  << layer.color.y << "," << layer.color.z << ") model " << model << " V=(" << V.x << "," << V.y << ","
                  << V.z << ") L=(" << L.x << "," << L.y << "," << L.z << ") metallic " << metallic << " roughness "
                  << roughness << " channel " << c << ": float " << got[c] << ", double " << expected[c];
                return s.str();
            });
    });
    expectWithinTolerance("specular layer", stats, 0, kTolerance);  // finiteness: FiniteAndNonNegativeEverywhere
}

TEST(BrdfLayers, FiniteAndNonNegativeEverywhere) {
    uint64_t bad = 0;
    forEachCombination([&](glm::vec3 N, glm::vec3 V, glm::vec3 L, glm::vec3 base, float metallic, float roughness,
                           uint32_t model, const Layer& layer) {
        const glm::vec3 got = layeredFloat(N, V, L, base, metallic, roughness, model, layer);
        for (int c = 0; c < 3; ++c) bad += std::isfinite(got[c]) && got[c] >= 0.0f ? 0 : 1;
    });
    EXPECT_EQ(bad, 0u);
}

TEST(BrdfLayers, ReferenceAtTheCoreValuesIsTheCoreBrdfAtMetallicZeroAndOne) {
    // IOR 1.5, specular 1, white: the specification's material is the core one where the two
    // diffuse weights agree (docs/materials.md says how they differ in between).
    const Layer core{1.5f, 1.0f, glm::vec3(1.0f)};
    double worst = 0.0;
    forEachCombination([&](glm::vec3 N, glm::vec3 V, glm::vec3 L, glm::vec3 base, float metallic, float roughness,
                           uint32_t model, const Layer& layer) {
        if (layer.ior != core.ior || layer.specular != core.specular || layer.color != core.color || metallic == 0.5f) return;
        const glm::dvec3 a = layeredReference(N, V, L, base, metallic, roughness, model, layer);
        const glm::dvec3 b = ref::brdfTimesCosine(glm::dvec3(N), glm::dvec3(V), glm::dvec3(L), glm::dvec3(base), metallic,
                                                  roughness, model);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[c] - b[c]) / std::max(std::abs(b[c]), 1e-12));
    });
    EXPECT_LT(worst, 1e-12);
}

TEST(BrdfLayers, SpecularZeroIsLambertAndIorOneReflectsNothingHeadOn) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f), V = direction(0.6, 0.0), L = direction(0.7, 2.0);
    const glm::vec3 base(0.8f, 0.5f, 0.2f);
    const glm::vec3 lambert = layeredFloat(N, V, L, base, 0.0f, 0.5f, ref::kPbr, {1.5f, 0.0f, glm::vec3(1.0f)});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(lambert[c], base[c] / std::numbers::pi * L.z, 1e-7) << c;
    // V = L = N: V·H = 1, so the Fresnel is f0 alone, which IOR 1 makes 0: only the diffuse remains.
    const shading::BrdfLobes headOn = shading::brdfLobesTimesCosineDielectric(
        N, N, N, base, 0.0f, 0.5f, ref::kPbr, shading::dielectricFresnel(1.0f, glm::vec3(1.0f), 1.0f));
    EXPECT_EQ(headOn.specular, glm::vec3(0.0f));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(headOn.diffuse[c], base[c] / std::numbers::pi, 1e-7) << c;
}


// ---- Clearcoat ---------------------------------------------------------------------------------

struct Coat {
    uint32_t bits;
    float ior;  // of the material beneath (with CANDELA_LAYER_SPECULAR)
    float weight, roughness;
    glm::vec3 normal;
};

// Coat weights 1 and 0.5 and roughness 0, 0.3, 1 on the base normal and tilted by 60° out of the
// view plane, over the core material and (alternately) over IOR 1.33 from the specular layer.
std::vector<Coat> coats() {
    std::vector<Coat> out;
    const glm::vec3 normals[] = {glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.8660254f, 0.5f)};
    uint32_t i = 0;
    for (float weight : {1.0f, 0.5f})
        for (float roughness : {0.0f, 0.3f, 1.0f})
            for (const glm::vec3& normal : normals) {
                const bool specular = ++i % 2 == 0;
                out.push_back({CANDELA_LAYER_CLEARCOAT | (specular ? CANDELA_LAYER_SPECULAR : 0u), specular ? 1.33f : 1.5f,
                               weight, roughness, normal});
            }
    return out;
}

TEST(BrdfLayers, ClearcoatFloatMatchesDoubleReference) {
    ref::ErrorStats stats{.floor = kFloor};
    uint64_t bad = 0;
    for (const Coat& coat : coats()) {
        std::ostringstream name;
        name << "coat " << coat.weight << " roughness " << coat.roughness << " normal z " << coat.normal.z << " bits " << coat.bits;
        const ref::Layers layers{.bits = coat.bits, .ior = coat.ior, .clearcoat = coat.weight,
                                 .clearcoatRoughness = coat.roughness, .clearcoatNormal = glm::dvec3(coat.normal)};
        forEachLobeInput(false, [&](const LobeInput& in) {
            const shading::LayeredLobes lobes = shading::layeredLobesTimesCosine(
                in.N, in.V, in.L, in.L, in.base, in.metallic, in.roughness, in.model, coat.bits,
                shading::dielectricFresnel(coat.ior, glm::vec3(1.0f), 1.0f), noAnisotropy(), noTransmission(), noDiffuseTransmission(), noSheen(),
                shading::clearcoatLayer(coat.weight, coat.roughness, coat.normal, in.V));
            compareChannels(stats, bad, in, lobes.diffuse + lobes.specular + lobes.sheen + glm::vec3(lobes.clearcoat),
                            referenceOf(in, layers), name.str());
        });
    }
    expectWithinTolerance("clearcoat", stats, bad, kTolerance);
}

TEST(BrdfLayers, ClearcoatOfWeightZeroIsTheMaterialAndGrazingLetsNothingThrough) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f), V = direction(0.6, 0.0), L = direction(0.7, 2.0), base(0.8f, 0.5f, 0.2f);
    const shading::Clearcoat none = shading::clearcoatLayer(0.0f, 0.3f, N, V);
    const shading::LayeredLobes coated = shading::layeredLobesTimesCosine(
        N, V, L, L, base, 0.3f, 0.5f, ref::kPbr, CANDELA_LAYER_CLEARCOAT, shading::coreDielectricFresnel(), noAnisotropy(), noTransmission(), noDiffuseTransmission(), noSheen(), none);
    const shading::BrdfLobes plain = shading::brdfLobesTimesCosine(N, V, L, base, 0.3f, 0.5f, ref::kPbr);
    EXPECT_EQ(coated.diffuse, plain.diffuse);
    EXPECT_EQ(coated.specular, plain.specular);
    EXPECT_EQ(coated.clearcoat, 0.0f);
    // N_c·V at its clamp (1e-4): 1 − F_c = 0.96 (1 − (1 − 1e-4)⁵) = 4.7990e-4, kept to float precision.
    const shading::Clearcoat grazing = shading::clearcoatLayer(1.0f, 0.0f, N, direction(0.0, 0.0));
    EXPECT_NEAR(grazing.baseWeight, 0.96 * (1.0 - std::pow(1.0 - 1e-4, 5.0)), 1e-10);
}

// The white furnace of the coat under image-based light, as the forward pass combines it: a white
// material that alone reflects exactly 1 (the core's split sum with multiscatter, any (A, B)),
// beneath a coat of any weight, roughness (its own (A, B)) and N_c·V, in an environment of
// radiance 1. Expected: exactly 1 (the coat takes clearcoat · F_c and the material loses as much);
// metric |x − 1|, tolerance 1e-6 (float rounding).
TEST(BrdfLayers, ClearcoatUnderImageBasedLightKeepsTheWhiteFurnace) {
    double worst = 0.0, highest = 0.0;
    for (float a = 0.0f; a <= 1.0f; a += 0.125f)
        for (float b = 0.0f; a + b <= 1.0f; b += 0.125f)
            for (float coatA = 0.0f; coatA <= 1.0f; coatA += 0.25f)
                for (float coatB = 0.0f; coatA + coatB <= 1.0f; coatB += 0.25f)
                    for (float weight : {0.25f, 1.0f})
                        for (double cosine : {1e-4, 0.05, 0.3, 0.7, 1.0}) {
                            const shading::Clearcoat coat = shading::clearcoatLayer(
                                weight, 0.5f, glm::vec3(0.0f, 0.0f, 1.0f), direction(cosine, 0.0));
                            const shading::BrdfLobes base = shading::iblShadeLobes(
                                glm::vec3(1.0f), glm::vec3(1.0f), glm::vec2(a, b), glm::vec3(0.04f), glm::vec3(1.0f), true, 1.0f, 1.0f);
                            const glm::vec3 total = (base.diffuse + base.specular) * coat.baseWeight +
                                                    shading::iblClearcoat(coat, glm::vec3(1.0f), glm::vec3(1.0f),
                                                                          glm::vec2(coatA, coatB), true, 1.0f, 1.0f);
                            for (int c = 0; c < 3; ++c) {
                                worst = std::max(worst, std::abs(double(total[c]) - 1.0));
                                highest = std::max(highest, double(total[c]) - 1.0);
                            }
                        }
    std::cout << "clearcoat IBL furnace: max |x - 1| " << worst << ", max x - 1 " << highest << "\n";
    EXPECT_LE(worst, 1e-6);
}

// The coat lit by punctual lights follows the specification's single-scattering lobe: over a
// material of albedo 1 its directional albedo is 1 − clearcoat · F_c · (1 − E(N_c·V)), E the GGX
// lobe's own albedo (the split sum's A + B, here from the double-precision reference). Never
// above 1; how far below is measured (docs/materials.md), largest at grazing views of rough coats.
TEST(BrdfLayers, ClearcoatUnderPunctualLightsNeverAddsEnergy) {
    double lowest = 1.0;
    std::string where;
    for (double roughness : {0.0, 0.25, 0.5, 0.75, 1.0})
        for (double cosine : {0.05, 0.2, 0.5, 1.0}) {
            const double fresnel = 0.04 + 0.96 * std::pow(1.0 - cosine, 5.0);
            const double albedo = 1.0 - fresnel * (1.0 - reports::reference::directionalAlbedo(cosine, std::max(roughness, 0.045)));
            EXPECT_LE(albedo, 1.0);
            if (albedo < lowest) {
                lowest = albedo;
                where = "roughness " + std::to_string(roughness) + ", N_c·V " + std::to_string(cosine);
            }
            std::cout << "clearcoat 1, roughness " << roughness << ", N_c·V " << cosine << ": albedo " << albedo << "\n";
        }
    std::cout << "clearcoat punctual furnace: lowest " << lowest << " at " << where << "\n";
}

// ---- Sheen -------------------------------------------------------------------------------------

struct SheenCase {
    uint32_t bits;
    glm::vec3 color;
    float roughness, albedo;
};

// White and coloured sheens; roughness 0 (clamped), 0.1, 0.3, 0.6, 1; albedos 0, 0.4 and 2.5 (given: the
// forward pass reads it from the LUT, tested on its own); alone and under a coat.
std::vector<SheenCase> sheens() {
    std::vector<SheenCase> out;
    for (const glm::vec3& color : {glm::vec3(1.0f), glm::vec3(0.8f, 0.3f, 0.1f)})
        for (float roughness : {0.0f, 0.1f, 0.3f, 0.6f, 1.0f})
            for (float albedo : {0.0f, 0.4f, 2.5f})  // 2.5: E above 1 (grazing, smooth sheen), clamped
                out.push_back({CANDELA_LAYER_SHEEN | (albedo > 0.0f && roughness == 0.3f ? CANDELA_LAYER_CLEARCOAT : 0u), color,
                               roughness, albedo});
    return out;
}

TEST(BrdfLayers, SheenFloatMatchesDoubleReference) {
    // Tolerance 1e-4: the Charlie exponent 1/(2α) reaches 247 at the smallest roughness and
    // multiplies the relative rounding of sin²θ_h (float ulp) by as much; elsewhere as the others.
    ref::ErrorStats stats{.floor = kFloor};
    uint64_t bad = 0;
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (const SheenCase& sc : sheens())
        for (uint32_t model : {uint32_t(ref::kPbr), uint32_t(ref::kPbrSchlickGgx)})
            for (double cv : kCosines)
                for (double cl : kCosines)
                    for (double phi : {0.0, std::numbers::pi / 2, std::numbers::pi})
                        for (float metallic : {0.0f, 1.0f}) {
                            const glm::vec3 V = direction(cv, 0.0), L = direction(cl, phi), base(0.5f, 0.4f, 0.3f);
                            const shading::LayeredLobes lobes = shading::layeredLobesTimesCosine(
                                N, V, L, L, base, metallic, 0.5f, model, sc.bits, shading::coreDielectricFresnel(),
                                noAnisotropy(), noTransmission(), noDiffuseTransmission(),
                                shading::sheenLayer(sc.color, sc.roughness, sc.albedo),
                                shading::clearcoatLayer(1.0f, 0.2f, N, V));
                            const glm::vec3 got = lobes.diffuse + lobes.specular + lobes.sheen + glm::vec3(lobes.clearcoat);
                            const ref::Layers layers{.bits = sc.bits, .clearcoat = 1.0, .clearcoatRoughness = 0.2,
                                                     .sheenColor = glm::dvec3(sc.color), .sheenRoughness = sc.roughness,
                                                     .sheenAlbedo = sc.albedo};
                            const glm::dvec3 expected = ref::brdfTimesCosineLayered(
                                glm::dvec3(N), glm::dvec3(V), glm::dvec3(L), glm::dvec3(base), metallic, 0.5, model, layers);
                            for (int c = 0; c < 3; ++c) {
                                bad += std::isfinite(got[c]) && got[c] >= 0.0f ? 0 : 1;
                                stats.add(got[c], expected[c], [&] {
                                    std::ostringstream s;
                                    s.precision(9);
                                    s << "sheen roughness " << sc.roughness << " albedo " << sc.albedo << " bits " << sc.bits
                                      << " V=(" << V.x << "," << V.z << ") L=(" << L.x << "," << L.y << "," << L.z
                                      << ") channel " << c << ": float " << got[c] << ", double " << expected[c];
                                    return s.str();
                                });
                            }
                        }
    expectWithinTolerance("sheen", stats, bad, 1e-4);
}

// The sheen under image-based light, as the forward pass combines it: a white material that alone
// reflects exactly 1, beneath a white sheen of any albedo E in an environment of radiance 1, reflects
// exactly 1 (the sheen takes E, the material loses E); a coloured sheen keeps its brightest channel
// at 1 and the others below. Metric |x − 1| on the brightest channel, x − 1 on all; tolerance 1e-6.
TEST(BrdfLayers, SheenUnderImageBasedLightKeepsTheWhiteFurnace) {
    double worst = 0.0, highest = -1.0;
    for (const glm::vec3& color : {glm::vec3(1.0f), glm::vec3(1.0f, 0.5f, 0.2f), glm::vec3(0.3f, 0.9f, 0.6f)})
        for (float albedo = 0.0f; albedo <= 4.0f; albedo += 0.0625f) {
            const shading::Sheen sheen = shading::sheenLayer(color, 0.5f, albedo);
            const shading::BrdfLobes base = shading::iblShadeLobes(glm::vec3(1.0f), glm::vec3(1.0f), glm::vec2(0.6f, 0.2f),
                                                                    glm::vec3(0.04f), glm::vec3(1.0f), true, 1.0f, 1.0f);
            const glm::vec3 total =
                (base.diffuse + base.specular) * sheen.baseWeight + shading::iblSheen(sheen, glm::vec3(1.0f), 1.0f);
            const int brightest = color.x >= color.y && color.x >= color.z ? 0 : (color.y >= color.z ? 1 : 2);
            worst = std::max(worst, std::abs(double(total[brightest]) - 1.0));
            for (int c = 0; c < 3; ++c) highest = std::max(highest, double(total[c]) - 1.0);
        }
    std::cout << "sheen IBL furnace: max |x - 1| (brightest channel) " << worst << ", max x - 1 " << highest << "\n";
    EXPECT_LE(worst, 1e-6);
    EXPECT_LE(highest, 1e-6);
}

// ---- Anisotropy --------------------------------------------------------------------------------

// Strength 0.5 and 1 (the extreme: α_t = 1 at the smallest roughness), the direction along the
// tangent and turned 30° (so the view plane is neither along nor across it), material roughness
// 0 (clamped), 0.3 and 1, over the core Fresnel and over the specular layer (IOR 1.33).
TEST(BrdfLayers, AnisotropyFloatMatchesDoubleReference) {
    ref::ErrorStats stats{.floor = kFloor};
    uint64_t bad = 0;
    for (float strength : {0.5f, 1.0f})
        for (const glm::vec3& T : {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.8660254f, 0.5f, 0.0f)})
            for (uint32_t bits : {uint32_t(CANDELA_LAYER_ANISOTROPY), uint32_t(CANDELA_LAYER_ANISOTROPY | CANDELA_LAYER_SPECULAR)}) {
                const float ior = (bits & CANDELA_LAYER_SPECULAR) ? 1.33f : 1.5f;
                std::ostringstream name;
                name << "strength " << strength << " T=(" << T.x << "," << T.y << ") bits " << bits;
                const ref::Layers layers{.bits = bits, .ior = ior, .anisotropy = strength, .anisotropyDirection = glm::dvec3(T)};
                forEachLobeInput(false, [&](const LobeInput& in) {
                    const shading::LayeredLobes lobes = shading::layeredLobesTimesCosine(
                        in.N, in.V, in.L, in.L, in.base, in.metallic, in.roughness, in.model, bits,
                        shading::dielectricFresnel(ior, glm::vec3(1.0f), 1.0f),
                        shading::anisotropyLayer(strength, T, glm::cross(in.N, T)), noTransmission(), noDiffuseTransmission(), noSheen(),
                        shading::clearcoatLayer(0.0f, 0.0f, in.N, in.V));
                    compareChannels(stats, bad, in, lobes.diffuse + lobes.specular, referenceOf(in, layers), name.str());
                });
            }
    expectWithinTolerance("anisotropy", stats, bad, kTolerance);
}

TEST(BrdfLayers, AnisotropyOfStrengthZeroIsTheIsotropicLobe) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f), V = direction(0.6, 0.0), L = direction(0.7, 2.0), base(0.8f, 0.5f, 0.2f);
    const shading::BrdfLobes iso = shading::brdfLobesTimesCosine(N, V, L, base, 0.3f, 0.4f, ref::kPbr);
    const shading::BrdfLobes aniso = shading::brdfLobesTimesCosineAnisotropic(
        N, V, L, base, 0.3f, 0.4f, false, shading::coreDielectricFresnel(),
        shading::anisotropyLayer(0.0f, glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(aniso.specular[c], iso.specular[c], 1e-6 * iso.specular[c]) << c;
        EXPECT_NEAR(aniso.diffuse[c], iso.diffuse[c], 1e-6 * iso.diffuse[c]) << c;
    }
}

// The transmission (KHR_materials_transmission) in float against the double reference: weight 1
// and 0.5, IOR 1.5, 1.2 and 1 (no blur: the stiffest lobe, the clamped roughness 0), over the core
// Fresnel and the specular layer, the light in front (the diffuse lobe loses the transmitted
// fraction) and mirrored behind the surface (the BTDF).
TEST(BrdfLayers, TransmissionFloatMatchesDoubleReference) {
    ref::ErrorStats stats{.floor = kFloor};
    uint64_t bad = 0;
    const glm::vec3 color(1.0f, 0.5f, 0.25f);
    for (float weight : {1.0f, 0.5f})
        for (float ior : {1.5f, 1.2f, 1.0f})
            for (uint32_t bits : {uint32_t(CANDELA_LAYER_TRANSMISSION), uint32_t(CANDELA_LAYER_TRANSMISSION | CANDELA_LAYER_SPECULAR)}) {
                std::ostringstream name;
                name << "transmission " << weight << " ior " << ior << " bits " << bits;
                const shading::DielectricFresnel d =
                    (bits & CANDELA_LAYER_SPECULAR) ? shading::dielectricFresnel(ior, color, 1.0f) : shading::coreDielectricFresnel();
                const ref::Layers layers{.bits = bits, .ior = ior, .specularColor = glm::dvec3(color), .transmission = weight};
                forEachLobeInput(true, [&](const LobeInput& in) {
                    const shading::LayeredLobes lobes = shading::layeredLobesTimesCosine(
                        in.N, in.V, in.L, in.L, in.base, in.metallic, in.roughness, in.model, bits, d, noAnisotropy(),
                        shading::transmissionLayer(weight, in.roughness, ior), noDiffuseTransmission(), noSheen(),
                        shading::clearcoatLayer(0.0f, 0.0f, in.N, in.V));
                    compareChannels(stats, bad, in, lobes.diffuse + lobes.specular + lobes.transmission, referenceOf(in, layers),
                                    name.str());
                });
            }
    expectWithinTolerance("transmission", stats, bad, kTolerance);
}

// Under image-based light the transmitted part is the transmission lobe's albedo (the split sum at
// the transmission roughness, (A_t, B_t)), at most the Lambert part's weight: with the light behind
// equal to the irradiance (a uniform environment seen through the surface) a transmitting material
// never reflects and transmits more than the same material without transmission, for any (A, B),
// (A_t, B_t), Fresnel and weight, and exactly as much where the BTDF loses nothing (A_t + B_t = 1,
// the smooth lobe) — so it keeps the white furnace there, and a rough BTDF loses what its single
// scattering loses (docs/materials.md). Tolerance 1e-6: float rounding of sums of terms ≤ 1.
TEST(BrdfLayers, TransmissionUnderImageBasedLightNeverExceedsTheWhiteFurnace) {
    double worstSmooth = 0.0, worstAbove = -1.0;
    for (float a = 0.0f; a <= 1.0f; a += 0.125f)
        for (float b = 0.0f; a + b <= 1.0f; b += 0.125f)
            for (float at = 0.0f; at <= 1.0f; at += 0.125f)
                for (float bt = 0.0f; at + bt <= 1.0f; bt += 0.125f)
                    for (const shading::DielectricFresnel& d :
                         {shading::coreDielectricFresnel(), shading::dielectricFresnel(1.0f, glm::vec3(1.0f), 1.0f),
                          shading::dielectricFresnel(10.0f, glm::vec3(1.0f, 0.5f, 0.25f), 0.5f)})
                        for (float weight : {0.0f, 0.5f, 1.0f})
                            for (float metallic : {0.0f, 0.5f}) {
                                const glm::vec3 base(1.0f), one(1.0f);
                                const glm::vec2 lut(a, b), transmissionLut(at, bt);
                                const shading::BrdfLobes opaque =
                                    shading::iblShadeLobesDielectric(one, one, lut, base, metallic, d, true, 1.0f, 1.0f, 1.0f);
                                const shading::BrdfLobes lobes = shading::iblShadeLobesDielectric(
                                    one, one, lut, base, metallic, d, true, 1.0f, 1.0f, 1.0f - weight);
                                const glm::vec3 transmitted = shading::iblTransmission(
                                    shading::transmissionLayer(weight, 0.5f, 1.5f), one, lut, transmissionLut, base, metallic, d, true);
                                // The BTDF that loses nothing (A_t + B_t = 1) at the reflection's (A, B).
                                const bool smooth = at == a && bt == b && a + b == 1.0f;
                                for (int c = 0; c < 3; ++c) {
                                    const double difference = double(lobes.diffuse[c] + lobes.specular[c] + transmitted[c]) -
                                                              double(opaque.diffuse[c] + opaque.specular[c]);
                                    worstAbove = std::max(worstAbove, difference);
                                    if (smooth) worstSmooth = std::max(worstSmooth, std::abs(difference));
                                }
                            }
    std::cout << "transmission IBL furnace: max with - without " << worstAbove << ", smooth BTDF max |with - without| "
              << worstSmooth << "\n";
    EXPECT_LE(worstAbove, 1e-6);
    EXPECT_LE(worstSmooth, 1e-6);
}

// KHR_materials_volume's Beer-Lambert transmittance at the extremes: thickness 0 and 1e6,
// attenuation distance 1e-6 and infinity (0), a black attenuation colour — finite, in [0, 1], and
// colour^(distance / attenuation distance) where that is representable.
TEST(BrdfLayers, VolumeTransmittanceAtTheExtremes) {
    const glm::vec3 color(1.0f, 0.5f, 0.0f);
    for (float attenuationDistance : {0.0f, 1e-6f, 1.0f, 1e6f})
        for (float distance : {0.0f, 1e-6f, 0.5f, 1.0f, 1e6f}) {
            const glm::vec3 t = shading::volumeTransmittance(color, attenuationDistance, distance);
            for (int c = 0; c < 3; ++c) {
                EXPECT_TRUE(std::isfinite(t[c]) && t[c] >= 0.0f && t[c] <= 1.0f)
                    << "distance " << distance << " attenuation distance " << attenuationDistance << ": " << t[c];
                const double expected = attenuationDistance == 0.0f || distance == 0.0f
                                            ? 1.0
                                            : std::pow(std::max(double(color[c]), 1e-30), double(distance) / attenuationDistance);
                EXPECT_NEAR(t[c], expected, 1e-6 + 1e-5 * expected) << "distance " << distance << " attenuation distance "
                                                                      << attenuationDistance << " channel " << c;
            }
        }
}

// The thin film (KHR_materials_iridescence) in float against the double reference: the thin-film
// Fresnel itself over N·V, thickness (0 … 1200 nm), film IOR (1, 1.3, 2.5, below and above the
// base) and base F0 (0, 0.04, a metal's colour, 1), outside IOR 1 and 1.5; then the layered lobes
// with a film of weight 1 and 0.5 over the core Fresnel and the specular layer.
TEST(BrdfLayers, IridescenceFloatMatchesDoubleReference) {
    ref::ErrorStats film{.floor = kFloor}, oneMinus{.floor = kFloor};
    uint64_t bad = 0;
    for (float outside : {1.0f, 1.5f})
        for (float ior : {1.0f, 1.3f, 2.5f})
            for (float thickness : {0.0f, 50.0f, 150.0f, 400.0f, 800.0f, 1200.0f})
                for (double cosine : {1e-4, 0.05, 0.3, 0.7, 1.0})
                    for (const glm::vec3& f0 : {glm::vec3(0.0f), glm::vec3(0.04f), glm::vec3(0.955f, 0.638f, 0.538f), glm::vec3(1.0f)}) {
                        const shading::ThinFilm got = shading::thinFilmFresnel(outside, ior, float(cosine), thickness, f0);
                        const glm::dvec3 expected = ref::thinFilmFresnel(outside, ior, double(float(cosine)), thickness, glm::dvec3(f0));
                        for (int c = 0; c < 3; ++c) {
                            bad += std::isfinite(got.reflectance[c]) && got.reflectance[c] >= 0.0f ? 0 : 1;
                            const auto describe = [&](float value, double reference) {
                                std::ostringstream s;
                                s.precision(9);
                                s << "outside " << outside << " film IOR " << ior << " thickness " << thickness << " cos "
                                  << cosine << " f0 " << f0[c] << " channel " << c << ": float " << value << ", double "
                                  << reference;
                                return s.str();
                            };
                            film.add(got.reflectance[c], expected[c], [&] { return describe(got.reflectance[c], expected[c]); });
                            oneMinus.add(got.oneMinusReflectance[c], 1.0 - expected[c],
                                         [&] { return describe(got.oneMinusReflectance[c], 1.0 - expected[c]); });
                        }
                    }
    // The spectral integration's cosines of phases of tens of radians lose float digits (~1e-7
    // absolute): a looser bound than the lobes' — 1e-4 on F, and 2e-3 on 1 − F, which over a mirror
    // base (F0 = 1) is only 2e-4 (docs/materials.md).
    expectWithinTolerance("thin-film Fresnel", film, bad, 1e-4);
    expectWithinTolerance("thin-film 1 - Fresnel", oneMinus, 0, 2e-3);

    ref::ErrorStats stats{.floor = kFloor};
    bad = 0;
    const glm::vec3 color(1.0f, 0.5f, 0.25f);
    for (float weight : {1.0f, 0.5f})
        for (uint32_t bits : {uint32_t(CANDELA_LAYER_IRIDESCENCE), uint32_t(CANDELA_LAYER_IRIDESCENCE | CANDELA_LAYER_SPECULAR)}) {
            std::ostringstream name;
            name << "film " << weight << " bits " << bits;
            const ref::Layers layers{.bits = bits, .ior = 1.33, .specularColor = glm::dvec3(color), .iridescence = weight,
                                     .iridescenceIor = double(1.3f)};
            forEachLobeInput(false, [&](const LobeInput& in) {
                const shading::DielectricFresnel d = shading::withThinFilm(
                    (bits & CANDELA_LAYER_SPECULAR) ? shading::dielectricFresnel(1.33f, color, 1.0f) : shading::coreDielectricFresnel(),
                    weight, 1.3f, 400.0f, 1.0f, std::clamp(glm::dot(in.N, in.V), 1e-4f, 1.0f), in.base);
                const shading::LayeredLobes lobes = shading::layeredLobesTimesCosine(
                    in.N, in.V, in.L, in.L, in.base, in.metallic, in.roughness, in.model, bits, d, noAnisotropy(), noTransmission(),
                    noDiffuseTransmission(), noSheen(), shading::clearcoatLayer(0.0f, 0.0f, in.N, in.V));
                compareChannels(stats, bad, in, lobes.diffuse + lobes.specular, referenceOf(in, layers), name.str());
            });
        }
    expectWithinTolerance("iridescence", stats, bad, kTolerance);
}

// Thickness 0 is no film: withThinFilm leaves the Fresnel as it is, and thinFilmFresnel gives
// Schlick's Fresnel of the base.
TEST(BrdfLayers, IridescenceOfThicknessZeroIsNoFilm) {
    const shading::DielectricFresnel d = shading::withThinFilm(shading::coreDielectricFresnel(), 1.0f, 1.3f, 0.0f, 1.0f, 0.5f,
                                                               glm::vec3(0.9f, 0.6f, 0.3f));
    EXPECT_EQ(d.film, 0.0f);
    const glm::vec3 N(0.0f, 0.0f, 1.0f), V = direction(0.6, 0.0), L = direction(0.7, 2.0), base(0.8f, 0.5f, 0.2f);
    const shading::BrdfLobes with = shading::brdfLobesTimesCosineDielectric(N, V, L, base, 0.3f, 0.4f, ref::kPbr, d);
    const shading::BrdfLobes without =
        shading::brdfLobesTimesCosineDielectric(N, V, L, base, 0.3f, 0.4f, ref::kPbr, shading::coreDielectricFresnel());
    EXPECT_EQ(with.specular, without.specular);
    EXPECT_EQ(with.diffuse, without.diffuse);
    const glm::vec3 schlick = shading::thinFilmFresnel(1.0f, 1.3f, 0.5f, 0.0f, glm::vec3(0.04f)).reflectance;
    EXPECT_NEAR(schlick.x, 0.04 + 0.96 * std::pow(0.5, 5.0), 1e-7);
}

}  // namespace
}  // namespace candela::test
