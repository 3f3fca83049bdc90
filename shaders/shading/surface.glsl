// The two ends of material evaluation (shading/material_eval.glsl): SurfaceInputs, what a material
// is evaluated from at one surface point, and Surface, everything the evaluation produces and the
// lighting (shading/lighting.glsl) reads. The fragment stage fills SurfaceInputs from its
// interpolants and derivatives (forward.frag.glsl), the visibility path's compute shading from
// the triangle it fetches (visibility_shade.comp.glsl).
#ifndef CANDELA_FORWARD_SURFACE_GLSL
#define CANDELA_FORWARD_SURFACE_GLSL

#include "shared/scene_data.h"
#ifdef CANDELA_MATERIAL_LAYERS
#include "shared/brdf_layers.h"
#endif

struct SurfaceInputs {
    uint draw;           // index into Draws: the primitive's world matrix and material
    vec3 eye;            // the viewer's position (world)
    vec3 position;       // world
    vec3 normal;         // the interpolated vertex normal, any length (zero where it degenerates)
    vec4 tangent;        // the interpolated tangent (xyz, any length) and the bitangent's sign (w)
    vec3 faceNormal;     // the triangle's unit normal, either orientation
    bool frontFacing;    // the triangle's front faces the viewer
    vec4 color;          // COLOR_0
    // |∂n/∂x|² + |∂n/∂y|² of the faced normal across the pixel (specular AA; 0 without it).
    float normalChange;
    vec2 uv[CANDELA_TEX_COUNT];  // per core texture slot, after KHR_texture_transform
#ifdef CANDELA_MATERIAL_LAYERS
    vec2 layerUv[CANDELA_LAYER_TEX_COUNT];  // per layer texture slot, likewise
#endif
#ifdef CANDELA_VISIBILITY_SHADING
    // Compute shading has no implicit derivatives: each slot's coordinates one pixel to the right
    // and one below, minus its own (visibility_shade.comp.glsl computes them analytically).
    vec2 uvDx[CANDELA_TEX_COUNT], uvDy[CANDELA_TEX_COUNT];
#ifdef CANDELA_MATERIAL_LAYERS
    vec2 layerUvDx[CANDELA_LAYER_TEX_COUNT], layerUvDy[CANDELA_LAYER_TEX_COUNT];
#endif
#endif
};

#ifdef CANDELA_MATERIAL_LAYERS
// KHR_materials_iridescence's thin film at this point: its weight (0 … 1), IOR and thickness in nm
// (0: no film).
struct Iridescence {
    float weight;
    float ior;
    float thickness;
};

// KHR_materials_volume beneath a transmitting surface: the ray refracted through its thickness
// (world units; zero when thin-walled) and the transmittance along it (every ray is as long as the
// thickness, so one transmittance serves all). With KHR_materials_dispersion the red and blue
// channels' rays besides (refracted at their own IORs; `ray` is the green's, at the material's).
struct Volume {
    vec3 ray;
    vec3 transmittance;
    vec3 redRay;
    vec3 blueRay;
};

// The layers of one surface point (each as shared/brdf_*.h defines it; a layer the variant does
// not evaluate holds its neutral value).
struct SurfaceLayers {
    // The dielectric Fresnel: the core's f0 0.04 and f90 1, or the specular layer's, with the thin
    // film at N·V mixed in (seen from the coat's IOR under a coat).
    DielectricFresnel dielectric;
    Iridescence film;
    Clearcoat coat;
    Sheen sheen;
    Anisotropy anisotropy;
    Transmission transmission;
    DiffuseTransmission diffuseTransmission;
    Volume volume;
};
#endif

struct Surface {
    vec3 position;            // world
    vec3 v;                   // unit, toward the viewer
    vec3 facedNormal;         // the interpolated normal on the viewer's side (no normal map)
    vec3 normal;              // the shading normal: facedNormal after the normal map
    vec3 baseColor;           // linear: factor × COLOR_0 × texture
    float metallic;
    float roughness;          // perceptual, as the lobes use it (widened by specular AA when on)
    float materialRoughness;  // perceptual, the material's own (before specular AA)
    vec3 f0;                  // the core's Fresnel at normal incidence, mix(0.04, baseColor, metallic); F90 1
    float ior;                // 1.5 (the core's), or KHR_materials_ior's
    float occlusion;          // 1 + strength · (texture − 1): for indirect light only
    vec3 emissive;            // factor × strength × texture, before any coat over it
#ifdef CANDELA_MATERIAL_LAYERS
    SurfaceLayers layers;
#endif
};

#endif
