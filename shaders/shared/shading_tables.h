// The shading's tables (the material programs of both paths: the forward programs and the
// visibility path's compute shading), each declared once here and read by GLSL and C++ alike. A
// table is an X-macro: it applies its argument, a macro X, to each of its rows.
//
//   CANDELA_CORE_TEXTURES(X)   the core material's texture slots (descriptor set 1 of the shading
//                              programs), X(NAME, field, slot, binding, normalMap)
//   CANDELA_LAYER_TEXTURES(X)  the layer texture slots (set 1 of the layered program, after its
//                              MaterialLayers buffer at binding 5), X(NAME, field, slot, binding, normalMap)
//   CANDELA_LAYER_BITS(X)      the material layers, as the bits of kLayers, X(NAME, Name, bit, name)
//   CANDELA_DEBUG_VIEWS(X)     the debug views, the values of kDebugView, X(NAME, Name, value, name, light)
//
// A texture slot's `field` names scene::Material's TextureRef and, with "Texture" appended, the
// GLSL sampler at `binding` (shading/resources.glsl); `normalMap`: it holds a tangent-space normal
// map (a flat normal when absent, its mips filtered as normals). From the tables come, besides:
// scene::Material's texture fields and kCoreTextureSlots / kLayerTextureSlots (scene/scene.h, which
// scene::GpuScene's uploads and the scene bindings' descriptor writes walk), scene::MaterialLayer and
// scene::layerNames, options::DebugView and its names (options/debug_view.h), and the constants below.
#ifndef CANDELA_SHARED_SHADING_TABLES_H
#define CANDELA_SHARED_SHADING_TABLES_H

#ifdef __cplusplus
#include <cstdint>
#endif

// X(NAME, field, slot, binding, normalMap); channels and colour spaces as glTF reads them.
#define CANDELA_CORE_TEXTURES(X)                                                                                 \
    X(BASE_COLOR, baseColor, 0, 0, false)                  /* sRGB, RGBA */                                       \
    X(METALLIC_ROUGHNESS, metallicRoughness, 1, 1, false)  /* linear: G roughness, B metallic */                  \
    X(NORMAL, normal, 2, 2, true)                          /* linear, tangent space */                            \
    X(OCCLUSION, occlusion, 3, 3, false)                   /* linear, R */                                        \
    X(EMISSIVE, emissive, 4, 4, false)                     /* sRGB, RGB */

#define CANDELA_LAYER_TEXTURES(X)                                                                                \
    X(SPECULAR, specular, 0, 6, false)                           /* KHR_materials_specular: linear, A */          \
    X(SPECULAR_COLOR, specularColor, 1, 7, false)                /* sRGB, RGB */                                  \
    X(CLEARCOAT, clearcoat, 2, 8, false)                         /* KHR_materials_clearcoat: linear, R */         \
    X(CLEARCOAT_ROUGHNESS, clearcoatRoughness, 3, 9, false)      /* linear, G */                                  \
    X(CLEARCOAT_NORMAL, clearcoatNormal, 4, 10, true)            /* linear, tangent space */                      \
    X(SHEEN_COLOR, sheenColor, 5, 11, false)                     /* KHR_materials_sheen: sRGB, RGB */             \
    X(SHEEN_ROUGHNESS, sheenRoughness, 6, 12, false)             /* linear, A */                                  \
    X(ANISOTROPY, anisotropy, 7, 13, false)                      /* KHR_materials_anisotropy: linear, RG direction, B strength */ \
    X(TRANSMISSION, transmission, 8, 14, false)                  /* KHR_materials_transmission: linear, R */      \
    X(THICKNESS, thickness, 9, 15, false)                        /* KHR_materials_volume: linear, G */            \
    X(IRIDESCENCE, iridescence, 10, 16, false)                   /* KHR_materials_iridescence: linear, R */       \
    X(IRIDESCENCE_THICKNESS, iridescenceThickness, 11, 17, false) /* linear, G */                             \
    X(DIFFUSE_TRANSMISSION, diffuseTransmission, 12, 18, false)  /* KHR_materials_diffuse_transmission: linear, A */ \
    X(DIFFUSE_TRANSMISSION_COLOR, diffuseTransmissionColor, 13, 19, false) /* sRGB, RGB */

