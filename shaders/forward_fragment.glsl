// The forward pass's fragment stage, included by forward.frag.glsl (core glTF materials) and by
// forward_layers.frag.glsl (materials with KHR_materials_* layers: CANDELA_MATERIAL_LAYERS defined,
// the layer code and its descriptors compiled in). glTF metallic-roughness material lit by
// punctual lights with the BRDFs of shared/brdf.h. Variants are specialization constants, so what
// a draw does not use costs nothing: no normal map → no TBN work; no lights → no light loop;
// unlit → no BRDF; no environment → no image-based lighting (shared/ibl.h: split sum,
// multiscatter, specular occlusion); in the layered program, only the layers the material uses.
#include "shared/brdf.h"
#include "shared/environment.h"
#include "shared/ibl.h"
#include "shared/scene_data.h"
#include "shared/tonemap.h"
#ifdef CANDELA_MATERIAL_LAYERS
#include "shared/brdf_layers.h"
#endif

layout(constant_id = 0) const bool kNormalMap = false;
layout(constant_id = 1) const bool kLights = true;
layout(constant_id = 2) const bool kUnlit = false;
layout(constant_id = 3) const bool kAlphaMask = false;
layout(constant_id = 4) const uint kShadingModel = CANDELA_SHADING_PBR;
layout(constant_id = 5) const bool kIbl = false;
layout(constant_id = 6) const bool kIrradianceSh = true;  // else the irradiance cube
layout(constant_id = 7) const bool kMultiscatter = true;
// > 0: ground truth for `candela ibl-report` — integrate the reflectance equation against the
// environment (the specular cube's mip 0) per pixel with this many GGX and as many cosine samples,
// instead of the split sum.
layout(constant_id = 8) const uint kReferenceSamples = 0u;
// A debug view (CANDELA_DEBUG_*) instead of the shaded colour.
layout(constant_id = 9) const uint kDebugView = CANDELA_DEBUG_NONE;
#ifdef CANDELA_MATERIAL_LAYERS
// The layers this variant evaluates (CANDELA_LAYER_* bits): a material pays only for its own.
layout(constant_id = 10) const uint kLayers = 0u;
#endif
// Specular anti-aliasing: roughness widened by the normal's change across the pixel and by what the
// normal map's mip averaged away (specularAntiAliasedRoughness, shared/brdf.h).
layout(constant_id = 11) const bool kSpecularAa = false;
// Alpha to coverage (MSAA, alpha-masked materials): the pipeline turns the output alpha into the
// sample coverage (and stores alpha 1: alphaToOne) instead of the alpha test's all-or-nothing.
layout(constant_id = 12) const bool kAlphaToCoverage = false;

layout(std430, set = 0, binding = 0) readonly buffer Lights {
    LightData lights[];
};
layout(std430, set = 0, binding = 1) readonly buffer Draws {
    DrawData draws[];
};
layout(std430, set = 0, binding = 2) readonly buffer Materials {
    MaterialData materials[];
};
layout(set = 1, binding = 0) uniform sampler2D baseColorTexture;
layout(set = 1, binding = 1) uniform sampler2D metallicRoughnessTexture;
layout(set = 1, binding = 2) uniform sampler2D normalTexture;
layout(set = 1, binding = 3) uniform sampler2D occlusionTexture;
layout(set = 1, binding = 4) uniform sampler2D emissiveTexture;
#ifdef CANDELA_MATERIAL_LAYERS
layout(std430, set = 1, binding = 5) readonly buffer MaterialLayers {
    MaterialLayerData layers[];
};
layout(set = 1, binding = 6) uniform sampler2D specularTexture;
layout(set = 1, binding = 7) uniform sampler2D specularColorTexture;
layout(set = 1, binding = 8) uniform sampler2D clearcoatTexture;
layout(set = 1, binding = 9) uniform sampler2D clearcoatRoughnessTexture;
layout(set = 1, binding = 10) uniform sampler2D clearcoatNormalTexture;
layout(set = 1, binding = 11) uniform sampler2D sheenColorTexture;
layout(set = 1, binding = 12) uniform sampler2D sheenRoughnessTexture;
layout(set = 1, binding = 13) uniform sampler2D anisotropyTexture;
layout(set = 1, binding = 14) uniform sampler2D transmissionTexture;
layout(set = 1, binding = 15) uniform sampler2D thicknessTexture;
layout(set = 1, binding = 16) uniform sampler2D iridescenceTexture;
layout(set = 1, binding = 17) uniform sampler2D iridescenceThicknessTexture;
// The layers' maps (set 3, the layered program only; placeholders where the frame has none): the
// sheen albedo LUT E(N·V, sheen roughness), the Charlie-prefiltered environment, and what lies
// behind the transmissive draws (the opaque image, mip m box-filtered 2^m × 2^m; passes/
// transmission_background_pass.h).
layout(set = 3, binding = 0) uniform sampler2D sheenLut;
layout(set = 3, binding = 1) uniform samplerCube sheenCube;
layout(set = 3, binding = 2) uniform sampler2D transmissionBackground;
#endif
// Image-based lighting (always bound; placeholders when the frame has no environment).
layout(set = 2, binding = 0) uniform samplerCube specularCube;
layout(set = 2, binding = 1) uniform samplerCube irradianceCube;
layout(set = 2, binding = 2) uniform sampler2D brdfLut;
layout(std140, set = 2, binding = 3) uniform IrradianceSh {
    vec4 sh[9];  // convolved, /π: irradiance(n)/π = Σ sh[i] · Y_i(n)
};
// Ground truth only (kReferenceSamples > 0): the environment as an equirectangular map (nearest
// texels; alpha 0 marks the brightest texels, which are summed explicitly instead of sampled) and
// the list of those texels: referenceTexels[0] = (count, width, height, 0), then per texel
// (x, y, 0, 0) and (radiance, 0).
layout(set = 2, binding = 4) uniform sampler2D referenceEquirect;
layout(std430, set = 2, binding = 5) readonly buffer ReferenceTexels {
    vec4 referenceTexels[];
};
layout(push_constant) uniform Push {
    ForwardPush push;
};

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec4 inColor;
layout(location = 4) in vec2 inTexUv[CANDELA_TEX_COUNT];  // per texture slot, transformed (see forward_vertex.glsl)
#ifdef CANDELA_MATERIAL_LAYERS
layout(location = 4 + CANDELA_TEX_COUNT) in vec4 inLayerUv[(CANDELA_LAYER_TEX_COUNT + 1) / 2];  // two layer slots each
#endif

