#pragma once
// Double-precision CPU reference of the forward pass's BRDFs (shaders/shared/brdf.h), written
// independently of that file in the textbook form, with the same documented clamps so that the two
// can be compared value for value:
//   - perceptual roughness clamped to [0.045, 1] (a = roughness²);
//   - N·L ≤ 0 → 0 (light behind the surface);
//   - N·V clamped to ≥ 1e-4 (grazing and back-facing views);
//   - half vector H = normalize(V + L); when |V + L| ≤ 1e-6 (V = −L) H = N and no specular term;
//   - N·H and V·H clamped to [0, 1];
//   - Blinn-Phong shininess 2 / max(r⁴, 1e-4) − 2 with r the clamped roughness.
// Header-only, used by tests/unit/shared/brdf_test.cpp and tests/gpu/brdf_probe_test.cpp.

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace candela::test::reference {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kMinRoughness = 0.045;
inline constexpr double kMinNoV = 1e-4;
inline constexpr double kMinHalfVectorLength = 1e-6;
inline constexpr double kMinBlinnPhongRoughness4 = 1e-4;

// Shading models, numbered like CANDELA_SHADING_* in shaders/shared/brdf.h.
enum Model : uint32_t {
    kPbr = 0,             // Cook-Torrance, height-correlated Smith-GGX visibility
    kPbrSchlickGgx = 1,   // Cook-Torrance, Schlick-GGX geometry with k = (r+1)²/8
    kBlinnPhong = 2,      // the original project's Blinn-Phong
};

inline double clampRoughness(double perceptualRoughness) { return std::clamp(perceptualRoughness, kMinRoughness, 1.0); }

// GGX / Trowbridge-Reitz: D = a² / (π ((N·H)² (a² − 1) + 1)²).
inline double distributionGgx(double NoH, double a) {
    const double a2 = a * a;
    const double d = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}

// Height-correlated Smith-GGX visibility:
// V = 0.5 / (N·L √((N·V)² (1 − a²) + a²) + N·V √((N·L)² (1 − a²) + a²)).
inline double visibilitySmithGgxCorrelated(double NoV, double NoL, double a) {
    const double a2 = a * a;
    return 0.5 / (NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2));
}

// Schlick-GGX: G1(n) = n / (n (1 − k) + k), k = (r + 1)² / 8, G = G1(N·V) G1(N·L),
// V = G / (4 N·V N·L). Preconditions: N·V > 0, N·L > 0.
inline double visibilitySchlickGgx(double NoV, double NoL, double roughness) {
    const double k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
    const auto g1 = [k](double n) { return n / (n * (1.0 - k) + k); };
    return g1(NoV) * g1(NoL) / (4.0 * NoV * NoL);
}

// Fresnel-Schlick: F = F0 + (1 − F0)(1 − V·H)⁵.
inline glm::dvec3 fresnelSchlick(double VoH, const glm::dvec3& f0) {
    return f0 + (glm::dvec3(1.0) - f0) * std::pow(1.0 - VoH, 5.0);
}

// The cosines the BRDFs read, with the clamps listed at the top: N·L (≤ 0: no light), N·V, and N·H,
// V·H of the half vector (H = N without one, when V = −L).
struct Angles {
    double NoL, NoV, NoH, VoH;
    bool hasHalfVector;
};

inline Angles angles(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L) {
    const glm::dvec3 sum = V + L;
    const double sumLength = glm::length(sum);
    const bool hasHalfVector = sumLength > kMinHalfVectorLength;
    const glm::dvec3 H = hasHalfVector ? sum / sumLength : N;
    return {glm::dot(N, L), std::max(glm::dot(N, V), kMinNoV), std::clamp(glm::dot(N, H), 0.0, 1.0),
            std::clamp(glm::dot(V, H), 0.0, 1.0), hasHalfVector};
}

