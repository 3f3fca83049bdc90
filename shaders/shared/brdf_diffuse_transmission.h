// KHR_materials_diffuse_transmission: a Lambertian BTDF that lets light from behind the surface
// through diffusely (leaves, paper, wax), for punctual and image-based light. One of the material
// layers (shared/brdf_layers.h), shared by GLSL and C++ (float); a double-precision reference of the
// same formulas lives in tests/unit/brdf_reference.h.
//
// The specification replaces the dielectric part's diffuse BRDF with
//   diffuse_bsdf = mix(diffuse_brdf(baseColor), diffuse_btdf(diffuseTransmissionColor), diffuseTransmission),
// which KHR_materials_transmission's specular BTDF then overrides by its own factor:
//   dielectric base = mix(diffuse_bsdf, specular_btdf · baseColor, transmission).
// The Fresnel weight 1 − max(F_d) of the BTDF is taken, as for the specular BTDF
// (shared/brdf_transmission.h), at the half vector of the light mirrored through the surface, H_T.
// With KHR_materials_volume (thickness > 0) the transmitted light is attenuated along the thickness
// (volumeTransmittance), punctual and image-based alike (the forward pass's lighting).
#ifndef CANDELA_SHARED_BRDF_DIFFUSE_TRANSMISSION_H
#define CANDELA_SHARED_BRDF_DIFFUSE_TRANSMISSION_H

#include "shared/brdf_specular.h"

CANDELA_NAMESPACE_BEGIN

// The diffuse transmission of one shading point: its weight (diffuseTransmissionFactor × texture A)
// and the colour of the transmitted light (diffuseTransmissionColorFactor × texture RGB).
struct DiffuseTransmission {
    float weight;
    vec3 color;
};

CANDELA_FN DiffuseTransmission diffuseTransmissionLayer(float weight, vec3 color) {
    DiffuseTransmission t;
    t.weight = weight;
    t.color = color;
    return t;
}

// The light transmitted diffusely from L behind the surface (N·L < 0; 0 otherwise) toward V, times
// |N·L|: weight · (1 − metallic) · (1 − max(F_d(V·H_T))) · color/π · |N·L|, H_T the half vector of V
// and L mirrored through the surface (N where V is the mirrored light's opposite, as brdfAngles).
// Not yet weighted by 1 − transmission (layeredLobesTimesCosine does that).
CANDELA_FN vec3 diffuseTransmissionTimesCosine(vec3 N, vec3 V, vec3 L, float metallic, DielectricFresnel d,
                                               DiffuseTransmission t) {
    float NoL = dot(N, L);
    if (NoL >= 0.0f || t.weight <= 0.0f) return vec3(0.0f);
    BrdfAngles mirrored = brdfAngles(N, V, L - 2.0f * NoL * N);
    float unreflected = minComponent(oneMinusFresnelDielectricAt(mirrored.VoH, d));
    return t.color * (t.weight * (1.0f - metallic) * unreflected * (1.0f / CANDELA_PI) * -NoL);
}

// The diffuse transmission under image-based light: `irradianceBehind` (the environment's
// irradiance / π about −N, already attenuated by a volume) through the Lambert part's weight in
// iblShadeLobesDielectric — (1 − metallic) · iblDielectricUnreflected — times the colour and the
// occlusion. The Lambert reflection keeps (1 − weight) of that weight, so a material whose colour
// and base colour are white returns in a uniform environment exactly what it returns opaque (the
// white furnace). Not yet weighted by 1 − transmission.
CANDELA_FN vec3 iblDiffuseTransmission(DiffuseTransmission t, vec3 irradianceBehind, vec2 lut, float metallic,
                                       DielectricFresnel d, bool multiscatter, float diffuseOcclusion) {
    float weight = t.weight * (1.0f - metallic) * iblDielectricUnreflected(lut, d, multiscatter);
    return t.color * irradianceBehind * (weight * diffuseOcclusion);
}

CANDELA_NAMESPACE_END

#endif
