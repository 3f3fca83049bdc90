// Material evaluation of the forward programs: the glTF material (and, in the layered program,
// each KHR_materials_* layer) at one surface point, SurfaceInputs → Surface (shading/surface.glsl).
// Nothing here reads a stage input or a derivative: the caller passes them in SurfaceInputs, and
// defines, before including this file, how a material texture is read —
//     CANDELA_CORE_TEXTURE(inputs, field, slot)   core texture slot `slot` (CANDELA_TEX_*), whose
//                                                 sampler is field##Texture in the forward programs
//     CANDELA_LAYER_TEXTURE(inputs, field, slot)  layer texture slot `slot` (CANDELA_LAYER_TEX_*)
// each a vec4 (the fragment stage: texture() of the slot's sampler, with its implicit derivatives;
// the visibility path's compute shading: textureGrad() with the gradients it computed). Branches are on specialization constants only, so a sample inside one keeps its
// derivatives and what a variant does not use is compiled out.
#ifndef CANDELA_FORWARD_MATERIAL_EVAL_GLSL
#define CANDELA_FORWARD_MATERIAL_EVAL_GLSL

#include "shading/resources.glsl"
#include "shading/surface.glsl"

// The interpolated normal flipped for back faces of double-sided materials (or, where it
// degenerates, the face normal on the viewer's side).
vec3 facedNormal(SurfaceInputs inputs) {
    // The sign of the face normal from position derivatives depends on the framebuffer's y
    // direction, not on the winding: orient it toward the eye explicitly.
    vec3 faceNormal = inputs.faceNormal;
    if (dot(faceNormal, inputs.eye - inputs.position) < 0.0f) faceNormal = -faceNormal;
    vec3 n = faceNormal;
    if (dot(inputs.normal, inputs.normal) > 1e-12f) n = inputs.frontFacing ? normalize(inputs.normal) : -normalize(inputs.normal);
    return n;
}

// Unit normal `n` perturbed by a tangent-space normal-map value (texel · 2 − 1) with the map's
// scale, in the frame of `tangent`; `n` itself where that frame degenerates.
vec3 mapNormal(vec3 n, vec4 tangent, vec3 tangentNormal, float scale) {
    vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
    // Relative to the tangent's own length, which scales with the draw's transform: an absolute
    // threshold let the rounding residual of a tangent along the normal through at scale 1e4
    // (an arbitrary tangent frame) and would drop valid tangents of scenes scaled by 1e-6.
    if (dot(t, t) <= 1e-6f * dot(tangent.xyz, tangent.xyz)) return n;
    t = normalize(t);
    vec3 b = cross(n, t) * (tangent.w < 0.0f ? -1.0f : 1.0f);
    tangentNormal.xy *= scale;
    vec3 mapped = mat3(t, b, n) * tangentNormal;
    return dot(mapped, mapped) > 1e-12f ? normalize(mapped) : n;
}

MaterialData materialOf(SurfaceInputs inputs) { return materials[draws[inputs.draw].material.x]; }

// Base colour and alpha: factor × COLOR_0 × texture (linear). Apart from evaluateMaterial, so that
// the alpha test can come first.
vec4 materialBaseColor(SurfaceInputs inputs) {
    return materialOf(inputs).baseColorFactor * inputs.color *
           CANDELA_CORE_TEXTURE(inputs, baseColor, CANDELA_TEX_BASE_COLOR);
}

#ifdef CANDELA_MATERIAL_LAYERS
MaterialLayerData materialLayersOf(SurfaceInputs inputs) { return layers[draws[inputs.draw].material.x]; }

// KHR_materials_ior and KHR_materials_specular: the dielectric Fresnel (the core's without the
// specular layer).
DielectricFresnel evaluateSpecular(MaterialLayerData layer, SurfaceInputs inputs) {
    if (!hasLayer(CANDELA_LAYER_SPECULAR)) return coreDielectricFresnel();
    float specular = layer.specular * CANDELA_LAYER_TEXTURE(inputs, specular, CANDELA_LAYER_TEX_SPECULAR).a;
    vec3 color = layer.specularColor * CANDELA_LAYER_TEXTURE(inputs, specularColor, CANDELA_LAYER_TEX_SPECULAR_COLOR).rgb;
    return dielectricFresnel(layer.ior, color, specular);
}