// f(V, L) · (N·L) for unit N, V, L (V towards the viewer, L towards the light).
inline glm::dvec3 brdfTimesCosine(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                                  const glm::dvec3& baseColor, double metallic, double perceptualRoughness,
                                  uint32_t model) {
    const auto [NoL, NoV, NoH, VoH, hasHalfVector] = angles(N, V, L);
    if (NoL <= 0.0) return glm::dvec3(0.0);
    const double specularWeight = hasHalfVector ? 1.0 : 0.0;
    const double roughness = clampRoughness(perceptualRoughness);

    if (model == kBlinnPhong) {
        const double shininess = 2.0 / std::max(std::pow(roughness, 4.0), kMinBlinnPhongRoughness4) - 2.0;
        return (baseColor + glm::dvec3(std::pow(NoH, shininess) * specularWeight)) * NoL;
    }
    const double a = roughness * roughness;
    const glm::dvec3 f0 = glm::dvec3(0.04) * (1.0 - metallic) + baseColor * metallic;
    const glm::dvec3 F = fresnelSchlick(VoH, f0);
    const double D = distributionGgx(NoH, a);
    const double Vis = model == kPbrSchlickGgx ? visibilitySchlickGgx(NoV, NoL, roughness)
                                               : visibilitySmithGgxCorrelated(NoV, NoL, a);
    const glm::dvec3 specular = F * D * Vis * specularWeight;
    const glm::dvec3 diffuse = (glm::dvec3(1.0) - F) * (1.0 - metallic) * baseColor / kPi;
    return (diffuse + specular) * NoL;
}

// Layer bits, numbered like CANDELA_LAYER_* in shaders/shared/scene_data.h.
enum LayerBit : uint32_t {
    kLayerSpecular = 1, kLayerClearcoat = 2, kLayerSheen = 8, kLayerAnisotropy = 16, kLayerTransmission = 32, kLayerIridescence = 128,
    kLayerDiffuseTransmission = 256
};

// KHR_materials_sheen's lobe f · N·L in the specification's form: the Charlie distribution
// D = (2 + 1/α) sin(θ_h)^(1/α) / 2π with α = roughness² (roughness clamped like the GGX one) and the
// Estevez-Kulla visibility 1 / ((1 + Λ(N·V) + Λ(N·L)) 4 N·V N·L), Λ from the fitted L(x).
inline double sheenL(double x, double alpha) {
    const double t = (1.0 - alpha) * (1.0 - alpha);
    const auto mix = [t](double a, double b) { return a + (b - a) * t; };
    return mix(21.5473, 25.3245) / (1.0 + mix(3.82987, 3.32435) * std::pow(x, mix(0.19823, 0.16801))) +
           mix(-1.97760, -1.27393) * x + mix(-4.32054, -4.85967);
}
inline double sheenLambda(double c, double alpha) {
    return c < 0.5 ? std::exp(sheenL(c, alpha)) : std::exp(2.0 * sheenL(0.5, alpha) - sheenL(1.0 - c, alpha));
}
inline double sheenTimesCosine(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L, double perceptualRoughness) {
    const auto [NoL, NoV, NoH, VoH, hasHalfVector] = angles(N, V, L);
    if (NoL <= 0.0 || !hasHalfVector) return 0.0;
    const double r = clampRoughness(perceptualRoughness);
    const double alpha = r * r;
    const double D = (2.0 + 1.0 / alpha) * std::pow(std::max(1.0 - NoH * NoH, 0.0), 0.5 / alpha) / (2.0 * kPi);
    const double cl = std::min(NoL, 1.0), cv = std::min(NoV, 1.0);
    return D / ((1.0 + sheenLambda(cv, alpha) + sheenLambda(cl, alpha)) * 4.0 * cv * cl) * cl;
}

// A material's layers and their parameters.
struct Layers {
    uint32_t bits = 0;  // LayerBit
    double ior = 1.5, specular = 1.0;
    glm::dvec3 specularColor{1.0};
    double clearcoat = 0.0, clearcoatRoughness = 0.0;
    glm::dvec3 clearcoatNormal{0.0, 0.0, 1.0};
    glm::dvec3 sheenColor{0.0};
    double sheenRoughness = 0.0;
    double sheenAlbedo = 0.0;  // E(N·V), given
    double anisotropy = 0.0;                    // strength
    glm::dvec3 anisotropyDirection{1.0, 0.0, 0.0};  // T, unit, ⟂ N
    double transmission = 0.0;  // weight
    double diffuseTransmission = 0.0;          // KHR_materials_diffuse_transmission's weight
    glm::dvec3 diffuseTransmissionColor{1.0};  // and colour
    double iridescence = 0.0;                 // the thin film's weight
    double iridescenceIor = 1.3, iridescenceThickness = 400.0;  // its IOR and thickness (nm)
    double outsideIor = 1.0;                  // the medium above the film (1, or a coat's 1.5)
};