// X(NAME, Name, bit, name): the layers beyond glTF's core metallic-roughness model a material can
// pay for (scene::Material::layers, docs/materials.md); `name` is what --explain and the variant
// names print.
#define CANDELA_LAYER_BITS(X)                                                                                    \
    X(SPECULAR, Specular, 1u, "specular")    /* a dielectric Fresnel other than the core's (KHR_materials_ior, KHR_materials_specular) */ \
    X(CLEARCOAT, Clearcoat, 2u, "clearcoat") /* a coat (KHR_materials_clearcoat with a non-zero factor) ... */ \
    X(CLEARCOAT_NORMAL, ClearcoatNormal, 4u, "clearcoat-normal-map") /* ... with its own normal map (the coat's TBN work) */ \
    X(SHEEN, Sheen, 8u, "sheen")             /* a sheen (KHR_materials_sheen with a non-black colour) */      \
    X(ANISOTROPY, Anisotropy, 16u, "anisotropy") /* an anisotropic GGX lobe (KHR_materials_anisotropy, non-zero strength) */ \
    X(TRANSMISSION, Transmission, 32u, "transmission") /* KHR_materials_transmission with a non-zero factor: drawn after the opaque draws, reading what lies behind them */ \
    X(VOLUME, Volume, 64u, "volume")         /* a volume beneath it (KHR_materials_volume with a thickness): refraction and absorption */ \
    X(IRIDESCENCE, Iridescence, 128u, "iridescence") /* a thin film (KHR_materials_iridescence, non-zero factor) changing the Fresnel */ \
    X(DIFFUSE_TRANSMISSION, DiffuseTransmission, 256u, "diffuse-transmission") /* a Lambertian BTDF (KHR_materials_diffuse_transmission, non-zero factor): light from behind */ \
    X(DISPERSION, Dispersion, 512u, "dispersion") /* per-channel refraction through the volume (KHR_materials_dispersion > 0 under transmission and a volume) */

// X(NAME, Name, value, name, light): what the forward pass writes instead of the shaded colour
// (options/debug_view.h); `name` is the command line's and the viewer's, `light`: the view shows
// light (tonemapped like the image) rather than data (shown as its value).
#define CANDELA_DEBUG_VIEWS(X)                                                                                   \
    X(NONE, None, 0u, "none", false)                                                                             \
    X(BASE_COLOR, BaseColor, 1u, "base-color", false)             /* material inputs ... */                     \
    X(GEOMETRIC_NORMAL, GeometricNormal, 2u, "geometric-normal", false) /* the faced normal, before the normal map */ \
    X(MAPPED_NORMAL, MappedNormal, 3u, "mapped-normal", false)    /* after it */                                 \
    X(ROUGHNESS, Roughness, 4u, "roughness", false)               /* the material's, before specular AA */      \
    X(METALLIC, Metallic, 5u, "metallic", false)                                                                 \
    X(OCCLUSION, Occlusion, 6u, "occlusion", false)                                                              \
    X(EMISSIVE, Emissive, 7u, "emissive", false)                                                                 \
    X(D, D, 8u, "d", false)                     /* GGX D toward the first punctual light, relative to its peak */ \
    X(G, G, 9u, "g", false)                     /* Smith's G toward it */                                        \
    X(F, F, 10u, "f", false)                    /* Schlick's F toward it */                                      \
    X(DIFFUSE, Diffuse, 11u, "diffuse", true)   /* the diffuse light alone (punctual + environment) */           \
    X(SPECULAR, Specular, 12u, "specular", true) /* the specular light alone */                                  \
    X(CLEARCOAT, Clearcoat, 13u, "clearcoat", true) /* the light the clearcoat reflects */                       \
    X(CLEARCOAT_NORMAL, ClearcoatNormal, 14u, "clearcoat-normal", false) /* the coat's normal (black without a coat) */ \
    X(SHEEN, Sheen, 15u, "sheen", true)         /* the light the sheen reflects */                               \
    X(ANISOTROPY, Anisotropy, 16u, "anisotropy-direction", false) /* the anisotropy direction T, scaled by its strength */ \
    X(TRANSMISSION, Transmission, 17u, "transmission", false) /* the fraction of the light behind that comes through */ \
    X(IRIDESCENCE_THICKNESS, IridescenceThickness, 18u, "iridescence-thickness", false) /* the thin film's thickness (µm) */ \
    X(IRIDESCENCE_FRESNEL, IridescenceFresnel, 19u, "iridescence-fresnel", false) /* the Fresnel the film gives at N·V */ \
    X(DIFFUSE_TRANSMISSION, DiffuseTransmission, 20u, "diffuse-transmission", true) /* the light the diffuse transmission lets through */ \
    X(DISPERSION, Dispersion, 21u, "dispersion", false) /* the angle between the red and blue refracted rays (1° white) */

