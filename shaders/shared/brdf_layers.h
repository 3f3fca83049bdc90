// The material layers beyond glTF's core metallic-roughness model (KHR_materials_*), shared by
// GLSL (the forward pass's layered program) and C++ (float), and their combination for one light.
// Each layer is a header of its own, building on shared/brdf.h:
//   shared/brdf_specular.h      KHR_materials_ior, KHR_materials_specular: the dielectric Fresnel
//   shared/brdf_iridescence.h   KHR_materials_iridescence: the thin film over that Fresnel
//   shared/brdf_transmission.h  KHR_materials_transmission, KHR_materials_volume and
//                               KHR_materials_dispersion
//   shared/brdf_diffuse_transmission.h  KHR_materials_diffuse_transmission
//   shared/brdf_clearcoat.h     KHR_materials_clearcoat
//   shared/brdf_sheen.h         KHR_materials_sheen
//   shared/brdf_anisotropy.h    KHR_materials_anisotropy
// A double-precision reference of the same formulas lives in tests/ and is compared with the GPU's
// evaluation of these files (docs/materials.md).
#ifndef CANDELA_SHARED_BRDF_LAYERS_H
#define CANDELA_SHARED_BRDF_LAYERS_H

#include "shared/brdf.h"
#include "shared/brdf_anisotropy.h"
#include "shared/brdf_clearcoat.h"
#include "shared/brdf_diffuse_transmission.h"
#include "shared/brdf_iridescence.h"
#include "shared/brdf_sheen.h"
#include "shared/brdf_specular.h"
#include "shared/brdf_transmission.h"
#include "shared/scene_data.h"

CANDELA_NAMESPACE_BEGIN

// f(V, L) · (N·L) of a layered material: the material's lobes (the core's, or with the dielectric
// Fresnel `d` when `layers` has CANDELA_LAYER_SPECULAR or CANDELA_LAYER_IRIDESCENCE — the thin film in d; with an anisotropic GGX
// lobe `an` when it has CANDELA_LAYER_ANISOTROPY), beneath the sheen
// `sheen` when `layers` has CANDELA_LAYER_SHEEN, and both beneath the coat `coat` when `layers` has
// CANDELA_LAYER_CLEARCOAT; with CANDELA_LAYER_DIFFUSE_TRANSMISSION the fraction `dt` of the diffuse
// lobe becomes the diffuse BTDF (light from L behind); with CANDELA_LAYER_TRANSMISSION the fraction
// `tr` of both becomes the transmission lobe toward `Lt` (L, or the direction to the light from where
// a volume's refracted ray leaves it). d is the dielectric Fresnel of both BTDFs' weights (the core's
// without the specular layer). The forward pass passes its kLayers, a specialization constant, so
// the branches not taken are compiled out.
struct LayeredLobes {
    vec3 diffuse;    // the material's, beneath the sheen and the coat
    vec3 specular;   // the material's, beneath the sheen and the coat
    vec3 transmission;  // the material's transmitted light (from L behind), beneath the sheen and the coat
    vec3 diffuseTransmission;  // the material's diffusely transmitted light (from L behind), likewise
    vec3 sheen;      // the sheen's, beneath the coat
    float clearcoat; // the coat's (colourless)
};

CANDELA_FN LayeredLobes layeredLobesTimesCosine(vec3 N, vec3 V, vec3 L, vec3 Lt, vec3 baseColor, float metallic,
                                                float perceptualRoughness, uint model, uint layers, DielectricFresnel d,
                                                Anisotropy an, Transmission tr, DiffuseTransmission dt, Sheen sheen,
                                                Clearcoat coat) {
    BrdfLobes base;
    // The specular layer and a thin film change the Fresnel: the Appendix B mix with `d`.
    bool dielectric = (layers & (CANDELA_LAYER_SPECULAR | CANDELA_LAYER_IRIDESCENCE)) != 0u;
    if ((layers & CANDELA_LAYER_ANISOTROPY) != 0u)
        base = brdfLobesTimesCosineAnisotropic(N, V, L, baseColor, metallic, perceptualRoughness, dielectric, d, an);
    else if (dielectric)
        base = brdfLobesTimesCosineDielectric(N, V, L, baseColor, metallic, perceptualRoughness, model, d);
    else
        base = brdfLobesTimesCosine(N, V, L, baseColor, metallic, perceptualRoughness, model);
    LayeredLobes layered;
    layered.diffuse = base.diffuse;
    layered.specular = base.specular;
    layered.transmission = vec3(0.0f);
    layered.diffuseTransmission = vec3(0.0f);
    layered.sheen = vec3(0.0f);
    layered.clearcoat = 0.0f;
    if ((layers & CANDELA_LAYER_DIFFUSE_TRANSMISSION) != 0u) {
        layered.diffuse *= 1.0f - dt.weight;
        layered.diffuseTransmission = diffuseTransmissionTimesCosine(N, V, L, metallic, d, dt);
    }
    if ((layers & CANDELA_LAYER_TRANSMISSION) != 0u) {
        layered.diffuse *= 1.0f - tr.weight;
        layered.diffuseTransmission *= 1.0f - tr.weight;
        layered.transmission = transmissionTimesCosine(N, V, Lt, baseColor, metallic, d, tr);
    }
    if ((layers & CANDELA_LAYER_SHEEN) != 0u) {
        layered.diffuse *= sheen.baseWeight;
        layered.specular *= sheen.baseWeight;
        layered.transmission *= sheen.baseWeight;
        layered.diffuseTransmission *= sheen.baseWeight;
        layered.sheen = sheen.color * sheenTimesCosine(N, V, L, sheen.roughness);
    }
    if ((layers & CANDELA_LAYER_CLEARCOAT) != 0u) {
        layered.diffuse *= coat.baseWeight;
        layered.specular *= coat.baseWeight;
        layered.transmission *= coat.baseWeight;
        layered.diffuseTransmission *= coat.baseWeight;
        layered.sheen *= coat.baseWeight;
        layered.clearcoat = clearcoatTimesCosine(coat, V, L, model);
    }
    return layered;
}

CANDELA_NAMESPACE_END

#endif