// KHR_materials_iridescence's thin-film Fresnel in the specification's form (its implementation
// notes, after Belcour & Barla 2017): the first interface's Schlick reflectance R12 at cos θ₁, the
// second's R23 at cos θ₂ (Snell) over a base of IOR (1 + √F0)/(1 − √F0), F0 ≤ 0.9999; phases π or
// 0 by the IORs' order; the compound R12 R23 clamped to [1e-5, 0.9999]; orders 0, 1, 2 of the
// analytic spectral integration with the Gaussian fit of the XYZ sensitivities, to Rec. 709; no
// film (thickness 0): Schlick's Fresnel of the base.
inline glm::dvec3 thinFilmFresnel(double outsideIor, double filmIor, double cos1, double thickness, const glm::dvec3& baseF0) {
    const auto schlick = [](double r0, double c) { return r0 + (1.0 - r0) * std::pow(1.0 - std::clamp(c, 0.0, 1.0), 5.0); };
    if (thickness <= 0.0) return {schlick(baseF0.x, cos1), schlick(baseF0.y, cos1), schlick(baseF0.z, cos1)};
    const double sin2Squared = std::pow(outsideIor / filmIor, 2.0) * (1.0 - cos1 * cos1);
    if (sin2Squared > 1.0) return glm::dvec3(1.0);
    const double cos2 = std::sqrt(1.0 - sin2Squared);
    const double r12 = schlick(std::pow((filmIor - outsideIor) / (filmIor + outsideIor), 2.0), cos1);
    const double t121 = 1.0 - r12;
    const double phi12 = filmIor < outsideIor ? kPi : 0.0;
    const double opd = 2.0 * filmIor * thickness * cos2;
    const auto sensitivity = [](double opdNm, const glm::dvec3& shift) {
        const double phase = 2.0 * kPi * opdNm * 1e-9;
        const glm::dvec3 val(5.4856e-13, 4.4201e-13, 5.2481e-13), pos(1.6810e+06, 1.7953e+06, 2.2084e+06),
            var(4.3278e+09, 9.3046e+09, 6.6121e+09);
        glm::dvec3 xyz;
        for (int c = 0; c < 3; ++c)
            xyz[c] = val[c] * std::sqrt(2.0 * kPi * var[c]) * std::cos(pos[c] * phase + shift[c]) * std::exp(-phase * phase * var[c]);
        xyz.x += 9.7470e-14 * std::sqrt(2.0 * kPi * 4.5282e+09) * std::cos(2.2399e+06 * phase + shift.x) *
                 std::exp(-4.5282e+09 * phase * phase);
        xyz /= 1.0685e-7;
        return glm::dvec3(3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
                          -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
                          0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z);
    };
    glm::dvec3 out(0.0), phi(0.0), r23(0.0), cm(0.0);
    for (int c = 0; c < 3; ++c) {
        const double s = std::sqrt(std::min(baseF0[c], 0.9999));
        const double baseIor = (1.0 + s) / (1.0 - s);
        r23[c] = schlick(std::pow((baseIor - filmIor) / (baseIor + filmIor), 2.0), cos2);
        phi[c] = (kPi - phi12) + (baseIor < filmIor ? kPi : 0.0);
        const double rs = t121 * t121 * r23[c] / (1.0 - std::clamp(r12 * r23[c], 1e-5, 0.9999));
        out[c] = r12 + rs;
        cm[c] = rs - t121;
    }
    for (int m = 1; m <= 2; ++m) {
        const glm::dvec3 s = 2.0 * sensitivity(m * opd, double(m) * phi);
        for (int c = 0; c < 3; ++c) {
            cm[c] *= std::sqrt(std::clamp(r12 * r23[c], 1e-5, 0.9999));
            out[c] += cm[c] * s[c];
        }
    }
    return glm::max(out, glm::dvec3(0.0));
}