// KHR_materials_iridescence: the film's weight, IOR (at least 1) and thickness (the maximum
// without a texture).
Iridescence evaluateIridescence(MaterialLayerData layer, SurfaceInputs inputs) {
    Iridescence film;
    film.weight = 0.0f;
    film.ior = 1.0f;
    film.thickness = 0.0f;
    if (!hasLayer(CANDELA_LAYER_IRIDESCENCE)) return film;
    film.weight = clamp(layer.iridescence * CANDELA_LAYER_TEXTURE(inputs, iridescence, CANDELA_LAYER_TEX_IRIDESCENCE).r, 0.0f, 1.0f);
    float g = CANDELA_LAYER_TEXTURE(inputs, iridescenceThickness, CANDELA_LAYER_TEX_IRIDESCENCE_THICKNESS).g;
    film.thickness = max(mix(layer.iridescenceThicknessMinimum, layer.iridescenceThicknessMaximum, g), 0.0f);
    film.ior = max(layer.iridescenceIor, 1.0f);
    return film;
}

// KHR_materials_clearcoat on the faced normal `faced` (its own normal map, if any; not the
// material's), seen from `v`.
Clearcoat evaluateClearcoat(MaterialLayerData layer, SurfaceInputs inputs, vec3 faced, vec3 v) {
    if (!hasLayer(CANDELA_LAYER_CLEARCOAT)) return clearcoatLayer(0.0f, 0.0f, faced, v);
    float weight = layer.clearcoat * CANDELA_LAYER_TEXTURE(inputs, clearcoat, CANDELA_LAYER_TEX_CLEARCOAT).r;
    float roughness =
        layer.clearcoatRoughness * CANDELA_LAYER_TEXTURE(inputs, clearcoatRoughness, CANDELA_LAYER_TEX_CLEARCOAT_ROUGHNESS).g;
    vec3 nc = faced;
    float mapLength = 1.0f;
    if (hasLayer(CANDELA_LAYER_CLEARCOAT_NORMAL)) {
        vec4 texel = CANDELA_LAYER_TEXTURE(inputs, clearcoatNormal, CANDELA_LAYER_TEX_CLEARCOAT_NORMAL);
        nc = mapNormal(faced, inputs.tangent, texel.xyz * 2.0f - 1.0f, layer.clearcoatNormalScale);
        mapLength = texel.a;
    }
    if (kSpecularAa) roughness = specularAntiAliasedRoughness(clamp(roughness, 0.0f, 1.0f), inputs.normalChange, mapLength);
    return clearcoatLayer(clamp(weight, 0.0f, 1.0f), clamp(roughness, 0.0f, 1.0f), nc, v);
}

// KHR_materials_anisotropy on shading normal `n`: direction (the texture's RG, or the tangent)
// rotated by anisotropyRotation in the tangent plane, strength anisotropyStrength × the texture's
// B. None where the tangent frame degenerates.
Anisotropy evaluateAnisotropy(MaterialLayerData layer, SurfaceInputs inputs, vec3 n) {
    Anisotropy none = anisotropyLayer(0.0f, vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f));
    if (!hasLayer(CANDELA_LAYER_ANISOTROPY)) return none;
    vec3 texel = CANDELA_LAYER_TEXTURE(inputs, anisotropy, CANDELA_LAYER_TEX_ANISOTROPY).rgb;
    bool textured = layer.anisotropyTextured > 0.5f;
    vec2 direction = textured ? texel.rg * 2.0f - 1.0f : vec2(1.0f, 0.0f);
    float strength = clamp(layer.anisotropy * (textured ? texel.b : 1.0f), 0.0f, 1.0f);
    float c = cos(layer.anisotropyRotation), s = sin(layer.anisotropyRotation);
    direction = vec2(c * direction.x - s * direction.y, s * direction.x + c * direction.y);
    vec3 t = inputs.tangent.xyz - n * dot(n, inputs.tangent.xyz);
    if (dot(t, t) <= 1e-6f * dot(inputs.tangent.xyz, inputs.tangent.xyz) || dot(direction, direction) < 1e-12f) return none;
    t = normalize(t);
    vec3 b = cross(n, t) * (inputs.tangent.w < 0.0f ? -1.0f : 1.0f);
    vec3 along = normalize(t * direction.x + b * direction.y);
    return anisotropyLayer(strength, along, cross(n, along));
}

