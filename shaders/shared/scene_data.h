// GPU-side scene structures shared by forward.*.glsl and the C++ upload (std430 storage buffers
// and push constants; members are grouped in 16-byte vec4/uvec4/mat4 units — a vec3 followed by a
// float, or four floats — so the GLSL layout and the C++ struct agree without padding rules).
// The /*Color*/, /*Range(MIN, MAX)*/ and /*Ignore*/ comments are UI annotations: the viewer's
// parameter panels are generated from the SPIR-V reflection of these structs (shader/annotations.h).
#ifndef CANDELA_SHARED_SCENE_DATA_H
#define CANDELA_SHARED_SCENE_DATA_H

#include "shared/compat.h"
#include "shared/shading_tables.h"
#include "shared/ibl.h"

CANDELA_NAMESPACE_BEGIN

#define CANDELA_LIGHT_DIRECTIONAL 0u
#define CANDELA_LIGHT_POINT 1u
#define CANDELA_LIGHT_SPOT 2u

#define CANDELA_ALPHA_OPAQUE 0u
#define CANDELA_ALPHA_MASK 1u
#define CANDELA_ALPHA_BLEND 2u
// An ID the per-pixel outputs give where there is none: no glTF node, mesh or instance, no surface.
#define CANDELA_NO_ID 0xFFFFFFFFu

// One punctual light (KHR_lights_punctual), world space.
struct LightData {
    /*Ignore*/ vec4 positionRange;   // xyz position, w range (0 = infinite)
    /*Ignore*/ vec4 directionType;   // xyz unit direction the light travels, w type (CANDELA_LIGHT_*)
    /*Color*/ vec3 color;            // linear RGB
    /*Range(0, 1000)*/ float intensity;  // candela (point, spot) or lux (directional)
    /*Ignore*/ vec4 cone;            // x = 1/max(cos inner − cos outer, 1e-4), y = −cos outer × x (spot)
};

// One drawn primitive instance.
struct DrawData {
    mat4 world;
    mat4 normalMatrix;  // inverse transpose of world's upper 3×3 (as a mat4)
    uvec4 material;     // x: index into the material array
    // The per-pixel outputs' IDs (docs/outputs.md): the glTF node, mesh, primitive within the
    // mesh, and the EXT_mesh_gpu_instancing instance; CANDELA_NO_ID where there is none.
    uvec4 ids;
};

// KHR_texture_transform of one texture slot as a 2×3 matrix: uv' = (dot(r0.xy, uv) + r0.z,
// dot(r1.xy, uv) + r1.z); r0.w = texCoord set (0 or 1).
struct UvTransform {
    vec4 r0;
    vec4 r1;
};

struct MaterialData {
    /*Color*/ vec4 baseColorFactor;  // linear RGBA
    /*Color*/ vec4 emissive;         // rgb = emissiveFactor × emissiveStrength, w unused
    /*Range(0, 1)*/ float metallic;
    /*Range(0, 1)*/ float roughness;
    /*Range(0, 2)*/ float normalScale;
    /*Range(0, 1)*/ float occlusionStrength;
    /*Range(0, 1)*/ float alphaCutoff;
    /*Ignore*/ float alphaMode;      // CANDELA_ALPHA_* as float
    /*Ignore*/ float pad0;
    /*Ignore*/ float pad1;
    /*Ignore*/ UvTransform uv[CANDELA_TEX_COUNT];
};