layout(location = 0) out vec4 outColor;

vec4 sampleSlot(sampler2D tex, int slot) {
    return texture(tex, inTexUv[slot]);
}

// Interpolated normal flipped for back faces of double-sided materials (or, where it degenerates,
// the face normal on the viewer's side).
vec3 facedNormal() {
    // The sign of dFdx × dFdy depends on the framebuffer's y direction (in Vulkan's y-down one it
    // points away from the viewer), not on the winding: orient it toward the eye explicitly.
    vec3 faceNormal = normalize(cross(dFdx(inWorldPosition), dFdy(inWorldPosition)));
    if (dot(faceNormal, push.eye.xyz - inWorldPosition) < 0.0f) faceNormal = -faceNormal;
    vec3 n = faceNormal;
    if (dot(inNormal, inNormal) > 1e-12f) n = gl_FrontFacing ? normalize(inNormal) : -normalize(inNormal);
    return n;
}

// Unit normal `n` perturbed by a tangent-space normal-map value (texel · 2 − 1) with the map's
// scale, in the vertex tangent frame; `n` itself where that frame degenerates.
vec3 mapNormal(vec3 n, vec3 tangentNormal, float scale) {
    vec3 t = inTangent.xyz - n * dot(n, inTangent.xyz);
    // Relative to the tangent's own length, which scales with the draw's transform: an absolute
    // threshold let the rounding residual of a tangent along the normal through at scale 1e4
    // (an arbitrary tangent frame) and would drop valid tangents of scenes scaled by 1e-6.
    if (dot(t, t) <= 1e-6f * dot(inTangent.xyz, inTangent.xyz)) return n;
    t = normalize(t);
    vec3 b = cross(n, t) * (inTangent.w < 0.0f ? -1.0f : 1.0f);
    tangentNormal.xy *= scale;
    vec3 mapped = mat3(t, b, n) * tangentNormal;
    return dot(mapped, mapped) > 1e-12f ? normalize(mapped) : n;
}

// The length of the mean normal the normal map's filtered texel stands for (its A: 1 at mip 0,
// less where a mip averaged diverging normals; scene/normal_map_mips.h), set by shadingNormal.
float gNormalMapLength = 1.0f;

// Shading normal: the faced normal, perturbed by the normal map when the variant has one and
// `mapped` is set.
vec3 shadingNormal(MaterialData m, bool mapped) {
    vec3 n = facedNormal();
    if (kNormalMap && mapped) {
        // Sampled outside any non-uniform branch: implicit-LOD sampling needs uniform control flow.
        vec4 texel = sampleSlot(normalTexture, CANDELA_TEX_NORMAL);
        n = mapNormal(n, texel.xyz * 2.0f - 1.0f, m.normalScale);
        gNormalMapLength = texel.a;
    }
    return n;
}

// |∂n/∂x|² + |∂n/∂y|² of the faced (interpolated vertex) normal, for geometric specular AA; the
// normal map's detail is accounted for by its filtered length instead.
float normalChange() {
    vec3 n = facedNormal();
    vec3 dx = dFdx(n), dy = dFdy(n);
    return dot(dx, dx) + dot(dy, dy);
}
float gNormalChange = 0.0f;

#ifdef CANDELA_MATERIAL_LAYERS
// This fragment's layers, set by main before any lighting: the dielectric Fresnel (the core's f0
// 0.04, f90 1 unless the specular layer changes it), the coat, and the light the coat reflects.
DielectricFresnel gDielectric;
Clearcoat gCoat;
vec3 gCoatLight = vec3(0.0f);
Sheen gSheen;
Anisotropy gAnisotropy;
Transmission gTransmission;
vec3 gSheenLight = vec3(0.0f);
vec3 gTransmissionLight = vec3(0.0f);
// The volume beneath a transmitting surface: the ray refracted through its thickness (world units;
// zero when thin-walled) and the transmittance along it.
vec3 gVolumeRay = vec3(0.0f);
vec3 gVolumeTransmittance = vec3(1.0f);

// The layers this variant evaluates: the material's, none under Blinn-Phong (kept for comparison
// with the original project, it has no Fresnel to layer).
uint layerBits() { return kShadingModel == CANDELA_SHADING_BLINN_PHONG ? 0u : kLayers; }
bool hasLayer(uint bit) { return (layerBits() & bit) != 0u; }