// KHR_materials_transmission: its weight and BTDF roughness (the material's `roughness`, scaled by
// the IOR).
Transmission evaluateTransmission(MaterialLayerData layer, SurfaceInputs inputs, float roughness) {
    if (!hasLayer(CANDELA_LAYER_TRANSMISSION)) return transmissionLayer(0.0f, 0.0f, 1.5f);
    float weight = layer.transmission * CANDELA_LAYER_TEXTURE(inputs, transmission, CANDELA_LAYER_TEX_TRANSMISSION).r;
    return transmissionLayer(clamp(weight, 0.0f, 1.0f), roughness, layer.ior);
}

// KHR_materials_diffuse_transmission: its weight (factor × texture A) and colour (factor × texture
// RGB, sRGB).
DiffuseTransmission evaluateDiffuseTransmission(MaterialLayerData layer, SurfaceInputs inputs) {
    if (!hasLayer(CANDELA_LAYER_DIFFUSE_TRANSMISSION)) return diffuseTransmissionLayer(0.0f, vec3(0.0f));
    float weight = layer.diffuseTransmission * CANDELA_LAYER_TEXTURE(inputs, diffuseTransmission, CANDELA_LAYER_TEX_DIFFUSE_TRANSMISSION).a;
    vec3 color = layer.diffuseTransmissionColor *
                 CANDELA_LAYER_TEXTURE(inputs, diffuseTransmissionColor, CANDELA_LAYER_TEX_DIFFUSE_TRANSMISSION_COLOR).rgb;
    return diffuseTransmissionLayer(clamp(weight, 0.0f, 1.0f), max(color, vec3(0.0f)));
}

// KHR_materials_volume on shading normal `n`: V refracted into it (an IOR below 1 taken as 1)
// across its thickness — thicknessFactor × texture (G) in the mesh's units, scaled by the draw's
// world transform (the mean of its axes' scales) — and the transmittance along that ray; with
// KHR_materials_dispersion the red and blue rays too, at their IORs (dispersionIors). Beneath a
// diffuse transmission alone nothing refracts: the transmittance along the thickness, no ray.
Volume evaluateVolume(MaterialLayerData layer, SurfaceInputs inputs, vec3 n, vec3 v) {
    Volume volume;
    volume.ray = vec3(0.0f);
    volume.transmittance = vec3(1.0f);
    volume.redRay = vec3(0.0f);
    volume.blueRay = vec3(0.0f);
    if (!hasLayer(CANDELA_LAYER_VOLUME)) return volume;
    float thickness = layer.thickness * CANDELA_LAYER_TEXTURE(inputs, thickness, CANDELA_LAYER_TEX_THICKNESS).g;
    mat4 world = draws[inputs.draw].world;
    float scale = (length(world[0].xyz) + length(world[1].xyz) + length(world[2].xyz)) * (1.0f / 3.0f);
    float rayLength = max(thickness, 0.0f) * scale;
    if (!hasLayer(CANDELA_LAYER_TRANSMISSION)) {
        volume.transmittance = volumeTransmittance(layer.attenuationColor, layer.attenuationDistance, rayLength);
        return volume;
    }
    volume.ray = refractedDirection(v, n, layer.ior) * rayLength;
    volume.transmittance = volumeTransmittance(layer.attenuationColor, layer.attenuationDistance, length(volume.ray));
    if (hasLayer(CANDELA_LAYER_DISPERSION)) {
        vec3 iors = dispersionIors(layer.ior, layer.dispersion);
        volume.redRay = refractedDirection(v, n, iors.r) * rayLength;
        volume.blueRay = refractedDirection(v, n, iors.b) * rayLength;
    }
    return volume;
}

// KHR_materials_sheen on shading normal `n`, with its albedo E(N·V) from the LUT.
Sheen evaluateSheen(MaterialLayerData layer, SurfaceInputs inputs, vec3 n, vec3 v) {
    if (!hasLayer(CANDELA_LAYER_SHEEN)) return sheenLayer(vec3(0.0f), 0.0f, 0.0f);
    vec3 color = layer.sheenColor * CANDELA_LAYER_TEXTURE(inputs, sheenColor, CANDELA_LAYER_TEX_SHEEN_COLOR).rgb;
    float roughness = clamp(
        layer.sheenRoughness * CANDELA_LAYER_TEXTURE(inputs, sheenRoughness, CANDELA_LAYER_TEX_SHEEN_ROUGHNESS).a, 0.0f, 1.0f);
    float NoV = clamp(dot(n, v), CANDELA_MIN_NOV, 1.0f);
    float albedo = textureLod(sheenLut, brdfLutUv(NoV, roughness, float(textureSize(sheenLut, 0).x)), 0.0f).r;
    return sheenLayer(color, roughness, albedo);
}

