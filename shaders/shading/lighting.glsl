// Lighting of the forward programs: a Surface (shading/surface.glsl) lit by punctual lights and by
// the environment, Surface → radiance toward the viewer, per lobe (SurfaceLight). The BRDFs are
// shared/brdf.h's and, in the layered program, shared/brdf_layers.h's; the split sum is
// shared/ibl.h's. Nothing here reads a stage input: what the fragment stage alone knows (its pixel)
// is an argument.
#ifndef CANDELA_FORWARD_LIGHTING_GLSL
#define CANDELA_FORWARD_LIGHTING_GLSL

#include "shading/resources.glsl"
#include "shading/surface.glsl"
#include "shared/ibl.h"

// Radiance toward the viewer, per lobe: the material's diffuse and specular reflection, its
// transmitted light (from punctual lights behind it) and diffusely transmitted light (from the
// lights and the environment behind it), and the sheen's and the coat's own reflections. Only the
// layered program has the last four.
struct SurfaceLight {
    vec3 diffuse;
    vec3 specular;
    vec3 transmission;
    vec3 diffuseTransmission;
    vec3 sheen;
    vec3 coat;
};

SurfaceLight noLight() {
    SurfaceLight light;
    light.diffuse = vec3(0.0f);
    light.specular = vec3(0.0f);
    light.transmission = vec3(0.0f);
    light.diffuseTransmission = vec3(0.0f);
    light.sheen = vec3(0.0f);
    light.coat = vec3(0.0f);
    return light;
}

SurfaceLight plus(SurfaceLight a, SurfaceLight b) {
    a.diffuse += b.diffuse;
    a.specular += b.specular;
    a.transmission += b.transmission;
    a.diffuseTransmission += b.diffuseTransmission;
    a.sheen += b.sheen;
    a.coat += b.coat;
    return a;
}

// Direction to punctual light `light` from world position `p` and its attenuation there.
bool hasLightType(uint type) { return (kLightTypes & (1u << type)) != 0u; }

// Whether `light` is of `type`: a constant where the frame has that type alone, or not at all.
bool isLightType(LightData light, uint type) {
    if (!hasLightType(type)) return false;
    return kLightTypes == (1u << type) || light.directionType.w == float(type);
}

vec3 lightDirection(LightData light, vec3 p, out float attenuation) {
    attenuation = 1.0f;
    if (isLightType(light, CANDELA_LIGHT_DIRECTIONAL)) return -light.directionType.xyz;
    vec3 toLight = light.positionRange.xyz - p;
    float distance2 = dot(toLight, toLight);
    vec3 l = toLight * inversesqrt(max(distance2, 1e-30f));
    attenuation = rangeAttenuation(distance2, light.positionRange.w);
    if (isLightType(light, CANDELA_LIGHT_SPOT)) attenuation *= spotAttenuation(-l, light.directionType.xyz, light.cone);
    return l;
}

// What punctual light `light` sends from `s` toward the viewer. In the layered program the
// material lies beneath the sheen and the coat (layeredLobesTimesCosine combines them), and its
// transmitted light comes through the volume: a point or spot light is seen from where the
// refracted ray leaves it (the green ray's, with dispersion), and attenuated along that ray; the
// diffusely transmitted light is attenuated along the thickness likewise.
SurfaceLight lightRadiance(Surface s, LightData light) {
    float attenuation;
    vec3 l = lightDirection(light, s.position, attenuation);
    vec3 radiance = (light.color * light.intensity) * attenuation;
    SurfaceLight lit = noLight();
#ifdef CANDELA_MATERIAL_LAYERS
    vec3 lt = l;
    if (hasLayer(CANDELA_LAYER_VOLUME) && !isLightType(light, CANDELA_LIGHT_DIRECTIONAL)) {
        vec3 toLight = light.positionRange.xyz - (s.position + s.layers.volume.ray);
        lt = dot(toLight, toLight) > 0.0f ? normalize(toLight) : l;
    }
    LayeredLobes lobes = layeredLobesTimesCosine(s.normal, s.v, l, lt, s.baseColor, s.metallic, s.roughness, kShadingModel,
                                                 layerBits(), s.layers.dielectric, s.layers.anisotropy,
                                                 s.layers.transmission, s.layers.diffuseTransmission, s.layers.sheen,
                                                 s.layers.coat);
    lit.diffuse = lobes.diffuse * radiance;
    lit.specular = lobes.specular * radiance;
    lit.sheen = lobes.sheen * radiance;
    lit.coat = lobes.clearcoat * radiance;
    lit.transmission = lobes.transmission * radiance * s.layers.volume.transmittance;
    if (hasLayer(CANDELA_LAYER_DIFFUSE_TRANSMISSION))
        lit.diffuseTransmission = lobes.diffuseTransmission * radiance * s.layers.volume.transmittance;
#else
    BrdfLobes lobes = brdfLobesTimesCosine(s.normal, s.v, l, s.baseColor, s.metallic, s.roughness, kShadingModel);
    lit.diffuse = lobes.diffuse * radiance;
    lit.specular = lobes.specular * radiance;
#endif
    return lit;
}