// The Fresnel terms of the Appendix B material at V·H: the dielectric's F_d = f0 + (f90 − f0)(1 − V·H)⁵
// (with kLayerSpecular f0 = min(((ior − 1)/(ior + 1))² · specularColor, 1) · specular, f90 = specular;
// else the core's 0.04 and 1) and the metal's Schlick(baseColor), each mixed with kLayerIridescence's
// thin-film Fresnel at N·V (over f0, and over baseColor) by its weight.
struct Fresnels {
    glm::dvec3 dielectric, metal;
};
inline Fresnels appendixBFresnels(double VoH, double NoV, const glm::dvec3& baseColor, const Layers& layers) {
    glm::dvec3 f0(0.04), f90(1.0);
    if (layers.bits & kLayerSpecular) {
        const double r = (layers.ior - 1.0) / (layers.ior + 1.0);
        f0 = glm::min(r * r * layers.specularColor, glm::dvec3(1.0)) * layers.specular;
        f90 = glm::dvec3(layers.specular);
    }
    Fresnels out{f0 + (f90 - f0) * std::pow(1.0 - VoH, 5.0), fresnelSchlick(VoH, baseColor)};
    if ((layers.bits & kLayerIridescence) && layers.iridescenceThickness > 0.0) {
        const double cos1 = std::clamp(NoV, kMinNoV, 1.0);
        const auto film = [&](const glm::dvec3& base) {
            return thinFilmFresnel(layers.outsideIor, layers.iridescenceIor, cos1, layers.iridescenceThickness, base);
        };
        out.dielectric += (film(f0) - out.dielectric) * layers.iridescence;
        out.metal += (film(baseColor) - out.metal) * layers.iridescence;
    }
    return out;
}

// The specular layer (KHR_materials_ior, KHR_materials_specular) and the thin film
// (KHR_materials_iridescence) in the specifications' form, the material
// (1 − metallic) · (F_d · specular_brdf + (1 − max(F_d)) · diffuse_brdf) + metallic · F_m · specular_brdf
// with appendixBFresnels. Cook-Torrance models only (the layers have no Blinn-Phong form).
inline glm::dvec3 brdfTimesCosineDielectric(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                                            const glm::dvec3& baseColor, double metallic, double perceptualRoughness,
                                            uint32_t model, const Layers& layers) {
    const auto [NoL, NoV, NoH, VoH, hasHalfVector] = angles(N, V, L);
    if (NoL <= 0.0) return glm::dvec3(0.0);
    const double roughness = clampRoughness(perceptualRoughness);
    const double a = roughness * roughness;
    const Fresnels F = appendixBFresnels(VoH, NoV, baseColor, layers);
    const double D = distributionGgx(NoH, a);
    const double Vis = model == kPbrSchlickGgx ? visibilitySchlickGgx(NoV, NoL, roughness)
                                               : visibilitySmithGgxCorrelated(NoV, NoL, a);
    const double specularBrdf = hasHalfVector ? D * Vis : 0.0;
    const double maxFresnel = std::max({F.dielectric.x, F.dielectric.y, F.dielectric.z});
    const glm::dvec3 dielectric = F.dielectric * specularBrdf + (1.0 - maxFresnel) * baseColor / kPi;
    return ((1.0 - metallic) * dielectric + metallic * F.metal * specularBrdf) * NoL;
}

// The diffuse lobe times N·L of the material brdfTimesCosineLayered starts from: with the specular
// layer or a thin film (1 − metallic)(1 − max(F_d)) · baseColor/π (appendixBFresnels), else the core's (1 − F)(1 − metallic) · baseColor/π.
inline glm::dvec3 diffuseTimesCosine(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                                     const glm::dvec3& baseColor, double metallic, const Layers& layers) {
    const auto [NoL, NoV, NoH, VoH, hasHalfVector] = angles(N, V, L);
    if (NoL <= 0.0) return glm::dvec3(0.0);
    if (layers.bits & (kLayerSpecular | kLayerIridescence)) {
        const glm::dvec3 F = appendixBFresnels(VoH, NoV, baseColor, layers).dielectric;
        return (1.0 - metallic) * (1.0 - std::max({F.x, F.y, F.z})) * baseColor / kPi * NoL;
    }
    const glm::dvec3 F = fresnelSchlick(VoH, glm::dvec3(0.04) * (1.0 - metallic) + baseColor * metallic);
    return (glm::dvec3(1.0) - F) * (1.0 - metallic) * baseColor / kPi * NoL;
}