// The layers of surface `s` (its core part evaluated).
SurfaceLayers evaluateLayers(SurfaceInputs inputs, Surface s) {
    MaterialLayerData layer = materialLayersOf(inputs);
    SurfaceLayers l;
    l.coat = evaluateClearcoat(layer, inputs, s.facedNormal, s.v);
    l.film = evaluateIridescence(layer, inputs);
    l.dielectric = evaluateSpecular(layer, inputs);
    // The film sits beneath the coat when there is one: seen from the coat's IOR, 1.5.
    if (hasLayer(CANDELA_LAYER_IRIDESCENCE))
        l.dielectric = withThinFilm(l.dielectric, l.film.weight, l.film.ior, l.film.thickness,
                                    1.0f + 0.5f * (hasLayer(CANDELA_LAYER_CLEARCOAT) ? l.coat.weight : 0.0f),
                                    clamp(dot(s.normal, s.v), CANDELA_MIN_NOV, 1.0f), s.baseColor);
    l.sheen = evaluateSheen(layer, inputs, s.normal, s.v);
    l.anisotropy = evaluateAnisotropy(layer, inputs, s.normal);
    // The material's roughness: what lies behind a thin surface does not change with its curvature
    // across the pixel (specular AA widens the reflection only).
    l.transmission = evaluateTransmission(layer, inputs, s.materialRoughness);
    l.diffuseTransmission = evaluateDiffuseTransmission(layer, inputs);
    l.volume = evaluateVolume(layer, inputs, s.normal, s.v);
    return l;
}
#endif

// The material at `inputs` with base colour `baseColor` (materialBaseColor's rgb).
Surface evaluateMaterial(SurfaceInputs inputs, vec3 baseColor) {
    MaterialData m = materialOf(inputs);
    Surface s;
    s.position = inputs.position;
    s.v = normalize(inputs.eye - inputs.position);
    s.baseColor = baseColor;
    vec4 mr = CANDELA_CORE_TEXTURE(inputs, metallicRoughness, CANDELA_TEX_METALLIC_ROUGHNESS);
    s.metallic = clamp(m.metallic * mr.b, 0.0f, 1.0f);
    s.materialRoughness = clamp(m.roughness * mr.g, 0.0f, 1.0f);
    s.facedNormal = facedNormal(inputs);
    s.normal = s.facedNormal;
    // The length of the mean normal the normal map's filtered texel stands for (its A: 1 at mip 0,
    // less where a mip averaged diverging normals; geometry/normal_map_mips.h).
    float normalMapLength = 1.0f;
    if (kNormalMap) {
        vec4 texel = CANDELA_CORE_TEXTURE(inputs, normal, CANDELA_TEX_NORMAL);
        s.normal = mapNormal(s.facedNormal, inputs.tangent, texel.xyz * 2.0f - 1.0f, m.normalScale);
        normalMapLength = texel.a;
    }
    s.roughness = s.materialRoughness;
    if (kSpecularAa) s.roughness = specularAntiAliasedRoughness(s.materialRoughness, inputs.normalChange, normalMapLength);
    s.f0 = mix(vec3(0.04f), baseColor, s.metallic);
    s.occlusion = 1.0f + m.occlusionStrength * (CANDELA_CORE_TEXTURE(inputs, occlusion, CANDELA_TEX_OCCLUSION).r - 1.0f);
    s.emissive = m.emissive.rgb * CANDELA_CORE_TEXTURE(inputs, emissive, CANDELA_TEX_EMISSIVE).rgb;
#ifdef CANDELA_MATERIAL_LAYERS
    s.ior = materialLayersOf(inputs).ior;
    s.layers = evaluateLayers(inputs, s);
#else
    s.ior = 1.5f;
#endif
    return s;
}

#endif