// The environment's irradiance / π at world normal `n`.
vec3 irradianceAt(vec3 n) {
    vec3 nEnv = iblLookupDirection(n, push.ibl.rotation);
    if (!kIrradianceSh) return textureLod(irradianceCube, nEnv, 0.0f).rgb;
    vec3 irradiance = vec3(0.0f);
    for (uint i = 0u; i < 9u; ++i) irradiance += sh[i].rgb * shBasis(i, nEnv);
    return max(irradiance, vec3(0.0f));  // order-2 ringing can dip below 0
}

// The prefiltered environment in the mirror direction of `v` about `n` at perceptual roughness
// `roughness`.
vec3 prefilteredAt(vec3 n, vec3 v, float roughness) {
    vec3 r = iblLookupDirection(reflect(-v, n), push.ibl.rotation);
    // Roughness 0 reads mip 0 (the environment) exactly; the mips in between are linearly blended.
    return textureLod(specularCube, r, roughness * push.ibl.maxLod).rgb;
}

// The split sum's (A, B) at (N·V, perceptual roughness).
vec2 splitSumAt(float NoV, float roughness) {
    return textureLod(brdfLut, brdfLutUv(NoV, roughness, push.ibl.lutSize), 0.0f).rg;
}

// Light from the environment (split sum), each lobe on its own: the material's diffuse and
// specular reflection and the sheen's and the coat's — not yet layered (underLayers does that).
// Occlusion (glTF: indirect light only) darkens the diffuse terms and, through specular occlusion,
// the specular ones.
SurfaceLight imageBasedLight(Surface s) {
    float ao = s.occlusion;
    float NoV = clamp(dot(s.normal, s.v), CANDELA_MIN_NOV, 1.0f);
    vec3 prefiltered;
    // The roughness the split sum is read at: an anisotropic lobe's mean roughness (shared/brdf_anisotropy.h).
    float roughness = s.roughness;
#ifdef CANDELA_MATERIAL_LAYERS
    if (hasLayer(CANDELA_LAYER_ANISOTROPY)) {
        // The streak where the bent normal puts it, as sharp as the narrow axis; the energy of the
        // stretched lobe (the split sum's albedo at its mean roughness).
        roughness = anisotropicIblRoughness(s.roughness, s.layers.anisotropy.strength);
        prefiltered = prefilteredAt(anisotropicBentNormal(s.normal, s.v, s.roughness, s.layers.anisotropy), s.v, s.roughness);
    } else
#endif
    prefiltered = prefilteredAt(s.normal, s.v, s.roughness);
    vec3 irradiance = irradianceAt(s.normal);
    vec2 lut = splitSumAt(NoV, roughness);
    vec3 diffuseColor = s.baseColor * (1.0f - s.metallic);
    BrdfLobes lobes;
#ifdef CANDELA_MATERIAL_LAYERS
    // Transmission takes its share of the Lambert part (the rest of it is the light from behind,
    // transmittedThroughput, with or without an environment), and of what remains the diffuse
    // transmission takes its own (the irradiance from behind, below).
    float lambertFraction = 1.0f - s.layers.transmission.weight;
    if (hasLayer(CANDELA_LAYER_DIFFUSE_TRANSMISSION)) lambertFraction *= 1.0f - s.layers.diffuseTransmission.weight;
    if (hasLayer(CANDELA_LAYER_SPECULAR) || hasLayer(CANDELA_LAYER_TRANSMISSION) || hasLayer(CANDELA_LAYER_IRIDESCENCE) ||
        hasLayer(CANDELA_LAYER_DIFFUSE_TRANSMISSION))
        lobes = iblShadeLobesDielectric(prefiltered, irradiance, lut, s.baseColor, s.metallic, s.layers.dielectric,
                                        kMultiscatter, ao, specularOcclusion(NoV, ao, roughness), lambertFraction);
    else
#endif
    lobes = iblShadeLobes(prefiltered, irradiance, lut, s.f0, diffuseColor, kMultiscatter, ao,
                          specularOcclusion(NoV, ao, roughness));
    SurfaceLight light = noLight();
    light.diffuse = lobes.diffuse * push.ibl.intensity;
    light.specular = lobes.specular * push.ibl.intensity;
#ifdef CANDELA_MATERIAL_LAYERS
    if (hasLayer(CANDELA_LAYER_DIFFUSE_TRANSMISSION)) {
        // The irradiance from behind the surface, through the volume's thickness.
        vec3 behind = irradianceAt(-s.normal) * s.layers.volume.transmittance;
        light.diffuseTransmission = push.ibl.intensity * (1.0f - s.layers.transmission.weight) *
                                    iblDiffuseTransmission(s.layers.diffuseTransmission, behind, lut, s.metallic,
                                                           s.layers.dielectric, kMultiscatter, ao);
    }
    if (hasLayer(CANDELA_LAYER_SHEEN)) {
        vec3 d = iblLookupDirection(sheenLookupDirection(s.normal, s.v), push.ibl.rotation);
        vec3 prefilteredSheen = textureLod(sheenCube, d, s.layers.sheen.roughness * push.ibl.maxLod).rgb;
        light.sheen = push.ibl.intensity * iblSheen(s.layers.sheen, prefilteredSheen, ao);
    }
    if (hasLayer(CANDELA_LAYER_CLEARCOAT)) {
        Clearcoat coat = s.layers.coat;
        light.coat = push.ibl.intensity * iblClearcoat(coat, prefilteredAt(coat.normal, s.v, coat.roughness),
                                                       irradianceAt(coat.normal), splitSumAt(coat.NoV, coat.roughness),
                                                       kMultiscatter, ao, specularOcclusion(coat.NoV, ao, coat.roughness));
    }
#endif
    return light;
}

