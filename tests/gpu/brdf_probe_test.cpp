// The GPU's own evaluation of the forward pass's BRDF (shaders/shared/brdf.h, compiled to SPIR-V),
// run through the render graph as the BRDF probe pass, against the double-precision CPU reference
// (tests/unit/brdf_reference.h) on every combination of the probe grid (shaders/shared/brdf_probe.h).
// Both sides build N, V, L from the same float literals, so the comparison measures the shader's
// arithmetic alone.
//
// Metric (reference::ErrorStats, per shading model, over every rgb value of the probe image): max
// relative error where the reference is ≥ 1e-6 · intensity, max absolute error below. Tolerances:
//   - Cook-Torrance (both visibility terms): relative 2e-5, twice the CPU float tolerance for the
//     ulps Vulkan allows in division and sqrt (lavapipe measured 2.3e-6; the cancellation in D that
//     brdf.h had measured 5.3e-3 here).
//   - Blinn-Phong: relative 5e-3: (N·H)^s with s up to 19998 amplifies the rounding of N·H near 1
//     (bound 2.4e-3, see brdf_test.cpp), plus the GPU's pow (exp2 · log2). Measured 1.4e-3.
//   - absolute below the floor: 1e-9 · intensity, or the relative tolerance at the floor where that
//     is larger (Blinn-Phong: 5e-9), so that a value just under the floor may be off by what the same
//     value just over it may. SwiftShader's pow (exp2 · log2) is off by 1.04e-3 relative at
//     Blinn-Phong's grazing texels, on both sides of the floor (1.03e-9 absolute just under it).
// And: no NaN or Inf anywhere in the output, at intensity 1 and 1e6.
#include "gpu_test.h"
#include "graph_runner.h"

#include "../unit/brdf_reference.h"
#include "passes/diagnostics/brdf_probe_pass.h"
#include "passes/post/readback_pass.h"
#include "shared/scene_data.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <sstream>
#include <vector>

