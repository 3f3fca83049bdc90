// The forward programs' debug views (kDebugView, CANDELA_DEBUG_*): what a surface shows instead of
// its shaded colour, from its Surface and the light it reflects.
#ifndef CANDELA_FORWARD_DEBUG_VIEWS_GLSL
#define CANDELA_FORWARD_DEBUG_VIEWS_GLSL

#include "shading/lighting.glsl"
#include "shading/resources.glsl"
#include "shading/surface.glsl"
#include "shared/tonemap.h"

// Data shown as its value: the debug variants are paired with the linear tonemap at exposure 0,
// which sRGB-encodes, so the value is decoded here and reaches the 8-bit output as value × 255.
vec3 asData(vec3 value) { return srgbDecode(clamp(value, vec3(0.0f), vec3(1.0f))); }

// The GGX terms of `s` toward the first punctual light (black without one): D relative to its peak
// (D · π a², 1 where the half vector meets the normal), Smith's G (visibility × 4 N·L N·V), and
// Schlick's F.
vec3 termTowardFirstLight(Surface s) {
    if (!kLights || push.counts.x == 0u) return vec3(0.0f);
    float attenuation;
    vec3 l = lightDirection(lights[0], s.position, attenuation);
    vec3 n = s.normal;
    float NoL = dot(n, l);
    if (NoL <= 0.0f) return vec3(0.0f);
    float NoV = max(dot(n, s.v), CANDELA_MIN_NOV);
    vec3 h = normalize(s.v + l);
    float NoH = clamp(dot(n, h), 0.0f, 1.0f);
    float roughness = clampRoughness(s.roughness);
    float a = roughness * roughness;
    vec3 NxH = cross(n, h);
    if (kDebugView == CANDELA_DEBUG_D) return vec3(distributionGgx(NoH, dot(NxH, NxH), a) * CANDELA_PI * a * a);
    if (kDebugView == CANDELA_DEBUG_G) return vec3(visibilitySmithGgxCorrelated(NoV, NoL, a) * 4.0f * NoL * NoV);
#ifdef CANDELA_MATERIAL_LAYERS
    if (hasLayer(CANDELA_LAYER_SPECULAR) || hasLayer(CANDELA_LAYER_IRIDESCENCE))
        return fresnelDielectricMetal(clamp(dot(s.v, h), 0.0f, 1.0f), s.baseColor, s.metallic, s.layers.dielectric);
#endif
    return fresnelSchlick(clamp(dot(s.v, h), 0.0f, 1.0f), s.f0);
}

// What debug view kDebugView shows of surface `s` (not CANDELA_DEBUG_NONE): `lit` is the light it
// reflects (layered), `emissive` its emission (beneath any coat), `throughput` the fraction of the
// light behind it that comes through.
vec3 debugViewValue(Surface s, SurfaceLight lit, vec3 emissive, vec3 throughput) {
    vec3 value = vec3(0.0f);
    if (kDebugView == CANDELA_DEBUG_BASE_COLOR) value = s.baseColor;
    else if (kDebugView == CANDELA_DEBUG_GEOMETRIC_NORMAL) value = asData(s.facedNormal * 0.5f + 0.5f);
    else if (kDebugView == CANDELA_DEBUG_MAPPED_NORMAL) value = asData(s.normal * 0.5f + 0.5f);
    else if (kDebugView == CANDELA_DEBUG_ROUGHNESS) value = asData(vec3(s.materialRoughness));
    else if (kDebugView == CANDELA_DEBUG_METALLIC) value = asData(vec3(s.metallic));
    else if (kDebugView == CANDELA_DEBUG_OCCLUSION) value = asData(vec3(s.occlusion));
    else if (kDebugView == CANDELA_DEBUG_EMISSIVE) value = emissive;
    else if (kDebugView == CANDELA_DEBUG_DIFFUSE) value = lit.diffuse;
    else if (kDebugView == CANDELA_DEBUG_SPECULAR) value = lit.specular;
    else if (kDebugView == CANDELA_DEBUG_CLEARCOAT) value = lit.coat;
    else if (kDebugView == CANDELA_DEBUG_SHEEN) value = lit.sheen;
    else if (kDebugView == CANDELA_DEBUG_TRANSMISSION) {
#ifdef CANDELA_MATERIAL_LAYERS
        value = asData(throughput);
#endif
    }
    else if (kDebugView == CANDELA_DEBUG_DIFFUSE_TRANSMISSION) {
#ifdef CANDELA_MATERIAL_LAYERS
        value = lit.diffuseTransmission;  // black without the layer
#endif
    }
    else if (kDebugView == CANDELA_DEBUG_DISPERSION) {
#ifdef CANDELA_MATERIAL_LAYERS
        // The angle between the red and the blue refracted rays, 1° white; black without dispersion.
        if (hasLayer(CANDELA_LAYER_DISPERSION) && dot(s.layers.volume.ray, s.layers.volume.ray) > 0.0f)
            value = asData(vec3(angleBetween(normalize(s.layers.volume.redRay), normalize(s.layers.volume.blueRay)) *
                                (180.0f / CANDELA_PI)));
#endif
    }
    else if (kDebugView == CANDELA_DEBUG_IRIDESCENCE_THICKNESS || kDebugView == CANDELA_DEBUG_IRIDESCENCE_FRESNEL) {
#ifdef CANDELA_MATERIAL_LAYERS
        // The film's thickness in µm as grey (1 µm white), and the Fresnel it gives at N·V (the
        // material's, dielectric and metal mixed, with the film at its weight); black without a film.
        if (hasLayer(CANDELA_LAYER_IRIDESCENCE) && s.layers.dielectric.film > 0.0f) {
            if (kDebugView == CANDELA_DEBUG_IRIDESCENCE_THICKNESS) value = asData(vec3(s.layers.film.thickness * 1e-3f));
            else value = asData(fresnelDielectricMetal(clamp(dot(s.normal, s.v), 0.0f, 1.0f), s.baseColor, s.metallic,
                                                       s.layers.dielectric));
        }
#endif
    }
    else if (kDebugView == CANDELA_DEBUG_ANISOTROPY) {
#ifdef CANDELA_MATERIAL_LAYERS
        // T as n·0.5+0.5, scaled by the strength; black without anisotropy.
        if (hasLayer(CANDELA_LAYER_ANISOTROPY)) value = asData((s.layers.anisotropy.t * 0.5f + 0.5f) * s.layers.anisotropy.strength);
#endif
    }
    else if (kDebugView == CANDELA_DEBUG_CLEARCOAT_NORMAL) {
#ifdef CANDELA_MATERIAL_LAYERS
        if (hasLayer(CANDELA_LAYER_CLEARCOAT)) value = asData(s.layers.coat.normal * 0.5f + 0.5f);  // black without a coat
#endif
    }
    else value = asData(termTowardFirstLight(s));
    return value;
}

#endif