#ifdef CANDELA_MATERIAL_LAYERS
// `light`, reflected by the material and its layers each on its own, as it leaves the layered
// surface: the material beneath the sheen (which passes its baseWeight of it), both beneath the
// coat (likewise). Punctual lights are layered per light by layeredLobesTimesCosine; this is the
// same for light summed otherwise (the environment's).
SurfaceLight underLayers(SurfaceLight light, Surface s) {
    if (hasLayer(CANDELA_LAYER_SHEEN)) {
        light.diffuse *= s.layers.sheen.baseWeight;
        light.specular *= s.layers.sheen.baseWeight;
        light.transmission *= s.layers.sheen.baseWeight;
        light.diffuseTransmission *= s.layers.sheen.baseWeight;
    }
    if (hasLayer(CANDELA_LAYER_CLEARCOAT)) {
        light.diffuse *= s.layers.coat.baseWeight;
        light.specular *= s.layers.coat.baseWeight;
        light.transmission *= s.layers.coat.baseWeight;
        light.diffuseTransmission *= s.layers.coat.baseWeight;
        light.sheen *= s.layers.coat.baseWeight;
    }
    return light;
}

// The fraction of the light behind `s` that its material lets through toward the viewer (not yet
// beneath the sheen and the coat): the transmission lobe's albedo, the split sum's (A, B) at the
// transmission roughness, at most what the reflections leave (the split sum at the material's
// roughness; iblTransmission) — with an environment from the BRDF LUT, without one from Karis's
// analytic fit of it; and the volume's transmittance.
vec3 transmittedThroughput(Surface s) {
    float NoV = clamp(dot(s.normal, s.v), CANDELA_MIN_NOV, 1.0f);
    float roughness = s.layers.transmission.roughness;
    vec2 lut = kIbl ? splitSumAt(NoV, s.roughness) : envBrdfApproximation(NoV, s.roughness);
    vec2 transmissionLut = kIbl ? splitSumAt(NoV, roughness) : envBrdfApproximation(NoV, roughness);
    return iblTransmission(s.layers.transmission, vec3(1.0f), lut, transmissionLut, s.baseColor, s.metallic,
                           s.layers.dielectric, kMultiscatter) * s.layers.volume.transmittance;
}

// The background (the opaque image) where the ray leaving a volume at world position `exit` meets
// the screen, at mip `lod`; where that point is behind the camera, straight behind `pixel` (window
// coordinates) instead.
vec4 backgroundAt(vec3 exit, vec2 pixel, vec2 size, float lod) {
    vec2 uv = pixel / size;
    vec4 clip = push.viewProjection * vec4(exit, 1.0f);
    if (clip.w > 1e-6f) uv = clamp(clip.xy / clip.w * 0.5f + 0.5f, vec2(0.0f), vec2(1.0f));
    return textureLod(transmissionBackground, uv, lod);
}

// The light from behind a transmitting surface: the background where the ray leaves the volume (at
// the surface itself when thin-walled), at the mip of the BTDF's roughness (log2(width) ·
// roughness, as the Khronos sample viewer), attenuated by the volume. With dispersion each channel
// where its own ray leaves (three reads, one channel of each; the mip is the material's). alpha:
// the background's coverage there (the green ray's).
vec4 transmittedBackground(Surface s, vec2 pixel) {
    vec2 size = vec2(textureSize(transmissionBackground, 0));
    float lod = log2(max(size.x, size.y)) * s.layers.transmission.roughness;
    vec4 behind = backgroundAt(s.position + s.layers.volume.ray, pixel, size, lod);
    if (hasLayer(CANDELA_LAYER_DISPERSION)) {
        behind.r = backgroundAt(s.position + s.layers.volume.redRay, pixel, size, lod).r;
        behind.b = backgroundAt(s.position + s.layers.volume.blueRay, pixel, size, lod).b;
    }
    return vec4(behind.rgb * s.layers.volume.transmittance, behind.a);
}
#endif

#endif