namespace candela::test {
namespace {

using passes::BrdfProbePass;
namespace ref = reference;

constexpr const char* kModelNames[] = {"pbr", "pbr-schlick-ggx", "blinn-phong"};
constexpr double kCookTorranceTolerance = 2e-5;
constexpr double kBlinnPhongTolerance = 5e-3;
constexpr double kAbsoluteTolerance = 1e-9;
constexpr double kFloor = 1e-6;

// Builds the graph brdf_probe → readback (into an imported host-visible buffer), compiles it,
// realizes its transients, executes it in a frame slot and returns the probe image's texels.
std::vector<glm::vec4> runProbe(vk::Context& context, const shading::BrdfProbeParams& params,
                                BrdfProbePass::Brdf brdf = BrdfProbePass::Brdf::Core) {
    const BrdfProbePass probe(context, brdf);
    GraphRunner runner(context);
    graph::RenderGraph graph;
    const VkDeviceSize bytes = sizeof(glm::vec4) * BrdfProbePass::kWidth * BrdfProbePass::kHeight;
    const graph::BufferId target = runner.readbackBuffer(graph, "brdf probe readback", bytes);
    passes::addReadbackPass(graph, probe.add(graph, params), target);
    runner.run(graph);
    return runner.read<glm::vec4>(target);
}

std::vector<glm::vec4> runProbe(vk::Context& context, float intensity) { return runProbe(context, {.intensity = intensity}); }

std::string describe(const shading::BrdfProbeSample& s, uint32_t x, uint32_t y, int channel, float got, double expected) {
    std::ostringstream out;
    out.precision(9);
    out << kModelNames[s.model] << " texel (" << x << "," << y << ") V=(" << s.V.x << "," << s.V.y << "," << s.V.z
        << ") L=(" << s.L.x << "," << s.L.y << "," << s.L.z << ") baseColor=(" << s.baseColor.x << "," << s.baseColor.y
        << "," << s.baseColor.z << ") metallic=" << s.metallic << " roughness=" << s.perceptualRoughness << " channel "
        << channel << ": GPU " << got << ", reference " << expected;
    return out.str();
}

// The reference of probe combination `s`: the core BRDF, or with `layer` the layered material's
// (Blinn-Phong has no layers and stays the core's, as in the forward pass).
glm::dvec3 referenceOf(const shading::BrdfProbeSample& s, const shading::BrdfProbeParams* layer) {
    if (!layer || s.model == ref::kBlinnPhong)
        return ref::brdfTimesCosine(glm::dvec3(s.N), glm::dvec3(s.V), glm::dvec3(s.L), glm::dvec3(s.baseColor), s.metallic,
                                    s.perceptualRoughness, s.model);
    const ref::Layers layers{.bits = layer->layers,
                             .ior = layer->ior,
                             .specular = layer->specular,
                             .specularColor = glm::dvec3(layer->specularColor),
                             .clearcoat = layer->clearcoat,
                             .clearcoatRoughness = layer->clearcoatRoughness,
                             .clearcoatNormal = glm::dvec3(layer->clearcoatNormal),
                             .sheenColor = glm::dvec3(layer->sheenColor),
                             .sheenRoughness = layer->sheenRoughness,
                             .sheenAlbedo = layer->sheenAlbedo,
                             .anisotropy = layer->anisotropy.w,
                             .anisotropyDirection = glm::dvec3(layer->anisotropy),
                             .transmission = layer->transmission.x,
                             .diffuseTransmission = layer->transmission.z,
                             .diffuseTransmissionColor =
                                 glm::dvec3(shading::brdfProbeDiffuseTransmissionColor(uint32_t(layer->transmission.w))),
                             .iridescence = layer->iridescence.x,
                             .iridescenceIor = layer->iridescence.y,
                             .iridescenceThickness = layer->iridescence.z,
                             .outsideIor = layer->iridescence.w};
    return ref::brdfTimesCosineLayered(glm::dvec3(s.N), glm::dvec3(s.V), glm::dvec3(s.L), glm::dvec3(s.baseColor),
                                       s.metallic, s.perceptualRoughness, s.model, layers);
}

// Compares every texel with the reference times `intensity`; checks finiteness and the index.
void checkProbe(const std::vector<glm::vec4>& texels, float intensity, const shading::BrdfProbeParams* layer = nullptr,
                double cookTorranceTolerance = kCookTorranceTolerance) {
    ref::ErrorStats stats[3] = {{.floor = kFloor * intensity}, {.floor = kFloor * intensity}, {.floor = kFloor * intensity}};
    uint64_t nonFinite = 0, wrongIndex = 0;
    for (uint32_t y = 0; y < BrdfProbePass::kHeight; ++y)
        for (uint32_t x = 0; x < BrdfProbePass::kWidth; ++x) {
            const glm::vec4& got = texels[size_t(y) * BrdfProbePass::kWidth + x];
            shading::BrdfProbeSample s = shading::brdfProbeSample(glm::uvec2(x, y));
            if (layer && layer->transmission.y > 0.5f) s.L.z = -s.L.z;  // as the probe mirrors it
            const glm::dvec3 expected = referenceOf(s, layer) * double(intensity);
            for (int c = 0; c < 4; ++c) nonFinite += std::isfinite(got[c]) ? 0 : 1;
            wrongIndex += got.w == float(y * BrdfProbePass::kWidth + x) ? 0 : 1;
            for (int c = 0; c < 3; ++c)
                stats[s.model].add(got[c], expected[c], [&] { return describe(s, x, y, c, got[c], expected[c]); });
        }
    EXPECT_EQ(nonFinite, 0u) << "NaN or Inf in the GPU output at intensity " << intensity;
    EXPECT_EQ(wrongIndex, 0u) << "texels whose alpha is not their combination's index";
    for (uint32_t model = 0; model < 3; ++model) {
        const ref::ErrorStats& s = stats[model];
        const double tolerance = model == ref::kBlinnPhong ? kBlinnPhongTolerance : cookTorranceTolerance;
        std::cout << "GPU, intensity " << intensity << ", " << kModelNames[model] << ": " << s.compared
                  << " values, max relative error " << s.maxRelative << " (" << s.relativeCount
                  << " values >= floor), max absolute error below " << s.maxAbsolute << "\n  worst: " << s.worstRelative
                  << "\n";
        ::testing::Test::RecordProperty(std::string("max_relative_") + kModelNames[model], std::to_string(s.maxRelative));
        EXPECT_LE(s.maxRelative, tolerance) << s.worstRelative;
        EXPECT_LE(s.maxAbsolute, std::max(kAbsoluteTolerance, tolerance * kFloor) * intensity) << s.worstAbsolute;
    }
}

TEST_F(GpuTest, BrdfProbeMatchesDoubleReference) { checkProbe(runProbe(context(), 1.0f), 1.0f); }

TEST_F(GpuTest, BrdfProbeStaysFiniteAtIntensity1e6) { checkProbe(runProbe(context(), 1e6f), 1e6f); }

// The specular layer (KHR_materials_ior, _specular) over the grid, at the core's values, at the
// extremes (IOR exactly 1: f0 = 0; IOR 10; IOR 0 with a specular colour above 1: f0 clamped to 1;
// specular 0: no specular reflection, all diffuse) and in between; same metric and tolerances.
TEST_F(GpuTest, SpecularLayerProbeMatchesDoubleReference) {
    const shading::BrdfProbeParams layers[] = {
        {.intensity = 1.0f, .ior = 1.5f, .specular = 1.0f, .layers = CANDELA_LAYER_SPECULAR, .specularColor = glm::vec4(1.0f)},
        {.intensity = 1.0f, .ior = 1.0f, .specular = 1.0f, .layers = CANDELA_LAYER_SPECULAR, .specularColor = glm::vec4(1.0f)},
        {.intensity = 1.0f, .ior = 10.0f, .specular = 1.0f, .layers = CANDELA_LAYER_SPECULAR, .specularColor = glm::vec4(1.0f)},
        {.intensity = 1.0f, .ior = 0.0f, .specular = 1.0f, .layers = CANDELA_LAYER_SPECULAR, .specularColor = glm::vec4(2.0f, 1.0f, 0.25f, 0.0f)},
        {.intensity = 1.0f, .ior = 1.33f, .specular = 0.5f, .layers = CANDELA_LAYER_SPECULAR, .specularColor = glm::vec4(1.0f, 0.5f, 0.0f, 0.0f)},
        {.intensity = 1.0f, .ior = 1.5f, .specular = 0.0f, .layers = CANDELA_LAYER_SPECULAR, .specularColor = glm::vec4(1.0f)},
        {.intensity = 1e6f, .ior = 1.0f, .specular = 1.0f, .layers = CANDELA_LAYER_SPECULAR, .specularColor = glm::vec4(1.0f)},
    };
    for (const shading::BrdfProbeParams& layer : layers) {
        SCOPED_TRACE(::testing::Message() << "ior " << layer.ior << ", specular " << layer.specular << ", colour ("
                                          << layer.specularColor.x << ", " << layer.specularColor.y << ", "
                                          << layer.specularColor.z << "), intensity " << layer.intensity);
        checkProbe(runProbe(context(), layer, BrdfProbePass::Brdf::Layers), layer.intensity, &layer);
    }
}

// The clearcoat (KHR_materials_clearcoat) over the grid: coat weights 1, 0.5 and 0 (the layer on
// but transparent), coat roughness 0 (clamped like the material's), 0.3 and 1, the coat normal
// along the base normal and tilted by 60° away from the view plane (so N_c·L, N_c·V and the
// mirror configuration differ from the base's), over the core material and over IOR 1 (no base
// reflection head-on); and at intensity 1e6. Same metric and tolerances.
TEST_F(GpuTest, ClearcoatProbeMatchesDoubleReference) {
    const glm::vec4 up(0.0f, 0.0f, 1.0f, 0.0f);
    const glm::vec4 tilted(0.0f, 0.8660254037844386f, 0.5f, 0.0f);
    const auto coat = [](float intensity, uint32_t layers, float ior, float weight, float roughness, glm::vec4 normal) {
        return shading::BrdfProbeParams{.intensity = intensity, .ior = ior, .specular = 1.0f, .layers = layers,
                                        .specularColor = glm::vec4(1.0f), .clearcoat = weight,
                                        .clearcoatRoughness = roughness, .clearcoatNormal = normal};
    };
    const uint32_t coatOnly = CANDELA_LAYER_CLEARCOAT, both = CANDELA_LAYER_CLEARCOAT | CANDELA_LAYER_SPECULAR;
    const shading::BrdfProbeParams layers[] = {
        coat(1.0f, coatOnly, 1.5f, 1.0f, 0.0f, up),     coat(1.0f, coatOnly, 1.5f, 1.0f, 0.3f, up),
        coat(1.0f, coatOnly, 1.5f, 1.0f, 1.0f, up),     coat(1.0f, coatOnly, 1.5f, 0.5f, 0.3f, tilted),
        coat(1.0f, coatOnly, 1.5f, 0.0f, 0.3f, up),     coat(1.0f, coatOnly, 1.5f, 1.0f, 0.0f, tilted),
        coat(1.0f, both, 1.0f, 1.0f, 0.3f, tilted),     coat(1e6f, both, 10.0f, 1.0f, 0.0f, up),
    };
    for (const shading::BrdfProbeParams& layer : layers) {
        SCOPED_TRACE(::testing::Message() << "layers " << layer.layers << ", ior " << layer.ior << ", clearcoat "
                                          << layer.clearcoat << ", roughness " << layer.clearcoatRoughness
                                          << ", normal z " << layer.clearcoatNormal.z << ", intensity " << layer.intensity);
        checkProbe(runProbe(context(), layer, BrdfProbePass::Brdf::Layers), layer.intensity, &layer);
    }
}


// The sheen (KHR_materials_sheen) over the grid: white and coloured, roughness 0 (clamped), 0.3 and
// 1, albedo E given (0.5; the LUT is tested on its own), over the core material, under a coat, and
// at intensity 1e6. Tolerance 1e-4 relative for these runs: the Charlie exponent 1/(2α) (up to 247)
// multiplies the float rounding of sin²θ_h (BrdfLayers.SheenFloatMatchesDoubleReference).
TEST_F(GpuTest, SheenProbeMatchesDoubleReference) {
    const glm::vec4 up(0.0f, 0.0f, 1.0f, 0.0f);
    const auto sheen = [&](float intensity, uint32_t layers, glm::vec4 color, float roughness) {
        return shading::BrdfProbeParams{.intensity = intensity, .ior = 1.5f, .specular = 1.0f, .layers = layers,
                                        .specularColor = glm::vec4(1.0f), .clearcoat = 1.0f, .clearcoatRoughness = 0.2f,
                                        .sheenRoughness = roughness, .sheenAlbedo = 0.5f, .clearcoatNormal = up,
                                        .sheenColor = color};
    };
    const glm::vec4 white(1.0f), coloured(0.8f, 0.3f, 0.1f, 0.0f);
    const shading::BrdfProbeParams cases[] = {
        sheen(1.0f, CANDELA_LAYER_SHEEN, white, 0.0f),   sheen(1.0f, CANDELA_LAYER_SHEEN, white, 0.3f),
        sheen(1.0f, CANDELA_LAYER_SHEEN, coloured, 1.0f), sheen(1.0f, CANDELA_LAYER_SHEEN | CANDELA_LAYER_CLEARCOAT, coloured, 0.3f),
        sheen(1e6f, CANDELA_LAYER_SHEEN, white, 0.0f)};
    for (const shading::BrdfProbeParams& c : cases) {
        SCOPED_TRACE(::testing::Message() << "layers " << c.layers << ", sheen roughness " << c.sheenRoughness
                                          << ", intensity " << c.intensity);
        checkProbe(runProbe(context(), c, BrdfProbePass::Brdf::Layers), c.intensity, &c, 1e-4);
    }
}


// The anisotropy (KHR_materials_anisotropy) over the grid: strength 0.5 and 1 (1 at the clamped
// roughness 0 is the stiffest: α_t = 1, α_b = 0.002), along the probe's tangent and turned 30°,
// over the core Fresnel and the specular layer, and at intensity 1e6. Same metric and tolerances.
TEST_F(GpuTest, AnisotropyProbeMatchesDoubleReference) {
    const auto aniso = [](float intensity, uint32_t layers, float strength, glm::vec3 t) {
        return shading::BrdfProbeParams{.intensity = intensity, .ior = 1.33f, .specular = 1.0f, .layers = layers,
                                        .specularColor = glm::vec4(1.0f), .anisotropy = glm::vec4(t, strength)};
    };
    const glm::vec3 along(1.0f, 0.0f, 0.0f), turned(0.8660254f, 0.5f, 0.0f);
    const uint32_t both = CANDELA_LAYER_ANISOTROPY | CANDELA_LAYER_SPECULAR;
    const shading::BrdfProbeParams cases[] = {
        aniso(1.0f, CANDELA_LAYER_ANISOTROPY, 1.0f, along), aniso(1.0f, CANDELA_LAYER_ANISOTROPY, 0.5f, turned),
        aniso(1.0f, both, 1.0f, turned), aniso(1e6f, CANDELA_LAYER_ANISOTROPY, 1.0f, along)};
    for (const shading::BrdfProbeParams& c : cases) {
        SCOPED_TRACE(::testing::Message() << "layers " << c.layers << ", strength " << c.anisotropy.w << ", T ("
                                          << c.anisotropy.x << ", " << c.anisotropy.y << "), intensity " << c.intensity);
        checkProbe(runProbe(context(), c, BrdfProbePass::Brdf::Layers), c.intensity, &c);
    }
}

// The transmission (KHR_materials_transmission) over the grid, with the light in front (the BTDF
// gives nothing, the diffuse lobe loses the transmitted fraction) and mirrored behind the surface:
// weight 1 and 0.5, IOR 1.5 (the roughness as it is), 1.2 (scaled by 0.4) and 1 (no blur: the
// clamped roughness 0, the stiffest lobe), over the core Fresnel and the specular layer, under a
// coat, and at intensity 1e6. Same metric and tolerances as the core BRDF.
TEST_F(GpuTest, TransmissionProbeMatchesDoubleReference) {
    const auto transmission = [](float intensity, uint32_t layers, float weight, float ior, bool behind) {
        return shading::BrdfProbeParams{.intensity = intensity, .ior = ior, .specular = 1.0f, .layers = layers,
                                        .specularColor = glm::vec4(1.0f, 0.5f, 0.25f, 0.0f), .clearcoat = 0.7f,
                                        .clearcoatRoughness = 0.3f, .clearcoatNormal = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f),
                                        .transmission = glm::vec4(weight, behind ? 1.0f : 0.0f, 0.0f, 0.0f)};
    };
    const uint32_t t = CANDELA_LAYER_TRANSMISSION;
    const shading::BrdfProbeParams cases[] = {
        transmission(1.0f, t, 1.0f, 1.5f, false),  transmission(1.0f, t, 1.0f, 1.5f, true),
        transmission(1.0f, t, 0.5f, 1.2f, true),   transmission(1.0f, t, 1.0f, 1.0f, true),
        transmission(1.0f, t | CANDELA_LAYER_SPECULAR, 1.0f, 1.33f, true),
        transmission(1.0f, t | CANDELA_LAYER_CLEARCOAT, 1.0f, 1.5f, true), transmission(1e6f, t, 1.0f, 1.0f, true)};
    for (const shading::BrdfProbeParams& c : cases) {
        SCOPED_TRACE(::testing::Message() << "layers " << c.layers << ", transmission " << c.transmission.x << ", IOR "
                                          << c.ior << (c.transmission.y > 0.5f ? ", light behind" : ", light in front")
                                          << ", intensity " << c.intensity);
        checkProbe(runProbe(context(), c, BrdfProbePass::Brdf::Layers), c.intensity, &c);
    }
}

// The diffuse transmission (KHR_materials_diffuse_transmission) over the grid, with the light in
// front (the diffuse lobe loses the transmitted fraction) and mirrored behind the surface (the
// Lambertian BTDF, weighted by the dielectric Fresnel at the mirrored light's half vector): weight
// 1, 0.5 and 0 (the layer on, nothing through), white and orange, over the core Fresnel and the
// specular layer (IOR 1.33, colour (1, 0.5, 0.25)), under a transmission of 0.5 (which takes its
// share), under the sheen and a coat, and at intensity 1e6. Same metric and tolerances as the core
// BRDF (the sheen's runs 1e-4, as SheenProbeMatchesDoubleReference).
TEST_F(GpuTest, DiffuseTransmissionProbeMatchesDoubleReference) {
    const auto diffuse = [](float intensity, uint32_t layers, float weight, float color, bool behind) {
        return shading::BrdfProbeParams{.intensity = intensity, .ior = 1.33f, .specular = 1.0f, .layers = layers,
                                        .specularColor = glm::vec4(1.0f, 0.5f, 0.25f, 0.0f), .clearcoat = 0.7f,
                                        .clearcoatRoughness = 0.3f, .sheenRoughness = 0.3f, .sheenAlbedo = 0.5f,
                                        .clearcoatNormal = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f),
                                        .sheenColor = glm::vec4(0.8f, 0.3f, 0.1f, 0.0f),
                                        .transmission = glm::vec4(0.5f, behind ? 1.0f : 0.0f, weight, color)};
    };
    const uint32_t d = CANDELA_LAYER_DIFFUSE_TRANSMISSION;
    const shading::BrdfProbeParams cases[] = {
        diffuse(1.0f, d, 1.0f, 0.0f, false),  diffuse(1.0f, d, 1.0f, 0.0f, true),
        diffuse(1.0f, d, 0.5f, 1.0f, true),   diffuse(1.0f, d, 0.0f, 1.0f, true),
        diffuse(1.0f, d | CANDELA_LAYER_SPECULAR, 1.0f, 1.0f, true),
        diffuse(1.0f, d | CANDELA_LAYER_TRANSMISSION, 0.75f, 1.0f, true),
        diffuse(1.0f, d | CANDELA_LAYER_TRANSMISSION | CANDELA_LAYER_SPECULAR, 1.0f, 0.0f, false),
        diffuse(1e6f, d, 1.0f, 1.0f, true)};
    for (const shading::BrdfProbeParams& c : cases) {
        SCOPED_TRACE(::testing::Message() << "layers " << c.layers << ", diffuse transmission " << c.transmission.z << ", colour "
                                          << c.transmission.w << (c.transmission.y > 0.5f ? ", light behind" : ", light in front")
                                          << ", intensity " << c.intensity);
        checkProbe(runProbe(context(), c, BrdfProbePass::Brdf::Layers), c.intensity, &c);
    }
    const shading::BrdfProbeParams sheen = diffuse(1.0f, d | CANDELA_LAYER_SHEEN | CANDELA_LAYER_CLEARCOAT, 0.5f, 1.0f, true);
    SCOPED_TRACE("under the sheen and a coat, light behind");
    checkProbe(runProbe(context(), sheen, BrdfProbePass::Brdf::Layers), 1.0f, &sheen, 1e-4);
}