vec2 layerUv(int slot) {
    vec4 pair = inLayerUv[slot / 2];
    return (slot & 1) == 0 ? pair.xy : pair.zw;
}

// The thin film's thickness in nm (KHR_materials_iridescence: the maximum without a texture).
float gFilmThickness = 0.0f;

// Specialization-constant branches only: uniform, so the samples inside keep their derivatives.
// The dielectric Fresnel (the specular layer's or the core's) with the thin film at N·V over it and
// over the metal's `baseColor`, seen from the coat's IOR where `coat` covers it.
DielectricFresnel layerDielectric(MaterialLayerData layer, float NoV, vec3 baseColor, float coat) {
    DielectricFresnel d = coreDielectricFresnel();
    if (hasLayer(CANDELA_LAYER_SPECULAR)) {
        float specular = layer.specular * texture(specularTexture, layerUv(CANDELA_LAYER_TEX_SPECULAR)).a;
        vec3 color = layer.specularColor * texture(specularColorTexture, layerUv(CANDELA_LAYER_TEX_SPECULAR_COLOR)).rgb;
        d = dielectricFresnel(layer.ior, color, specular);
    }
    if (hasLayer(CANDELA_LAYER_IRIDESCENCE)) {
        float weight = clamp(layer.iridescence * texture(iridescenceTexture, layerUv(CANDELA_LAYER_TEX_IRIDESCENCE)).r, 0.0f, 1.0f);
        float g = texture(iridescenceThicknessTexture, layerUv(CANDELA_LAYER_TEX_IRIDESCENCE_THICKNESS)).g;
        gFilmThickness = max(mix(layer.iridescenceThicknessMinimum, layer.iridescenceThicknessMaximum, g), 0.0f);
        d = withThinFilm(d, weight, max(layer.iridescenceIor, 1.0f), gFilmThickness, 1.0f + 0.5f * coat, NoV, baseColor);
    }
    return d;
}

// The coat on the faced normal `faced` (its own normal map, if any; not the material's).
Clearcoat layerClearcoat(MaterialLayerData layer, vec3 faced, vec3 v) {
    if (!hasLayer(CANDELA_LAYER_CLEARCOAT)) return clearcoatLayer(0.0f, 0.0f, faced, v);
    float weight = layer.clearcoat * texture(clearcoatTexture, layerUv(CANDELA_LAYER_TEX_CLEARCOAT)).r;
    float roughness = layer.clearcoatRoughness * texture(clearcoatRoughnessTexture, layerUv(CANDELA_LAYER_TEX_CLEARCOAT_ROUGHNESS)).g;
    vec3 nc = faced;
    float mapLength = 1.0f;
    if (hasLayer(CANDELA_LAYER_CLEARCOAT_NORMAL)) {
        vec4 texel = texture(clearcoatNormalTexture, layerUv(CANDELA_LAYER_TEX_CLEARCOAT_NORMAL));
        nc = mapNormal(faced, texel.xyz * 2.0f - 1.0f, layer.clearcoatNormalScale);
        mapLength = texel.a;
    }
    if (kSpecularAa) roughness = specularAntiAliasedRoughness(clamp(roughness, 0.0f, 1.0f), gNormalChange, mapLength);
    return clearcoatLayer(clamp(weight, 0.0f, 1.0f), clamp(roughness, 0.0f, 1.0f), nc, v);
}

// The anisotropy on shading normal `n`: direction (the texture's RG, or the tangent) rotated by
// anisotropyRotation in the tangent plane, strength anisotropyStrength × the texture's B. None where
// the tangent frame degenerates.
Anisotropy layerAnisotropy(MaterialLayerData layer, vec3 n) {
    Anisotropy none = anisotropyLayer(0.0f, vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f));
    if (!hasLayer(CANDELA_LAYER_ANISOTROPY)) return none;
    vec3 texel = texture(anisotropyTexture, layerUv(CANDELA_LAYER_TEX_ANISOTROPY)).rgb;
    bool textured = layer.anisotropyTextured > 0.5f;
    vec2 direction = textured ? texel.rg * 2.0f - 1.0f : vec2(1.0f, 0.0f);
    float strength = clamp(layer.anisotropy * (textured ? texel.b : 1.0f), 0.0f, 1.0f);
    float c = cos(layer.anisotropyRotation), s = sin(layer.anisotropyRotation);
    direction = vec2(c * direction.x - s * direction.y, s * direction.x + c * direction.y);
    vec3 t = inTangent.xyz - n * dot(n, inTangent.xyz);
    if (dot(t, t) <= 1e-6f * dot(inTangent.xyz, inTangent.xyz) || dot(direction, direction) < 1e-12f) return none;
    t = normalize(t);
    vec3 b = cross(n, t) * (inTangent.w < 0.0f ? -1.0f : 1.0f);
    vec3 along = normalize(t * direction.x + b * direction.y);
    return anisotropyLayer(strength, along, cross(n, along));
}

// The transmission: its weight and BTDF roughness (the material's, scaled by the IOR).
Transmission layerTransmission(MaterialLayerData layer, float roughness) {
    if (!hasLayer(CANDELA_LAYER_TRANSMISSION)) return transmissionLayer(0.0f, 0.0f, 1.5f);
    float weight = layer.transmission * texture(transmissionTexture, layerUv(CANDELA_LAYER_TEX_TRANSMISSION)).r;
    return transmissionLayer(clamp(weight, 0.0f, 1.0f), roughness, layer.ior);
}