// A material's layer parameters (the layered program's MaterialLayers buffer, one per material;
// read only for the layers the material uses).
struct MaterialLayerData {
    /*Color*/ vec3 specularColor;      // KHR_materials_specular specularColorFactor (may exceed 1)
    /*Range(0, 1)*/ float specular;    // specularFactor
    /*Range(0, 3)*/ float ior;         // KHR_materials_ior (0: f0 = specularColor, see shared/brdf_layers.h)
    /*Range(0, 1)*/ float clearcoat;   // KHR_materials_clearcoat clearcoatFactor
    /*Range(0, 1)*/ float clearcoatRoughness;  // clearcoatRoughnessFactor
    /*Range(0, 2)*/ float clearcoatNormalScale;  // clearcoatNormalTexture.scale
    /*Color*/ vec3 sheenColor;         // KHR_materials_sheen sheenColorFactor (linear)
    /*Range(0, 1)*/ float sheenRoughness;  // sheenRoughnessFactor
    /*Range(0, 1)*/ float anisotropy;  // KHR_materials_anisotropy anisotropyStrength
    /*Range(-3.2, 3.2)*/ float anisotropyRotation;  // radians, counter-clockwise from the tangent
    /*Ignore*/ float anisotropyTextured;  // 1: anisotropyTexture gives direction (RG) and strength (B)
    /*Range(0, 1)*/ float transmission;  // KHR_materials_transmission transmissionFactor
    /*Color*/ vec3 attenuationColor;   // KHR_materials_volume attenuationColor
    /*Range(0, 10)*/ float thickness;  // thicknessFactor (mesh units; 0: thin-walled)
    /*Range(0, 10)*/ float attenuationDistance;  // world units; 0: infinite (no absorption)
    /*Range(0, 1)*/ float iridescence;           // KHR_materials_iridescence iridescenceFactor
    /*Range(1, 3)*/ float iridescenceIor;        // the film's IOR
    /*Range(0, 1200)*/ float iridescenceThicknessMinimum;  // nm (iridescenceThicknessTexture.g = 0)
    /*Range(0, 1200)*/ float iridescenceThicknessMaximum;  // nm (texture 1, or no texture)
    /*Range(0, 3)*/ float dispersion;            // KHR_materials_dispersion: 20 / Abbe number (0: none)
    /*Ignore*/ float pad0;
    /*Ignore*/ float pad1;
    /*Color*/ vec3 diffuseTransmissionColor;     // KHR_materials_diffuse_transmission diffuseTransmissionColorFactor
    /*Range(0, 1)*/ float diffuseTransmission;   // diffuseTransmissionFactor
    /*Ignore*/ UvTransform uv[CANDELA_LAYER_TEX_COUNT];
};

// Push constants of every program that draws or shades the scene (the forward programs, the
// visibility raster and shading): the view, which draw or dispatch this is and the environment
// lookup (128 bytes: exactly what every device guarantees).
struct FramePush {
    /*Ignore*/ mat4 viewProjection;
    /*Ignore*/ vec4 eye;     // xyz: camera position (world)
    /*Ignore*/ uvec4 counts; // x: light count, y: draw index, z: the visibility shading's dispatch, w: unused
    IblParams ibl;
};

// Applies a texture slot's transform to the vertex's texture coordinate sets.
CANDELA_FN vec2 transformUv(UvTransform t, vec2 uv0, vec2 uv1) {
    vec2 uv = t.r0.w > 0.5f ? uv1 : uv0;
    return vec2(dot(vec2(t.r0.x, t.r0.y), uv) + t.r0.z, dot(vec2(t.r1.x, t.r1.y), uv) + t.r1.z);
}

// KHR_lights_punctual range attenuation: smooth window to 0 at `range` (0 = none), times 1/d².
CANDELA_FN float rangeAttenuation(float distance2, float range) {
    float inverseSquare = 1.0f / max(distance2, 1e-8f);
    if (range <= 0.0f) return inverseSquare;
    float ratio = distance2 / (range * range);
    float window = clamp(1.0f - ratio * ratio, 0.0f, 1.0f);
    return window * window * inverseSquare;
}

// KHR_lights_punctual spot cone falloff (smoothstep-like as in the specification's sample code).
CANDELA_FN float spotAttenuation(vec3 lightToSurface, vec3 spotDirection, vec4 cone) {
    float cd = dot(spotDirection, lightToSurface);
    float attenuation = clamp(cd * cone.x + cone.y, 0.0f, 1.0f);
    return attenuation * attenuation;
}

CANDELA_NAMESPACE_END

#ifdef __cplusplus
static_assert(sizeof(candela::shading::LightData) == 64);
static_assert(sizeof(candela::shading::DrawData) == 160);
static_assert(sizeof(candela::shading::MaterialData) == 64 + 32 * CANDELA_TEX_COUNT);
static_assert(sizeof(candela::shading::MaterialLayerData) == 128 + 32 * CANDELA_LAYER_TEX_COUNT);
static_assert(sizeof(candela::shading::FramePush) == 128);
#endif

#endif