// The thin film (KHR_materials_iridescence) over the grid: weight 1 and 0.5, film IOR 1.3 and 2,
// thickness 400 nm, 150 nm and 0 (no film), from air and from under a coat (outside IOR 1.5), over
// the core Fresnel, the specular layer and with the anisotropy and the transmission (the Fresnel they
// share), and at intensity 1e6. Same metric; tolerance 1e-4, the thin-film Fresnel's own in float:
// the spectral terms take cosines of phases of tens of radians, and under a coat (outside IOR 1.5
// over a film of 1.3) Snell's cos²θ₂ nears 0 close to total internal reflection (docs/materials.md).
TEST_F(GpuTest, IridescenceProbeMatchesDoubleReference) {
    const auto film = [](float intensity, uint32_t layers, float weight, float ior, float thickness, float outside) {
        return shading::BrdfProbeParams{.intensity = intensity, .ior = 1.33f, .specular = 1.0f, .layers = layers,
                                        .specularColor = glm::vec4(1.0f, 0.5f, 0.25f, 0.0f), .clearcoat = 0.7f,
                                        .clearcoatRoughness = 0.3f, .clearcoatNormal = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f),
                                        .anisotropy = glm::vec4(1.0f, 0.0f, 0.0f, 0.6f),
                                        .transmission = glm::vec4(0.5f, 0.0f, 0.0f, 0.0f),
                                        .iridescence = glm::vec4(weight, ior, thickness, outside)};
    };
    const uint32_t i = CANDELA_LAYER_IRIDESCENCE;
    const shading::BrdfProbeParams cases[] = {
        film(1.0f, i, 1.0f, 1.3f, 400.0f, 1.0f),
        film(1.0f, i, 0.5f, 2.0f, 150.0f, 1.0f),
        film(1.0f, i, 1.0f, 1.3f, 0.0f, 1.0f),
        film(1.0f, i | CANDELA_LAYER_SPECULAR | CANDELA_LAYER_CLEARCOAT, 1.0f, 1.3f, 400.0f, 1.5f),
        film(1.0f, i | CANDELA_LAYER_ANISOTROPY, 1.0f, 1.8f, 600.0f, 1.0f),
        film(1.0f, i | CANDELA_LAYER_TRANSMISSION, 1.0f, 1.3f, 400.0f, 1.0f),
        film(1e6f, i, 1.0f, 1.3f, 400.0f, 1.0f)};
    for (const shading::BrdfProbeParams& c : cases) {
        SCOPED_TRACE(::testing::Message() << "layers " << c.layers << ", film weight " << c.iridescence.x << ", IOR "
                                          << c.iridescence.y << ", thickness " << c.iridescence.z << " nm, outside IOR "
                                          << c.iridescence.w << ", intensity " << c.intensity);
        checkProbe(runProbe(context(), c, BrdfProbePass::Brdf::Layers), c.intensity, &c, 1e-4);
    }
}

}  // namespace
}  // namespace candela::test
