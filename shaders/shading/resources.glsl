// What the forward programs read besides their stage inputs: specialization constants, descriptor
// sets 0–3 and push constants. Included by the fragment stage (forward.frag.glsl) and, through
// it, by the material evaluation and lighting it calls (shading/material_eval.glsl,
// shading/lighting.glsl) — a compute shader that calls those includes this file too.
#ifndef CANDELA_FORWARD_RESOURCES_GLSL
#define CANDELA_FORWARD_RESOURCES_GLSL

#include "shared/brdf.h"
#include "shading/scene_buffers.glsl"
#include "shared/specialization_ids.h"

layout(constant_id = CANDELA_SPEC_NORMAL_MAP) const bool kNormalMap = false;
layout(constant_id = CANDELA_SPEC_LIGHTS) const bool kLights = true;
layout(constant_id = CANDELA_SPEC_UNLIT) const bool kUnlit = false;
layout(constant_id = CANDELA_SPEC_ALPHA_MASK) const bool kAlphaMask = false;
layout(constant_id = CANDELA_SPEC_SHADING_MODEL) const uint kShadingModel = CANDELA_SHADING_PBR;
layout(constant_id = CANDELA_SPEC_IBL) const bool kIbl = false;
layout(constant_id = CANDELA_SPEC_IRRADIANCE_SH) const bool kIrradianceSh = true;  // else the irradiance cube
layout(constant_id = CANDELA_SPEC_MULTISCATTER) const bool kMultiscatter = true;
// CANDELA_SPEC_REFERENCE_SAMPLES is the ground truth's (shading/reference_ibl.glsl: its program only).
// A debug view (CANDELA_DEBUG_*) instead of the shaded colour.
layout(constant_id = CANDELA_SPEC_DEBUG_VIEW) const uint kDebugView = CANDELA_DEBUG_NONE;
#ifdef CANDELA_MATERIAL_LAYERS
// The layers this variant evaluates (CANDELA_LAYER_* bits): a material pays only for its own.
layout(constant_id = CANDELA_SPEC_LAYERS) const uint kLayers = 0u;
#endif
// Specular anti-aliasing: roughness widened by the normal's change across the pixel and by what the
// normal map's mip averaged away (specularAntiAliasedRoughness, shared/brdf.h).
layout(constant_id = CANDELA_SPEC_SPECULAR_AA) const bool kSpecularAa = false;
// Alpha to coverage (MSAA, alpha-masked materials): the pipeline turns the output alpha into the
// sample coverage (and stores alpha 1: alphaToOne) instead of the alpha test's all-or-nothing.
layout(constant_id = CANDELA_SPEC_ALPHA_TO_COVERAGE) const bool kAlphaToCoverage = false;
// The punctual light types the frame has (bit 1 << CANDELA_LIGHT_*): the code of the others is
// compiled out of the light loop (llvmpipe pays for untaken branches).
layout(constant_id = CANDELA_SPEC_LIGHT_TYPES) const uint kLightTypes = 7u;

CANDELA_LIGHTS_BLOCK
CANDELA_DRAWS_BLOCK
CANDELA_MATERIALS_BLOCK
// The material's textures (set 1): one sampler per row of shared/shading_tables.h's texture tables,
// named after its field ("baseColorTexture").
#define CANDELA_MATERIAL_SAMPLER(NAME, field, slot, bindingNumber, normalMap) \
    layout(set = 1, binding = bindingNumber) uniform sampler2D field##Texture;
CANDELA_CORE_TEXTURES(CANDELA_MATERIAL_SAMPLER)
#ifdef CANDELA_MATERIAL_LAYERS
CANDELA_MATERIAL_LAYERS_BLOCK
CANDELA_LAYER_TEXTURES(CANDELA_MATERIAL_SAMPLER)
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
#ifdef CANDELA_IBL_REFERENCE
// The ground truth's inputs (read by shading/reference_ibl.glsl), declared in its program only (a
// frame draws with it or not at all): other programs keep the storage buffer and sampler for what
// they read, within the per-stage limits of small devices (4 storage buffers, 16 samplers).
// The environment as an equirectangular map (nearest texels; alpha 0 marks the brightest texels,
// which are summed explicitly instead of sampled) and the list of those texels:
// referenceTexels[0] = (count, width, height, 0), then per texel (x, y, 0, 0) and (radiance, 0).
layout(set = 2, binding = 4) uniform sampler2D referenceEquirect;
layout(std430, set = 2, binding = 5) readonly buffer ReferenceTexels {
    vec4 referenceTexels[];
};
#endif
layout(push_constant) uniform Push {
    FramePush push;
};

#ifdef CANDELA_MATERIAL_LAYERS
// The layers this variant evaluates: the material's, none under Blinn-Phong (kept for comparison
// with the original project, it has no Fresnel to layer).
uint layerBits() { return kShadingModel == CANDELA_SHADING_BLINN_PHONG ? 0u : kLayers; }
// Whether the variant evaluates layer `bit`. The layered program is specialized to its kLayers at
// load (vk::ProgramSpecialization): the test of kLayers comes first, alone, so that for a layer the
// material lacks the whole branch — and the textures and maps it samples — folds away.
bool hasLayer(uint bit) {
    if ((kLayers & bit) == 0u) return false;
    return kShadingModel != CANDELA_SHADING_BLINN_PHONG;
}
#endif

#endif