// The number of rows of the texture tables: the sizes of the per-slot arrays (MaterialData::uv, ...).
#define CANDELA_TEXTURE_ROW_COUNT(NAME, field, slot, binding, normalMap) +1
#define CANDELA_TEX_COUNT (0 CANDELA_CORE_TEXTURES(CANDELA_TEXTURE_ROW_COUNT))
#define CANDELA_LAYER_TEX_COUNT (0 CANDELA_LAYER_TEXTURES(CANDELA_TEXTURE_ROW_COUNT))

// Constants named after the rows, in both languages (global in C++, like the macros they replace):
// CANDELA_TEX_BASE_COLOR … (slots), CANDELA_LAYER_TEX_SPECULAR … (layer slots), CANDELA_LAYER_SPECULAR …
// (bits); GLSL alone has CANDELA_DEBUG_NONE … (C++ has options::DebugView).
#ifdef __cplusplus
#define CANDELA_TABLE_CONSTANT(type, name, value) inline constexpr type name = value;
#define CANDELA_TABLE_INT int
#define CANDELA_TABLE_UINT uint32_t
#else
#define CANDELA_TABLE_CONSTANT(type, name, value) const type name = value;
#define CANDELA_TABLE_INT int
#define CANDELA_TABLE_UINT uint
#endif
#define CANDELA_TEXTURE_SLOT_CONSTANT(NAME, field, slot, binding, normalMap) \
    CANDELA_TABLE_CONSTANT(CANDELA_TABLE_INT, CANDELA_TEX_##NAME, slot)
#define CANDELA_LAYER_TEXTURE_SLOT_CONSTANT(NAME, field, slot, binding, normalMap) \
    CANDELA_TABLE_CONSTANT(CANDELA_TABLE_INT, CANDELA_LAYER_TEX_##NAME, slot)
#define CANDELA_LAYER_BIT_CONSTANT(NAME, Name, bit, name) CANDELA_TABLE_CONSTANT(CANDELA_TABLE_UINT, CANDELA_LAYER_##NAME, bit)
CANDELA_CORE_TEXTURES(CANDELA_TEXTURE_SLOT_CONSTANT)
CANDELA_LAYER_TEXTURES(CANDELA_LAYER_TEXTURE_SLOT_CONSTANT)
CANDELA_LAYER_BITS(CANDELA_LAYER_BIT_CONSTANT)
#ifndef __cplusplus
#define CANDELA_DEBUG_VIEW_CONSTANT(NAME, Name, value, name, light) CANDELA_TABLE_CONSTANT(uint, CANDELA_DEBUG_##NAME, value)
CANDELA_DEBUG_VIEWS(CANDELA_DEBUG_VIEW_CONSTANT)
#endif

#endif