// KHR_materials_transmission's lobe times |N·L| in the specification's form (its implementation
// notes): for L behind the surface, transmission · (1 − metallic) · baseColor · (1 − max(F_d)) ·
// D_T · V_T · |N·L| with H_T = normalize(V − 2(N·L)N + L), the GGX D_T with χ⁺(N·H_T), the
// separable V_T with χ⁺(H_T·L / N·L) χ⁺(H_T·V / N·V), α = (roughness · clamp(2 ior − 2, 0, 1))²
// (roughness clamped like the GGX one), F_d the dielectric Fresnel at V·H_T (the core's f0 0.04,
// f90 1 without the specular layer).
inline glm::dvec3 transmissionTimesCosine(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                                          const glm::dvec3& baseColor, double metallic, double perceptualRoughness,
                                          const Layers& layers) {
    const double NoL = glm::dot(N, L);
    if (NoL >= 0.0 || layers.transmission <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 sum = V - 2.0 * NoL * N + L;
    if (glm::length(sum) <= 1e-6) return glm::dvec3(0.0);
    const glm::dvec3 H = glm::normalize(sum);
    const double NoV = std::max(glm::dot(N, V), 1e-4);
    const double NoH = glm::dot(N, H), VoH = glm::dot(V, H), LoH = glm::dot(L, H);
    if (NoH <= 0.0 || LoH / NoL <= 0.0 || VoH / NoV <= 0.0) return glm::dvec3(0.0);
    const double roughness = clampRoughness(perceptualRoughness * std::clamp(2.0 * layers.ior - 2.0, 0.0, 1.0));
    const double a = roughness * roughness, a2 = a * a;
    const double q = NoH * NoH * (a2 - 1.0) + 1.0;
    const double D = a2 / (kPi * q * q);
    const double absNoL = -NoL;
    const double Vt = 1.0 / ((absNoL + std::sqrt(a2 + (1.0 - a2) * absNoL * absNoL)) * (NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV)));
    const glm::dvec3 F = appendixBFresnels(VoH, NoV, baseColor, layers).dielectric;
    const double maxF = std::max({F.x, F.y, F.z});
    return layers.transmission * (1.0 - metallic) * (1.0 - maxF) * D * Vt * absNoL * baseColor;
}

// KHR_materials_diffuse_transmission's BTDF times |N·L| in the specification's form: for L on the
// other side of the surface than V (N·L < 0; V is on the front, as the clamp of N·V above takes
// it), the Lambertian diffuse_btdf = diffuseTransmissionColor / π in the dielectric part's
// fresnel_mix, (1 − metallic) · diffuseTransmission · (1 − max(F_d)) · diffuse_btdf · |N·L|, with
// the Fresnel at the light mirrored to V's side, L_m = L − 2(N·L)N (Candela's choice for its BTDFs:
// the specification leaves the half vector of a transmitted direction open), V·H and its fallback
// H = N as `angles` takes them.
inline glm::dvec3 diffuseTransmissionTimesCosine(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                                                 const glm::dvec3& baseColor, double metallic, const Layers& layers) {
    const double NoL = glm::dot(N, L);
    if (NoL >= 0.0) return glm::dvec3(0.0);
    const Angles mirrored = angles(N, V, L - 2.0 * NoL * N);
    const glm::dvec3 F = appendixBFresnels(mirrored.VoH, mirrored.NoV, baseColor, layers).dielectric;
    const double maxF = std::max({F.x, F.y, F.z});
    return (1.0 - metallic) * layers.diffuseTransmission * (1.0 - maxF) * layers.diffuseTransmissionColor / kPi * -NoL;
}

// KHR_materials_dispersion's IORs of the red (n_C), green (n_d) and blue (n_F) rays from the Abbe
// number V_d = 20 / dispersion: n_F − n_C = (n_d − 1) / V_d, split evenly about n_d (the
// specification's implementation notes), n_d = max(ior, 1), the red at least 1; no dispersion: n_d
// three times.
inline glm::dvec3 dispersionIors(double ior, double dispersion) {
    const double nd = std::max(ior, 1.0);
    if (dispersion <= 0.0) return glm::dvec3(nd);
    const double abbe = 20.0 / dispersion;
    const double spread = (nd - 1.0) / abbe;
    return {std::max(nd - 0.5 * spread, 1.0), nd, nd + 0.5 * spread};
}