// The volume (KHR_materials_volume) on shading normal `n`: V refracted into it (IOR below 1 taken as
// 1) across its thickness — thicknessFactor × texture (G) in the mesh's units, scaled by the draw's
// world transform (the mean of its axes' scales) — sets gVolumeRay and gVolumeTransmittance.
void layerVolume(MaterialLayerData layer, vec3 n, vec3 v) {
    if (!hasLayer(CANDELA_LAYER_VOLUME)) return;
    float thickness = layer.thickness * texture(thicknessTexture, layerUv(CANDELA_LAYER_TEX_THICKNESS)).g;
    mat4 world = draws[push.counts.y].world;
    float scale = (length(world[0].xyz) + length(world[1].xyz) + length(world[2].xyz)) * (1.0f / 3.0f);
    vec3 refracted = refract(-v, n, 1.0f / max(layer.ior, 1.0f));
    gVolumeRay = normalize(refracted) * (max(thickness, 0.0f) * scale);
    gVolumeTransmittance = volumeTransmittance(layer.attenuationColor, layer.attenuationDistance, length(gVolumeRay));
}

// The light from behind a transmitting surface: the background (the opaque image) where the ray
// leaves the volume (at the surface itself when thin-walled), at the mip of the BTDF's roughness
// (log2(width) · roughness, as the Khronos sample viewer), attenuated by the volume. Where that exit
// point is behind the camera, the background straight behind the fragment. alpha: the background's
// coverage there.
vec4 transmittedBackground() {
    vec2 size = vec2(textureSize(transmissionBackground, 0));
    vec2 uv = gl_FragCoord.xy / size;
    vec4 clip = push.viewProjection * vec4(inWorldPosition + gVolumeRay, 1.0f);
    if (clip.w > 1e-6f) uv = clamp(clip.xy / clip.w * 0.5f + 0.5f, vec2(0.0f), vec2(1.0f));
    float lod = log2(max(size.x, size.y)) * gTransmission.roughness;
    vec4 behind = textureLod(transmissionBackground, uv, lod);
    return vec4(behind.rgb * gVolumeTransmittance, behind.a);
}

// The sheen on shading normal `n`, with its albedo E(N·V) from the LUT.
Sheen layerSheen(MaterialLayerData layer, vec3 n, vec3 v) {
    if (!hasLayer(CANDELA_LAYER_SHEEN)) return sheenLayer(vec3(0.0f), 0.0f, 0.0f);
    vec3 color = layer.sheenColor * texture(sheenColorTexture, layerUv(CANDELA_LAYER_TEX_SHEEN_COLOR)).rgb;
    float roughness =
        clamp(layer.sheenRoughness * texture(sheenRoughnessTexture, layerUv(CANDELA_LAYER_TEX_SHEEN_ROUGHNESS)).a, 0.0f, 1.0f);
    float NoV = clamp(dot(n, v), CANDELA_MIN_NOV, 1.0f);
    float albedo = textureLod(sheenLut, brdfLutUv(NoV, roughness, float(textureSize(sheenLut, 0).x)), 0.0f).r;
    return sheenLayer(color, roughness, albedo);
}
#endif

// f(V, L) · (N·L) of the fragment's material toward light direction `l`, as diffuse and specular
// (in the layered program: beneath the sheen and the coat, whose own reflections go to `sheen` and
// `coat`; the light transmitted from `lt` — `l` seen from where a volume's ray leaves it — to
// `transmission`).
BrdfLobes surfaceLobes(vec3 n, vec3 v, vec3 l, vec3 lt, vec3 baseColor, float metallic, float roughness, out vec3 sheen,
                       out float coat, out vec3 transmission) {
#ifdef CANDELA_MATERIAL_LAYERS
    LayeredLobes layered = layeredLobesTimesCosine(n, v, l, lt, baseColor, metallic, roughness, kShadingModel, layerBits(),
                                                   gDielectric, gAnisotropy, gTransmission, gSheen, gCoat);
    sheen = layered.sheen;
    coat = layered.clearcoat;
    transmission = layered.transmission;
    BrdfLobes lobes;
    lobes.diffuse = layered.diffuse;
    lobes.specular = layered.specular;
    return lobes;
#else
    sheen = vec3(0.0f);
    coat = 0.0f;
    transmission = vec3(0.0f);
    return brdfLobesTimesCosine(n, v, l, baseColor, metallic, roughness, kShadingModel);
#endif
}

