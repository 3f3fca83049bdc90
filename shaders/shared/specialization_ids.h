// The specialization constants' ids (layout(constant_id = …) in GLSL, the index into a pipeline's
// specialization values in C++), declared once for both. Each group is one family of programs;
// ids are unique within a group (checked below for C++), and a program declares only the ones it
// reads — a value given for an id the program does not declare is ignored.
#ifndef CANDELA_SHARED_SPECIALIZATION_IDS_H
#define CANDELA_SHARED_SPECIALIZATION_IDS_H

// ---- The shading programs: forward.*, forward_layers.*, forward_reference.frag, the visibility
// raster (visibility_masked.frag), the visibility shading (visibility_shade*.comp) and the
// per-pixel outputs (aov.frag).
#define CANDELA_SPEC_NORMAL_MAP 0  // the material has a normal texture
#define CANDELA_SPEC_LIGHTS 1  // the frame has punctual lights
#define CANDELA_SPEC_UNLIT 2  // KHR_materials_unlit
#define CANDELA_SPEC_ALPHA_MASK 3  // alpha mode MASK
#define CANDELA_SPEC_SHADING_MODEL 4  // CANDELA_SHADING_*
#define CANDELA_SPEC_IBL 5  // image-based lighting
#define CANDELA_SPEC_IRRADIANCE_SH 6  // SH9 irradiance, else the irradiance cube
#define CANDELA_SPEC_MULTISCATTER 7  // multiple-scattering energy compensation
#define CANDELA_SPEC_REFERENCE_SAMPLES 8  // the ground truth's samples per lobe (forward_reference.frag only)
#define CANDELA_SPEC_DEBUG_VIEW 9  // CANDELA_DEBUG_*
#define CANDELA_SPEC_LAYERS 10  // the CANDELA_LAYER_* bits the layered program evaluates
#define CANDELA_SPEC_SPECULAR_AA 11  // specular anti-aliasing
#define CANDELA_SPEC_ALPHA_TO_COVERAGE 12  // masked draws turn alpha into sample coverage
#define CANDELA_SPEC_DEFORMED 13  // the frame has deformed vertices (visibility shading)
#define CANDELA_SPEC_CORE_TEXTURES 14  // the core texture slots the texture set fills (visibility shading)
#define CANDELA_SPEC_LAYER_TEXTURES 15  // the layer texture slots it fills (visibility shading)
#define CANDELA_SPEC_LIGHT_TYPES 16  // bit 1 << CANDELA_LIGHT_* of the frame's lights
#define CANDELA_SPEC_DISTINCT 17  // which distinct triangle of a pixel's samples (visibility shading, MSAA)
#define CANDELA_SPEC_SAMPLES 18  // the frame's sample count (visibility raster and shading)
#define CANDELA_SPEC_TILE_X 20  // the visibility shading's workgroup size (a screen tile)
#define CANDELA_SPEC_TILE_Y 21
#define CANDELA_SPEC_AOV_TARGETS 22  // bit 1 << CANDELA_AOV_* of the targets the aov pass writes (aov.frag)

// ---- The tonemap programs (tonemap.frag, tonemap_sky.frag).
#define CANDELA_SPEC_TONEMAP_OPERATOR 0  // CANDELA_TONEMAP_*
#define CANDELA_SPEC_TONEMAP_ENCODE_SRGB 1
#define CANDELA_SPEC_TONEMAP_DITHER 2
#define CANDELA_SPEC_TONEMAP_BACKGROUND 3
#define CANDELA_SPEC_TONEMAP_IMAGE_CLEAR 4  // tonemap_sky.frag: the image holds its clear value (not read)

// ---- ibl_filter_cube.comp: the lobe's weights (GGX prefilter, else the irradiance cube).
#define CANDELA_SPEC_FILTER_WEIGHT_BY_COSINE 0

// ---- brdf_probe.comp: the layered BRDF instead of the core one.
#define CANDELA_SPEC_PROBE_LAYERS 0

#ifdef __cplusplus
#include <cstdint>
#include <iterator>

namespace candela::shading {
// The shading programs' ids, to check that no two share one.
inline constexpr uint32_t kShadingSpecializationIds[] = {
    CANDELA_SPEC_NORMAL_MAP,
    CANDELA_SPEC_LIGHTS,
    CANDELA_SPEC_UNLIT,
    CANDELA_SPEC_ALPHA_MASK,
    CANDELA_SPEC_SHADING_MODEL,
    CANDELA_SPEC_IBL,
    CANDELA_SPEC_IRRADIANCE_SH,
    CANDELA_SPEC_MULTISCATTER,
    CANDELA_SPEC_REFERENCE_SAMPLES,
    CANDELA_SPEC_DEBUG_VIEW,
    CANDELA_SPEC_LAYERS,
    CANDELA_SPEC_SPECULAR_AA,
    CANDELA_SPEC_ALPHA_TO_COVERAGE,
    CANDELA_SPEC_DEFORMED,
    CANDELA_SPEC_CORE_TEXTURES,
    CANDELA_SPEC_LAYER_TEXTURES,
    CANDELA_SPEC_LIGHT_TYPES,
    CANDELA_SPEC_DISTINCT,
    CANDELA_SPEC_SAMPLES,
    CANDELA_SPEC_TILE_X,
    CANDELA_SPEC_TILE_Y,
    CANDELA_SPEC_AOV_TARGETS,
};
consteval bool specializationIdsUnique() {
    for (uint32_t a = 0; a < std::size(kShadingSpecializationIds); ++a)
        for (uint32_t b = a + 1; b < std::size(kShadingSpecializationIds); ++b)
            if (kShadingSpecializationIds[a] == kShadingSpecializationIds[b]) return false;
    return true;
}
static_assert(specializationIdsUnique(), "two shading specialization constants share an id");
}  // namespace candela::shading
#endif

#endif