// The direction of the ray refracted into a surface of unit normal N (on V's side) from the unit
// direction toward the viewer V, by Snell's law with the outside IOR 1 and the inside `ior` ≥ 1:
// the tangential part of −V scaled by 1/ior and the normal part from cos θ_t = √(1 − sin²θ_i / ior²).
inline glm::dvec3 refractedDirection(const glm::dvec3& V, const glm::dvec3& N, double ior) {
    const double cosI = glm::dot(N, V);
    const glm::dvec3 tangential = (-V + cosI * N) / ior;
    const double sin2T = (1.0 - cosI * cosI) / (ior * ior);
    return glm::normalize(tangential - std::sqrt(std::max(1.0 - sin2T, 0.0)) * N);
}

// KHR_materials_anisotropy's material in the specification's form: the GGX lobe with
// α_t = α + (1 − α) · strength² along T and α_b = α across (B = N × T),
// D = 1 / (π α_t α_b ((T·H/α_t)² + (B·H/α_b)² + (N·H)²)²) and the height-correlated anisotropic
// Smith visibility; Fresnel and diffuse as brdfTimesCosine, or with kLayerSpecular as
// brdfTimesCosineDielectric. Both Cook-Torrance models use these D and Vis.
inline glm::dvec3 brdfTimesCosineAnisotropic(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                                             const glm::dvec3& baseColor, double metallic, double perceptualRoughness,
                                             const Layers& layers) {
    const auto [NoL, NoV, NoH, VoH, hasHalfVector] = angles(N, V, L);
    if (NoL <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 H = hasHalfVector ? glm::normalize(V + L) : N;
    const glm::dvec3 T = glm::normalize(layers.anisotropyDirection), B = glm::cross(N, T);
    const double r = clampRoughness(perceptualRoughness);
    const double ab = r * r, at = ab + (1.0 - ab) * layers.anisotropy * layers.anisotropy;
    const double q = std::pow(glm::dot(T, H) / at, 2.0) + std::pow(glm::dot(B, H) / ab, 2.0) + NoH * NoH;
    const double D = 1.0 / (kPi * at * ab * q * q);
    const auto lambda = [&](const glm::dvec3& X, double NoX) {
        return std::sqrt(at * at * std::pow(glm::dot(T, X), 2.0) + ab * ab * std::pow(glm::dot(B, X), 2.0) + NoX * NoX);
    };
    const double Vis = 0.5 / (NoL * lambda(V, NoV) + NoV * lambda(L, NoL));
    const double specularBrdf = hasHalfVector ? D * Vis : 0.0;
    if (layers.bits & (kLayerSpecular | kLayerIridescence)) {
        const Fresnels F = appendixBFresnels(VoH, NoV, baseColor, layers);
        const double maxF = std::max({F.dielectric.x, F.dielectric.y, F.dielectric.z});
        return ((1.0 - metallic) * (F.dielectric * specularBrdf + (1.0 - maxF) * baseColor / kPi) +
                metallic * F.metal * specularBrdf) *
               NoL;
    }
    const glm::dvec3 F = fresnelSchlick(VoH, glm::dvec3(0.04) * (1.0 - metallic) + baseColor * metallic);
    return (F * specularBrdf + (glm::dvec3(1.0) - F) * (1.0 - metallic) * baseColor / kPi) * NoL;
}

// The layered material in the specifications' form: the material (brdfTimesCosine, or with
// kLayerSpecular brdfTimesCosineDielectric); with kLayerSheen, KHR_materials_sheen's albedo scaling
//   sheenColor · f_sheen + material · (1 − max(sheenColor) · min(E(N·V), 1))  (E clamped: see
//   shaders/shared/brdf_sheen.h);
// and, with kLayerClearcoat, over both KHR_materials_clearcoat's
//   mix(material, D(α_c) G(α_c) / (4 N_c·V N_c·L), clearcoat · F_c),  F_c = 0.04 + 0.96 (1 − N_c·V)⁵,
// with N_c·V, N_c·L, the half vector and the coat's roughness clamped as listed at the top.
inline glm::dvec3 brdfTimesCosineLayered(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                                         const glm::dvec3& baseColor, double metallic, double perceptualRoughness,
                                         uint32_t model, const Layers& layers) {
    glm::dvec3 material =
        (layers.bits & kLayerAnisotropy) ? brdfTimesCosineAnisotropic(N, V, L, baseColor, metallic, perceptualRoughness, layers)
        : (layers.bits & (kLayerSpecular | kLayerIridescence))
            ? brdfTimesCosineDielectric(N, V, L, baseColor, metallic, perceptualRoughness, model, layers)
            : brdfTimesCosine(N, V, L, baseColor, metallic, perceptualRoughness, model);
    if (layers.bits & (kLayerTransmission | kLayerDiffuseTransmission)) {
        // The dielectric base mix(mix(diffuse_brdf, diffuse_btdf, dt), specular_btdf, tr): the
        // diffuse lobe gives up its transmitted fractions to the BTDFs.
        const double dt = (layers.bits & kLayerDiffuseTransmission) ? layers.diffuseTransmission : 0.0;
        const double tr = (layers.bits & kLayerTransmission) ? layers.transmission : 0.0;
        const glm::dvec3 diffuse = diffuseTimesCosine(N, V, L, baseColor, metallic, layers);
        const glm::dvec3 diffuseBtdf = dt > 0.0 ? diffuseTransmissionTimesCosine(N, V, L, baseColor, metallic, layers) : glm::dvec3(0.0);
        const glm::dvec3 specularBtdf =
            tr > 0.0 ? transmissionTimesCosine(N, V, L, baseColor, metallic, perceptualRoughness, layers) : glm::dvec3(0.0);
        material += (1.0 - tr) * diffuseBtdf + specularBtdf - (1.0 - (1.0 - tr) * (1.0 - dt)) * diffuse;
    }
    if (layers.bits & kLayerSheen) {
        const double maxColor = std::max({layers.sheenColor.x, layers.sheenColor.y, layers.sheenColor.z});
        material = material * (1.0 - maxColor * std::min(layers.sheenAlbedo, 1.0)) +
                   layers.sheenColor * sheenTimesCosine(N, V, L, layers.sheenRoughness);
    }
    if (!(layers.bits & kLayerClearcoat)) return material;
    // Normalized in double: the textbook D amplifies a float normal's length error (1 − |N| ≈ 1e-8)
    // 4 / a² times at the mirror peak — 1.3% at the smallest roughness.
    const auto [NcL, NcV, NcH, VoH, hasHalfVector] = angles(glm::normalize(layers.clearcoatNormal), V, L);
    const double cosine = std::min(NcV, 1.0);
    const double fresnel = 0.04 + 0.96 * std::pow(1.0 - cosine, 5.0);
    const double weight = layers.clearcoat * fresnel;
    double coat = 0.0;
    if (NcL > 0.0 && hasHalfVector) {
        const double roughness = clampRoughness(layers.clearcoatRoughness);
        const double a = roughness * roughness;
        const double Vis = model == kPbrSchlickGgx ? visibilitySchlickGgx(cosine, NcL, roughness)
                                                   : visibilitySmithGgxCorrelated(cosine, NcL, a);
        coat = distributionGgx(NcH, a) * Vis * NcL;
    }
    return material * (1.0 - weight) + glm::dvec3(weight * coat);
}

// The metric of the BRDF comparisons: relative error |got − expected| / |expected| where
// |expected| ≥ floor, absolute error |got − expected| below it (where relative error means nothing).
// Keeps the maxima and a description of the input of each, for the test's messages.
struct ErrorStats {
    double floor = 1e-6;
    double maxRelative = 0.0;
    double maxAbsolute = 0.0;
    std::string worstRelative;  // description of the input with the largest relative error
    std::string worstAbsolute;
    uint64_t compared = 0;
    uint64_t relativeCount = 0;  // values at or above the floor

    // `describe()` returns a description of the input; called only when a maximum changes.
    template <class Describe>
    void add(double got, double expected, Describe&& describe) {
        ++compared;
        const double difference = std::abs(got - expected);
        if (std::abs(expected) >= floor) {
            ++relativeCount;
            const double relative = difference / std::abs(expected);
            if (relative > maxRelative || std::isnan(relative)) {
                maxRelative = std::isnan(relative) ? INFINITY : relative;
                worstRelative = describe();
            }
        } else if (difference > maxAbsolute || std::isnan(difference)) {
            maxAbsolute = std::isnan(difference) ? INFINITY : difference;
            worstAbsolute = describe();
        }
    }
};

}  // namespace candela::test::reference