float occlusion(MaterialData m) {
    return 1.0f + m.occlusionStrength * (sampleSlot(occlusionTexture, CANDELA_TEX_OCCLUSION).r - 1.0f);
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
// `roughness`, and the split sum's (A, B) there.
vec3 prefilteredAt(vec3 n, vec3 v, float roughness) {
    vec3 r = iblLookupDirection(reflect(-v, n), push.ibl.rotation);
    // Roughness 0 reads mip 0 (the environment) exactly; the mips in between are linearly blended.
    return textureLod(specularCube, r, roughness * push.ibl.maxLod).rgb;
}
vec2 splitSumAt(float NoV, float roughness) {
    return textureLod(brdfLut, brdfLutUv(NoV, roughness, push.ibl.lutSize), 0.0f).rg;
}

// Diffuse and specular light from the environment (split sum). Occlusion (glTF: indirect light
// only) darkens the diffuse term and, through specular occlusion, the specular one. In the layered
// program the material lies beneath the coat, whose own reflection goes to gCoatLight.
BrdfLobes imageBasedLight(MaterialData m, vec3 n, vec3 v, vec3 baseColor, float metallic, float roughness) {
    float ao = occlusion(m);
    float NoV = clamp(dot(n, v), CANDELA_MIN_NOV, 1.0f);
    vec3 prefiltered;
#ifdef CANDELA_MATERIAL_LAYERS
    if (hasLayer(CANDELA_LAYER_ANISOTROPY))
        prefiltered = prefilteredAt(anisotropicBentNormal(n, v, roughness, gAnisotropy), v, roughness);
    else
#endif
    prefiltered = prefilteredAt(n, v, roughness);
    vec3 irradiance = irradianceAt(n);
    vec2 lut = splitSumAt(NoV, roughness);
    vec3 f0 = mix(vec3(0.04f), baseColor, metallic);
    vec3 diffuseColor = baseColor * (1.0f - metallic);
    BrdfLobes light;
#ifdef CANDELA_MATERIAL_LAYERS
    // Transmission takes its share of the Lambert part (the rest of it is the light from behind,
    // added in main with or without an environment).
    if (hasLayer(CANDELA_LAYER_SPECULAR) || hasLayer(CANDELA_LAYER_TRANSMISSION) || hasLayer(CANDELA_LAYER_IRIDESCENCE))
        light = iblShadeLobesDielectric(prefiltered, irradiance, lut, baseColor, metallic, gDielectric, kMultiscatter, ao,
                                        specularOcclusion(NoV, ao, roughness), 1.0f - gTransmission.weight);
    else
#endif
    light = iblShadeLobes(prefiltered, irradiance, lut, f0, diffuseColor, kMultiscatter, ao,
                          specularOcclusion(NoV, ao, roughness));
    light.diffuse *= push.ibl.intensity;
    light.specular *= push.ibl.intensity;
#ifdef CANDELA_MATERIAL_LAYERS
    if (hasLayer(CANDELA_LAYER_SHEEN)) {
        light.diffuse *= gSheen.baseWeight;
        light.specular *= gSheen.baseWeight;
        vec3 r = iblLookupDirection(reflect(-v, n), push.ibl.rotation);
        vec3 prefilteredSheen = textureLod(sheenCube, r, gSheen.roughness * push.ibl.maxLod).rgb;
        gSheenLight += push.ibl.intensity * iblSheen(gSheen, prefilteredSheen, ao) *
                       (hasLayer(CANDELA_LAYER_CLEARCOAT) ? gCoat.baseWeight : 1.0f);
    }
    if (hasLayer(CANDELA_LAYER_CLEARCOAT)) {
        light.diffuse *= gCoat.baseWeight;
        light.specular *= gCoat.baseWeight;
        gCoatLight += push.ibl.intensity *
                      iblClearcoat(gCoat, prefilteredAt(gCoat.normal, v, gCoat.roughness), irradianceAt(gCoat.normal),
                                   splitSumAt(gCoat.NoV, gCoat.roughness), kMultiscatter, ao,
                                   specularOcclusion(gCoat.NoV, ao, gCoat.roughness));
    }
#endif
    return light;
}

// Radiance of the environment in world direction `d` for the ground truth: its equirectangular
// texel (piecewise constant); with `skipSummed`, 0 for the texels summed explicitly.
vec3 referenceRadiance(vec3 d, bool skipSummed) {
    vec2 uv = directionToEquirectUv(iblLookupDirection(d, push.ibl.rotation), 0.0f);
    ivec2 size = textureSize(referenceEquirect, 0);
    vec4 texel = texelFetch(referenceEquirect, clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0);
    return skipSummed ? texel.rgb * texel.a : texel.rgb;
}

// Ground truth: the reflectance equation of the forward pass's BRDF (single scattering: Cook-Torrance
// GGX with height-correlated Smith visibility and Schlick Fresnel, Lambert weighted by
// (1 − F)(1 − metallic)) against the environment's texels. The brightest texels (a sun, lamps) are
// summed — no sampler finds a 0.5° sun — each as k × k sub-texels with their exact solid angles, k
// chosen so a sub-texel is at most half the specular lobe's width; the rest is integrated by Monte
// Carlo: cosine samples for the diffuse lobe, GGX half-vector samples for the specular one, over a
// per-pixel rotated Hammersley set. When the lobe would need more than kMaxSubdivision (many bright
// texels: large lamps) the specular lobe samples the whole map instead — a lobe that narrow finds
// large bright regions by itself.
vec3 referenceImageBasedLight(vec3 n, vec3 v, vec3 baseColor, float metallic, float roughness) {
    float alpha = roughness * roughness;
    float NoV = clamp(dot(n, v), CANDELA_MIN_NOV, 1.0f);
    vec3 f0 = mix(vec3(0.04f), baseColor, metallic);
    uint count = uint(referenceTexels[0].x);
    vec2 size = referenceTexels[0].yz;
    uint maxSubdivision = count <= 64u ? 16u : (count <= 512u ? 4u : 1u);
    float texelAngle = CANDELA_PI / size.y;
    uint subdivision = uint(clamp(ceil(2.0f * texelAngle / max(alpha, 1e-4f)), 1.0f, 1024.0f));
    bool sumSpecular = subdivision <= maxSubdivision;
    subdivision = min(subdivision, maxSubdivision);
    mat3 frame = basisAround(n);
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint hash = (p.x * 1973u + p.y * 9277u + 26699u) * 0x9E3779B9u;
    vec2 shift = vec2(float(hash & 0xFFFFu), float(hash >> 16u)) / 65536.0f;
    vec3 specular = vec3(0.0f);
    vec3 diffuse = vec3(0.0f);
    for (uint i = 0u; i < kReferenceSamples; ++i) {
        vec2 xi = fract(hammersley(i, kReferenceSamples) + shift);
        vec3 h = frame * sampleGgxHalfVector(xi, alpha).xyz;
        float VoH = dot(v, h);
        vec3 l = 2.0f * VoH * h - v;
        float NoL = dot(n, l);
        if (NoL > 0.0f && VoH > 0.0f) {
            float NoH = max(dot(n, h), 1e-6f);
            specular += referenceRadiance(l, sumSpecular) * fresnelSchlick(VoH, f0) *
                        (visibilitySmithGgxCorrelated(NoV, NoL, alpha) * 4.0f * NoL * VoH / NoH);
        }
        vec3 ld = frame * sampleCosine(xi);
        vec3 hd = normalize(v + ld);
        diffuse += referenceRadiance(ld, true) * (vec3(1.0f) - fresnelSchlick(dot(v, hd), f0));
    }
    diffuse *= baseColor * (1.0f - metallic);
    vec3 sampled = (specular + diffuse) / float(kReferenceSamples);
    // Environment frame → world: the inverse rotation.
    vec4 inverseRotation = vec4(push.ibl.rotation.x, -push.ibl.rotation.y, 0.0f, 0.0f);
    vec3 summed = vec3(0.0f);
    float k = float(subdivision);
    for (uint i = 0u; i < count; ++i) {
        vec2 texel = referenceTexels[1u + 2u * i].xy;
        vec3 radiance = referenceTexels[2u + 2u * i].rgb;
        for (uint sy = 0u; sy < subdivision; ++sy) {
            float v0 = (texel.y + float(sy) / k) / size.y, v1 = (texel.y + float(sy + 1u) / k) / size.y;
            float solidAngle = (CANDELA_TWO_PI / (size.x * k)) * (cos(CANDELA_PI * v0) - cos(CANDELA_PI * v1));
            for (uint sx = 0u; sx < subdivision; ++sx) {
                vec2 uv = vec2((texel.x + (float(sx) + 0.5f) / k) / size.x, 0.5f * (v0 + v1));
                vec3 l = iblLookupDirection(equirectUvToDirection(uv, 0.0f), inverseRotation);
                float NoL = dot(n, l);
                if (NoL <= 0.0f) continue;
                vec3 h = normalize(v + l);
                vec3 F = fresnelSchlick(dot(v, h), f0);
                vec3 f = (vec3(1.0f) - F) * (1.0f - metallic) * baseColor * (1.0f / CANDELA_PI);
                if (sumSpecular) {
                    vec3 nxh = cross(n, h);
                    float NoH = clamp(dot(n, h), 0.0f, 1.0f);
                    f += F * (distributionGgx(NoH, dot(nxh, nxh), alpha) * visibilitySmithGgxCorrelated(NoV, NoL, alpha));
                }
                summed += f * NoL * radiance * solidAngle;
            }
        }
    }
    return (sampled + summed) * push.ibl.intensity;  // no occlusion texture in the report's scene
}

// Direction to punctual light `light` from the surface and its attenuation there.
vec3 lightDirection(LightData light, out float attenuation) {
    attenuation = 1.0f;
    if (light.directionType.w == float(CANDELA_LIGHT_DIRECTIONAL)) return -light.directionType.xyz;
    vec3 toLight = light.positionRange.xyz - inWorldPosition;
    float distance2 = dot(toLight, toLight);
    vec3 l = toLight * inversesqrt(max(distance2, 1e-30f));
    attenuation = rangeAttenuation(distance2, light.positionRange.w);
    if (light.directionType.w == float(CANDELA_LIGHT_SPOT)) attenuation *= spotAttenuation(-l, light.directionType.xyz, light.cone);
    return l;
}

// Data shown as its value: the debug variants are paired with the linear tonemap at exposure 0,
// which sRGB-encodes, so the value is decoded here and reaches the 8-bit output as value × 255.
vec3 asData(vec3 value) { return srgbDecode(clamp(value, vec3(0.0f), vec3(1.0f))); }

// The GGX terms toward the first punctual light (black without one): D relative to its peak
// (D · π a², 1 where the half vector meets the normal), Smith's G (visibility × 4 N·L N·V), and
// Schlick's F.
vec3 termTowardFirstLight(vec3 n, vec3 v, vec3 baseColor, float metallic, float perceptualRoughness) {
    if (!kLights || push.counts.x == 0u) return vec3(0.0f);
    float attenuation;
    vec3 l = lightDirection(lights[0], attenuation);
    float NoL = dot(n, l);
    if (NoL <= 0.0f) return vec3(0.0f);
    float NoV = max(dot(n, v), CANDELA_MIN_NOV);
    vec3 h = normalize(v + l);
    float NoH = clamp(dot(n, h), 0.0f, 1.0f);
    float roughness = clampRoughness(perceptualRoughness);
    float a = roughness * roughness;
    vec3 NxH = cross(n, h);
    if (kDebugView == CANDELA_DEBUG_D) return vec3(distributionGgx(NoH, dot(NxH, NxH), a) * CANDELA_PI * a * a);
    if (kDebugView == CANDELA_DEBUG_G) return vec3(visibilitySmithGgxCorrelated(NoV, NoL, a) * 4.0f * NoL * NoV);
#ifdef CANDELA_MATERIAL_LAYERS
    if (hasLayer(CANDELA_LAYER_SPECULAR) || hasLayer(CANDELA_LAYER_IRIDESCENCE))
        return fresnelDielectricMetal(clamp(dot(v, h), 0.0f, 1.0f), baseColor, metallic, gDielectric);
#endif
    return fresnelSchlick(clamp(dot(v, h), 0.0f, 1.0f), mix(vec3(0.04f), baseColor, metallic));
}

void main() {
    MaterialData m = materials[draws[push.counts.y].material.x];
    vec4 baseColor = m.baseColorFactor * inColor * sampleSlot(baseColorTexture, CANDELA_TEX_BASE_COLOR);
    // The fraction of the pixel inside the cutoff's edge: alpha sharpened so that it crosses 0 → 1
    // over one pixel around the cutoff (Castaño 2010; Golus 2017), which alpha to coverage turns
    // into that many samples. Without MSAA the alpha test.
    float maskCoverage = 1.0f;
    if (kAlphaMask && kAlphaToCoverage) {
        maskCoverage = clamp((baseColor.a - m.alphaCutoff) / max(fwidth(baseColor.a), 1e-4f) + 0.5f, 0.0f, 1.0f);
        if (maskCoverage <= 0.0f) discard;
    } else if (kAlphaMask && baseColor.a < m.alphaCutoff) discard;
    float alpha = m.alphaMode == float(CANDELA_ALPHA_BLEND) ? baseColor.a : 1.0f;

    if (kUnlit && kDebugView == CANDELA_DEBUG_NONE) {
        outColor = vec4(baseColor.rgb * alpha, alpha * maskCoverage);
        return;
    }

    vec4 mr = sampleSlot(metallicRoughnessTexture, CANDELA_TEX_METALLIC_ROUGHNESS);
    float metallic = clamp(m.metallic * mr.b, 0.0f, 1.0f);
    float roughness = clamp(m.roughness * mr.g, 0.0f, 1.0f);
    float materialRoughness = roughness;  // before specular AA: the transmission and the roughness debug view
    vec3 n = shadingNormal(m, true);
    vec3 v = normalize(push.eye.xyz - inWorldPosition);
    if (kSpecularAa) {
        gNormalChange = normalChange();
        roughness = specularAntiAliasedRoughness(roughness, gNormalChange, gNormalMapLength);
    }
#ifdef CANDELA_MATERIAL_LAYERS
    MaterialLayerData layer = layers[draws[push.counts.y].material.x];
    gCoat = layerClearcoat(layer, facedNormal(), v);
    gDielectric = layerDielectric(layer, clamp(dot(n, v), CANDELA_MIN_NOV, 1.0f), baseColor.rgb,
                                  hasLayer(CANDELA_LAYER_CLEARCOAT) ? gCoat.weight : 0.0f);
    gSheen = layerSheen(layer, n, v);
    gAnisotropy = layerAnisotropy(layer, n);
    // The material's roughness: what lies behind a thin surface does not change with its curvature
    // across the pixel (specular AA widens the reflection only).
    gTransmission = layerTransmission(layer, materialRoughness);
    layerVolume(layer, n, v);
#endif

    BrdfLobes lit;
    lit.diffuse = vec3(0.0f);
    lit.specular = vec3(0.0f);
    vec3 reference = vec3(0.0f);
    if (kLights && !kUnlit) {
        for (uint i = 0u; i < push.counts.x; ++i) {
            LightData light = lights[i];
            float attenuation;
            vec3 l = lightDirection(light, attenuation);
            vec3 lt = l;
#ifdef CANDELA_MATERIAL_LAYERS
            // Through a volume, a point or spot light is seen from where the refracted ray leaves it.
            if (hasLayer(CANDELA_LAYER_VOLUME) && light.directionType.w != float(CANDELA_LIGHT_DIRECTIONAL)) {
                vec3 toLight = light.positionRange.xyz - (inWorldPosition + gVolumeRay);
                lt = dot(toLight, toLight) > 0.0f ? normalize(toLight) : l;
            }
#endif
            vec3 sheen;
            float coat;
            vec3 transmission;
            BrdfLobes lobes = surfaceLobes(n, v, l, lt, baseColor.rgb, metallic, roughness, sheen, coat, transmission);
            vec3 radiance = (light.color * light.intensity) * attenuation;
            lit.diffuse += lobes.diffuse * radiance;
            lit.specular += lobes.specular * radiance;
#ifdef CANDELA_MATERIAL_LAYERS
            gSheenLight += sheen * radiance;
            gCoatLight += coat * radiance;
            gTransmissionLight += transmission * radiance * gVolumeTransmittance;
#endif
        }
    }
    if (kIbl && !kUnlit) {
        if (kReferenceSamples > 0u) {
            reference = referenceImageBasedLight(n, v, baseColor.rgb, metallic, roughness);
        } else {
            BrdfLobes environment = imageBasedLight(m, n, v, baseColor.rgb, metallic, roughness);
            lit.diffuse += environment.diffuse;
            lit.specular += environment.specular;
        }
    }
    vec3 emissive = m.emissive.rgb * sampleSlot(emissiveTexture, CANDELA_TEX_EMISSIVE).rgb;
    vec3 coatLight = vec3(0.0f);
    vec3 sheenLight = vec3(0.0f);
#ifdef CANDELA_MATERIAL_LAYERS
    vec3 transmissionLight = vec3(0.0f);
    vec3 throughput = vec3(0.0f);  // the fraction of the light behind that comes through
    float backgroundAlpha = 1.0f;
    // The emission lies beneath the coat too.
    if (hasLayer(CANDELA_LAYER_CLEARCOAT)) emissive *= gCoat.baseWeight;
    coatLight = gCoatLight;
    sheenLight = gSheenLight;
    if (hasLayer(CANDELA_LAYER_TRANSMISSION)) {
        // The light from behind, through the part of the surface the reflections leave: with an
        // environment the split sum's (A, B) weigh it as they weigh the Lambert part, without one
        // Karis's analytic fit of them.
        float NoV = clamp(dot(n, v), CANDELA_MIN_NOV, 1.0f);
        vec2 lut = kIbl ? splitSumAt(NoV, roughness) : envBrdfApproximation(NoV, roughness);
        throughput = iblTransmission(gTransmission, vec3(1.0f), lut, baseColor.rgb, metallic, gDielectric, kMultiscatter) *
                     gVolumeTransmittance * (hasLayer(CANDELA_LAYER_SHEEN) ? gSheen.baseWeight : 1.0f) *
                     (hasLayer(CANDELA_LAYER_CLEARCOAT) ? gCoat.baseWeight : 1.0f);
        vec4 behind = transmittedBackground();
        backgroundAlpha = behind.a;
        transmissionLight = gTransmissionLight + throughput * behind.rgb;
    }
#endif

    if (kDebugView != CANDELA_DEBUG_NONE) {
        vec3 value = vec3(0.0f);
        if (kDebugView == CANDELA_DEBUG_BASE_COLOR) value = baseColor.rgb;
        else if (kDebugView == CANDELA_DEBUG_GEOMETRIC_NORMAL) value = asData(shadingNormal(m, false) * 0.5f + 0.5f);
        else if (kDebugView == CANDELA_DEBUG_MAPPED_NORMAL) value = asData(n * 0.5f + 0.5f);
        else if (kDebugView == CANDELA_DEBUG_ROUGHNESS) value = asData(vec3(materialRoughness));
        else if (kDebugView == CANDELA_DEBUG_METALLIC) value = asData(vec3(metallic));
        else if (kDebugView == CANDELA_DEBUG_OCCLUSION) value = asData(vec3(occlusion(m)));
        else if (kDebugView == CANDELA_DEBUG_EMISSIVE) value = emissive;
        else if (kDebugView == CANDELA_DEBUG_DIFFUSE) value = lit.diffuse;
        else if (kDebugView == CANDELA_DEBUG_SPECULAR) value = lit.specular;
        else if (kDebugView == CANDELA_DEBUG_CLEARCOAT) value = coatLight;
        else if (kDebugView == CANDELA_DEBUG_SHEEN) value = sheenLight;
        else if (kDebugView == CANDELA_DEBUG_TRANSMISSION) {
#ifdef CANDELA_MATERIAL_LAYERS
            value = asData(throughput);
#endif
        }
        else if (kDebugView == CANDELA_DEBUG_IRIDESCENCE_THICKNESS || kDebugView == CANDELA_DEBUG_IRIDESCENCE_FRESNEL) {
#ifdef CANDELA_MATERIAL_LAYERS
            // The film's thickness in µm as grey (1 µm white), and the Fresnel it gives at N·V (the
            // material's, dielectric and metal mixed, with the film at its weight); black without a film.
            if (hasLayer(CANDELA_LAYER_IRIDESCENCE) && gDielectric.film > 0.0f) {
                if (kDebugView == CANDELA_DEBUG_IRIDESCENCE_THICKNESS) value = asData(vec3(gFilmThickness * 1e-3f));
                else value = asData(fresnelDielectricMetal(clamp(dot(n, v), 0.0f, 1.0f), baseColor.rgb, metallic, gDielectric));
            }
#endif
        }
        else if (kDebugView == CANDELA_DEBUG_ANISOTROPY) {
#ifdef CANDELA_MATERIAL_LAYERS
            // T as n·0.5+0.5, scaled by the strength; black without anisotropy.
            if (hasLayer(CANDELA_LAYER_ANISOTROPY)) value = asData((gAnisotropy.t * 0.5f + 0.5f) * gAnisotropy.strength);
#endif
        }
        else if (kDebugView == CANDELA_DEBUG_CLEARCOAT_NORMAL) {
#ifdef CANDELA_MATERIAL_LAYERS
            if (hasLayer(CANDELA_LAYER_CLEARCOAT)) value = asData(gCoat.normal * 0.5f + 0.5f);  // black without a coat
#endif
        }
        else value = asData(termTowardFirstLight(n, v, baseColor.rgb, metallic, roughness));
        outColor = vec4(min(value, vec3(60000.0f)) * alpha, alpha * maskCoverage);
        return;
    }

    vec3 color = lit.diffuse + lit.specular + sheenLight + coatLight + reference + emissive;
#ifdef CANDELA_MATERIAL_LAYERS
    color += transmissionLight;
    // Where the background behind a transmitting surface is uncovered (a transparent background),
    // the part of it that comes through stays uncovered: coverage 1 − mean(throughput) · (1 − its alpha).
    float coverage = alpha * (1.0f - (throughput.r + throughput.g + throughput.b) * (1.0f / 3.0f) * (1.0f - backgroundAlpha));
#else
    float coverage = alpha;
#endif
    // Radiance can exceed half-float range with extreme lights: keep it finite.
    color = min(color, vec3(60000.0f));
    outColor = vec4(color * alpha, coverage * maskCoverage);
}
