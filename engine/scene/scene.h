#pragma once
// The CPU-side scene: flattened geometry, materials, textures, lights and cameras, as the glTF
// loader and the built-in scenes produce it and the GPU upload consumes it. Plain data, no Vulkan.
// Conventions follow glTF 2.0: right-handed, +Y up, metres, linear colour factors, counter-
// clockwise front faces.

#include "animation/node_tree.h"
#include "core/load_report.h"
#include "shared/shading_tables.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace candela::scene {

// One vertex of the flattened scene (all primitives share one array). 72 bytes.
struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz unit tangent, w = ±1 bitangent sign (glTF)
    glm::vec2 uv0{0.0f};
    glm::vec2 uv1{0.0f};
    glm::vec4 color{1.0f};  // COLOR_0, linear; white when absent
};
static_assert(sizeof(Vertex) == 72);

struct Aabb {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& other) {
        if (other.valid()) extend(other.min), extend(other.max);
    }
};

// A decoded image. Pixels are RGBA8 (16-bit sources are reduced to 8 bits; see loader docs).
struct Image {
    std::string name;
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;  // width × height × 4, top row first
    // The file's own smaller levels (KTX2), level 1 first, each halved as Vulkan's (⌊size / 2⌋, at
    // least 1); empty when the file has none and the mips are generated on upload.
    std::vector<std::vector<uint8_t>> mips;
    bool srgb = false;           // true when used as base colour or emissive (sRGB-encoded)
    std::string format;          // what it was decoded from (SceneLoadReport::TextureDecoding::formats); "" when made in memory
    uint64_t encodedBytes = 0;   // bytes of that encoded file (a second use of one file counts them again)
};

enum class Filter : uint8_t { Nearest, Linear };
enum class Wrap : uint8_t { Repeat, MirroredRepeat, ClampToEdge };

struct Sampler {
    Filter magFilter = Filter::Linear;
    Filter minFilter = Filter::Linear;
    Filter mipFilter = Filter::Linear;
    bool mipmaps = true;  // false for glTF NEAREST/LINEAR min filters (no mip sampling)
    Wrap wrapU = Wrap::Repeat;
    Wrap wrapV = Wrap::Repeat;
};

// KHR_texture_transform, applied as uv' = offset + R(rotation) * (scale * uv).
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians
    glm::vec2 scale{1.0f};
    bool identity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
};

struct TextureRef {
    int image = -1;    // index into Scene::images; -1 = no texture
    int sampler = -1;  // index into Scene::samplers; -1 = default sampler
    uint32_t texCoord = 0;  // 0 or 1 (after KHR_texture_transform's texCoord override)
    TextureTransform transform;
    bool present() const { return image >= 0; }
};

enum class AlphaMode : uint8_t { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
    float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength
    float normalScale = 1.0f;
    float occlusionStrength = 1.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    bool unlit = false;  // KHR_materials_unlit
    // Its textures, one per row of shared/shading_tables.h's CANDELA_CORE_TEXTURES and
    // CANDELA_LAYER_TEXTURES (which give each one's channels and colour space): baseColor,
    // metallicRoughness, normal, occlusion, emissive; specular, specularColor, clearcoat, … .
#define CANDELA_MATERIAL_TEXTURE_FIELD(NAME, field, slot, binding, normalMap) TextureRef field;
    CANDELA_CORE_TEXTURES(CANDELA_MATERIAL_TEXTURE_FIELD)
    CANDELA_LAYER_TEXTURES(CANDELA_MATERIAL_TEXTURE_FIELD)
#undef CANDELA_MATERIAL_TEXTURE_FIELD

    // KHR_materials_ior and KHR_materials_specular: the dielectric Fresnel term,
    //   f0 = min(((ior − 1)/(ior + 1))² · specularColor, 1) · specular,  f90 = specular,
    // specularColor = specularColorFactor · specularColor texture (RGB), specular =
    // specularFactor · specular texture (A). ior 0 gives f0 = 1 (the specular-glossiness
    // conversion). The defaults reproduce the core material (f0 0.04, f90 1).
    float ior = 1.5f;
    float specularFactor = 1.0f;
    glm::vec3 specularColorFactor{1.0f};

    // KHR_materials_clearcoat: a GGX coat over the material, clearcoat = clearcoatFactor ·
    // texture (R), its perceptual roughness clearcoatRoughnessFactor · texture (G), on its own
    // normal map (or the unmapped normal). Factor 0 (the default): no coat.
    float clearcoatFactor = 0.0f;
    float clearcoatRoughnessFactor = 0.0f;
    float clearcoatNormalScale = 1.0f;

    // KHR_materials_sheen: a Charlie sheen over the material (beneath the coat), colour
    // sheenColorFactor · texture (RGB, sRGB), perceptual roughness sheenRoughnessFactor · texture
    // (A). A black sheen colour (the default) disables the layer.
    glm::vec3 sheenColorFactor{0.0f};
    float sheenRoughnessFactor = 0.0f;

    // KHR_materials_anisotropy: the GGX lobe stretched along a direction in the tangent plane —
    // the anisotropyTexture's RG (else the tangent), rotated by anisotropyRotation (radians) —
    // with strength anisotropyStrength · texture B. Strength 0 (the default): isotropic.
    float anisotropyStrength = 0.0f;
    float anisotropyRotation = 0.0f;

    // KHR_materials_transmission: the fraction transmissionFactor · texture (R) of the light that
    // enters the dielectric part and is transmitted through it (tinted by the base colour, blurred by
    // the roughness) instead of diffusely re-emitted. Factor 0 (the default): no transmission.
    float transmissionFactor = 0.0f;
    // KHR_materials_volume (meaningful only with transmission, specular or diffuse): the volume's
    // thickness beneath the surface, thicknessFactor · texture (G), in the mesh's units (0, the
    // default: thin-walled), and its absorption: light keeps attenuationColor after
    // attenuationDistance (world units; 0 stands for the specification's default, infinity: no
    // absorption).
    float thicknessFactor = 0.0f;
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = 0.0f;

    // KHR_materials_iridescence: a thin film over the material, weight iridescenceFactor · texture
    // (R), IOR iridescenceIor, thickness mix(minimum, maximum, thickness texture G) nm (the maximum
    // without a texture). Factor 0 (the default): no film.
    float iridescenceFactor = 0.0f;
    float iridescenceIor = 1.3f;
    float iridescenceThicknessMinimum = 100.0f;
    float iridescenceThicknessMaximum = 400.0f;

    // KHR_materials_diffuse_transmission: the fraction diffuseTransmissionFactor · texture (A) of the
    // light entering the dielectric part that a Lambertian BTDF lets through from behind (instead of
    // diffusely reflecting it), coloured diffuseTransmissionColorFactor · texture (RGB, sRGB);
    // KHR_materials_transmission overrides it by its own factor. Factor 0 (the default): none.
    float diffuseTransmissionFactor = 0.0f;
    glm::vec3 diffuseTransmissionColorFactor{1.0f};

    // KHR_materials_dispersion: 20 / the Abbe number of the volume's medium, spreading the IORs of the
    // red and blue rays refracted through it (meaningful only with transmission and a volume). 0 (the
    // default): none.
    float dispersion = 0.0f;

    // Layers (MaterialLayer bits) a KHR_animation_pointer animation of the file may switch on (a
    // factor animated from 0): the loader sets them (scene/animated_properties.h
    // layersAnimationMayNeed) so that the material's variant and layer data exist from the start.
    uint32_t animatedLayers = 0;

    // The layers beyond the core model this material uses (MaterialLayer bits), animatedLayers
    // included: only those are evaluated for it (see docs/materials.md).
    uint32_t layers() const;
    // The texture of core texture slot `slot` (CANDELA_TEX_*) and of layer texture slot `slot`
    // (CANDELA_LAYER_TEX_*). Precondition: `slot` is below CANDELA_TEX_COUNT / CANDELA_LAYER_TEX_COUNT.
    const TextureRef& texture(int slot) const;
    const TextureRef& layerTexture(int slot) const;
    // The texture whose coordinates the material's tangent frame follows — its normal map, else the
    // coat's (KHR_materials_clearcoat asks for the same coordinates), else the anisotropy texture or,
    // for an untextured anisotropy (at rest or animated), set 0 — or nullopt when the material needs
    // no tangent frame.
    std::optional<TextureRef> tangentSpaceMap() const {
        if (normal.present()) return normal;
        if (clearcoatNormal.present()) return clearcoatNormal;
        if (layers() & CANDELA_LAYER_ANISOTROPY) return anisotropy.present() ? anisotropy : TextureRef{};
        return std::nullopt;
    }
};

// One texture slot of a material (a row of shared/shading_tables.h's texture tables): the
// Material field, the forward programs' sampler for it and its binding in descriptor set 1, and
// whether it holds a tangent-space normal map (a flat normal when absent, mips filtered as normals).
struct TextureSlot {
    TextureRef Material::*field;
    const char* sampler;
    uint32_t binding;
    bool normalMap;
};

#define CANDELA_TEXTURE_SLOT(NAME, field, slot, binding, normalMap) {&Material::field, #field "Texture", binding, normalMap},
// The core texture slots and the layer texture slots, in slot order (CANDELA_TEX_*, CANDELA_LAYER_TEX_*).
inline constexpr TextureSlot kCoreTextureSlots[] = {CANDELA_CORE_TEXTURES(CANDELA_TEXTURE_SLOT)};
inline constexpr TextureSlot kLayerTextureSlots[] = {CANDELA_LAYER_TEXTURES(CANDELA_TEXTURE_SLOT)};
#undef CANDELA_TEXTURE_SLOT

inline const TextureRef& Material::texture(int slot) const { return this->*kCoreTextureSlots[slot].field; }
inline const TextureRef& Material::layerTexture(int slot) const { return this->*kLayerTextureSlots[slot].field; }

// Layers of a material beyond glTF's core metallic-roughness model, as bits (kLayerSpecular, …: the
// rows of shared/shading_tables.h's CANDELA_LAYER_BITS, which say what each stands for).
#define CANDELA_MATERIAL_LAYER(NAME, Name, bit, name) kLayer##Name = bit,
enum MaterialLayer : uint32_t { CANDELA_LAYER_BITS(CANDELA_MATERIAL_LAYER) };
#undef CANDELA_MATERIAL_LAYER

// The names of the layers in `layers` (MaterialLayer bits), in bit order: "specular", "clearcoat",
// "clearcoat-normal-map", "sheen", "anisotropy", "transmission", "volume", "iridescence",
// "diffuse-transmission", "dispersion".
inline std::vector<std::string_view> layerNames(uint32_t layers) {
#define CANDELA_LAYER_NAME(NAME, Name, bit, name) std::pair<uint32_t, std::string_view>{bit, name},
    constexpr std::pair<uint32_t, std::string_view> kNames[] = {CANDELA_LAYER_BITS(CANDELA_LAYER_NAME)};
#undef CANDELA_LAYER_NAME
    std::vector<std::string_view> out;
    for (const auto& [bit, name] : kNames)
        if (layers & bit) out.push_back(name);
    return out;
}

inline uint32_t Material::layers() const {
    uint32_t out = 0;
    // IOR 1.5 with no specular change is the core material's Fresnel: nothing to pay for.
    if (ior != 1.5f || specularFactor != 1.0f || specularColorFactor != glm::vec3(1.0f) || specular.present() ||
        specularColor.present())
        out |= kLayerSpecular;
    // The specification: clearcoatFactor 0 disables the whole layer, whatever its textures.
    if (clearcoatFactor > 0.0f) out |= kLayerClearcoat | (clearcoatNormal.present() ? kLayerClearcoatNormal : 0u);
    // The specification: a zero sheen colour factor disables the layer.
    if (sheenColorFactor != glm::vec3(0.0f)) out |= kLayerSheen;
    if (anisotropyStrength > 0.0f) out |= kLayerAnisotropy;
    // The specifications: no transmission, specular or diffuse, without its factor; a volume only
    // beneath a transmitting surface, and thickness 0 is thin-walled (no refraction, no absorption);
    // dispersion only where a volume refracts (specular transmission).
    if (transmissionFactor > 0.0f) out |= kLayerTransmission;
    if (diffuseTransmissionFactor > 0.0f) out |= kLayerDiffuseTransmission;
    if ((out & (kLayerTransmission | kLayerDiffuseTransmission)) && thicknessFactor > 0.0f) out |= kLayerVolume;
    if ((out & kLayerTransmission) && (out & kLayerVolume) && dispersion > 0.0f) out |= kLayerDispersion;
    // The specification: factor 0 disables the film. A film of thickness 0 everywhere is none either.
    const bool filmAnywhere =
        iridescenceThicknessMaximum > 0.0f || (iridescenceThickness.present() && iridescenceThicknessMinimum > 0.0f);
    if (iridescenceFactor > 0.0f && filmAnywhere) out |= kLayerIridescence;
    return out | animatedLayers;
}

// The change one morph target makes to one vertex. 80 bytes (the GPU reads the same layout).
struct MorphDelta {
    glm::vec4 position{0.0f};  // xyz
    glm::vec4 normal{0.0f};    // xyz
    glm::vec4 tangent{0.0f};   // xyz (glTF morphs no handedness)
    glm::vec4 uv{0.0f};        // TEXCOORD_0 in xy, TEXCOORD_1 in zw
    glm::vec4 color{0.0f};     // COLOR_0
};
static_assert(sizeof(MorphDelta) == 80);

// One joint's pull on one vertex: an index into its skin's joints and a weight.
struct JointInfluence {
    uint32_t joint = 0;
    float weight = 0.0f;
};

// What deforms one converted primitive each frame — its morph targets and skin weights —
// aligned with its vertex range in Scene::vertices (after the loader's vertex splits).
struct Deformation {
    uint32_t firstVertex = 0;
    uint32_t vertexCount = 0;
    uint32_t targetCount = 0;
    std::vector<MorphDelta> deltas;  // targetCount × vertexCount, target-major
    // Per target: the largest |delta position| per axis over the vertices (bounds of a morphed pose).
    std::vector<glm::vec3> maxPositionDelta;
    uint32_t influencesPerVertex = 0;          // 4 per JOINTS_n/WEIGHTS_n set; 0 without a skin
    std::vector<JointInfluence> influences;    // vertexCount × influencesPerVertex, weights sum to 1
    uint32_t maxJoint = 0;                     // the largest joint index with a non-zero weight
};

// A glTF skin: the joints (Scene::nodes indices) and their inverse bind matrices.
struct Skin {
    std::string name;
    std::vector<uint32_t> joints;
    std::vector<glm::mat4> inverseBind;  // one per joint (identity when the file has none)
};

// One level of detail of a primitive: an index range of Scene::indices over the same vertices as the
// full-detail triangles, and how far its surface may lie from theirs.
struct LodLevel {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    float error = 0.0f;  // mesh units: the simplifier's bound on the distance to the full-detail surface
};
// A primitive's levels of detail (geometry/mesh_lod.h builds them): levels[0] is the full detail (the
// draw's own range, error 0), each further level coarser, with a larger error.
struct LodChain {
    std::vector<LodLevel> levels;
};

// What a draw's indices list. glTF's seven modes are converted on load: TRIANGLES, TRIANGLE_STRIP
// and TRIANGLE_FAN to a triangle list, LINES, LINE_LOOP and LINE_STRIP to a line list (index
// pairs), POINTS to a point list. Points and lines are drawn one pixel wide.
enum class Topology : uint8_t { Triangles, Lines, Points };
inline const char* topologyName(Topology topology) {
    return topology == Topology::Triangles ? "triangles" : topology == Topology::Lines ? "lines" : "points";
}
// Indices per primitive of `topology`: 3, 2, 1.
inline uint32_t indicesPerPrimitive(Topology topology) {
    return topology == Topology::Triangles ? 3u : topology == Topology::Lines ? 2u : 1u;
}

// One drawn primitive instance: an index range of Scene::indices (into Scene::vertices) with the
// world transform of its node.
struct Draw {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    Topology topology = Topology::Triangles;
    // Points or lines without NORMAL: drawn as their material unlit (base colour × COLOR_0, alpha),
    // as the glTF specification's implementation note asks, since nothing gives them a normal.
    bool unshaded = false;
    uint32_t material = 0;  // index into Scene::materials (a default material is appended if needed)
    glm::mat4 world{1.0f};
    bool flipWinding = false;  // det(world) < 0: the front face is clockwise
    Aabb bounds;               // world space
    Aabb localBounds;          // mesh space
    int32_t node = -1;         // index into Scene::nodes (-1: built-in scenes, which have no nodes)
    // The glTF mesh and the index of the primitive within it that this draw draws (-1: built-in
    // scenes, which have no meshes): the mesh and primitive IDs of the per-pixel outputs.
    int32_t mesh = -1;
    int32_t primitive = -1;
    int32_t deformation = -1;  // index into Scene::deformations: morph targets and/or skin weights
    // Index into Scene::skins when the node is skinned and the primitive has joints: its vertices
    // are then placed by the joints in world space and `world` is the identity.
    int32_t skin = -1;
    // Not drawn in this pose: its node is not shown (KHR_node_visibility: it or an ancestor is
    // hidden), or an animated node's transform is singular (scaled to 0) or beyond a float (the
    // loader drops static singular draws).
    bool hidden = false;
    // EXT_mesh_gpu_instancing: the draw is `instanceCount` instances, instance i placed by
    // world · Scene::instances[firstInstance + i] (drawn as one instanced draw). The loader splits a
    // node's instances so that all of one draw mirror alike (flipWinding holds for each).
    uint32_t firstInstance = 0;
    uint32_t instanceCount = 0;  // 0: not instanced (one copy at `world`)
    // Index into Scene::lodChains: the simplified versions of this draw's triangles; -1: full
    // detail only (deformed primitives, and meshes that do not simplify).
    int32_t lod = -1;
};

// KHR_materials_variants of one draw: its own material and the material each variant that maps it
// gives it.
struct DrawVariants {
    uint32_t draw = 0;             // Scene::draws index
    uint32_t defaultMaterial = 0;  // the primitive's material without a variant
    std::vector<std::pair<uint32_t, uint32_t>> materials;  // (Scene::variants index, Scene::materials index)
};

enum class LightType : uint8_t { Directional, Point, Spot };

// KHR_lights_punctual, in world space. Units: candela (point/spot), lux (directional).
struct Light {
    LightType type = LightType::Point;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f;  // 0 = infinite
    float innerConeAngle = 0.0f;
    float outerConeAngle = 0.7853982f;  // π/4
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the way the light shines
    int32_t node = -1;  // index into Scene::nodes (-1: not from a node)
    int32_t source = -1;  // the glTF light (KHR_lights_punctual index) it was loaded from; -1: none
    // Its node is not shown (KHR_node_visibility): it lights nothing (uploaded with intensity 0).
    bool hidden = false;
};

struct Camera {
    std::string name;
    bool perspective = true;
    float yfov = 0.8f;         // radians (perspective)
    float aspectRatio = 0.0f;  // 0: use the viewport's
    float znear = 0.01f;
    float zfar = 0.0f;         // 0: infinite
    float xmag = 1.0f, ymag = 1.0f;  // orthographic half extents
    glm::mat4 world{1.0f};     // camera-to-world (looks down its local −Z)
    int32_t node = -1;         // index into Scene::nodes (-1: not from a node)
    int32_t source = -1;       // the glTF camera it was loaded from; -1: none
};

// What loading a scene met (LoadReport: its warnings and notes) and what it cost.
struct SceneLoadReport : LoadReport {
    // The file's extensionsUsed, in its order (empty for built-in scenes).
    std::vector<std::string> extensionsUsed;
    // What the file's compressed geometry cost to load (KHR_draco_mesh_compression,
    // EXT_meshopt_compression): wall time of the decoding, and what was decoded. Zero otherwise.
    struct Decompression {
        double milliseconds = 0.0;
        size_t dracoPrimitives = 0;
        size_t meshoptViews = 0;
    } decompression;
    // What decoding the images the materials use cost (PNG, JPEG, WebP, KTX2): wall time, the
    // files decoded by format name ("PNG", "WebP", "KTX2 ETC1S", "KTX2 UASTC+zstd", …), their
    // encoded bytes and the RGBA8 bytes they became (every level a KTX2 file stores included).
    // `milliseconds` is the decode's wall time; `waitMilliseconds` the share of it the load waited
    // for (the rest ran beside the meshes and the geometry: glTF files of PNG, JPEG and WebP).
    struct TextureDecoding {
        double milliseconds = 0.0;
        double waitMilliseconds = 0.0;
        std::map<std::string, size_t> formats;
        uint64_t encodedBytes = 0;
        uint64_t decodedBytes = 0;
    } textureDecoding;
    // What preparing the geometry for drawing did (geometry/mesh_optimize.h): the distinct meshes
    // (index ranges the draws use), how many got a chain of levels of detail, the index memory of
    // their full detail and of the chains' further levels, and the wall time it took (the chains'
    // share of it apart); whether the chains wait for a cost model's decision (lodDeferred), and
    // that decision's line once made (geometry/lod_cost.h).
    struct GeometryPreparation {
        size_t meshes = 0;
        size_t simplifiedMeshes = 0;
        uint64_t indexBytes = 0;
        uint64_t lodIndexBytes = 0;
        double milliseconds = 0.0;
        double lodMilliseconds = 0.0;
        bool lodDeferred = false;
        std::string lodDecision;
    } geometry;
};

struct Scene {
    std::string source;  // file path, or "built-in: NAME"
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<Draw> draws;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<Sampler> samplers;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    // The loaded scene's node hierarchy, depth-first (a parent before its children), with the
    // world transforms the draws, lights and cameras above were placed with. Empty for built-in
    // scenes. Animations move them (animation/node_tree.h, pose/scene_pose.h).
    std::vector<animation::SceneNode> nodes;
    // The file's animations, in file order; channels name Scene::nodes indices.
    std::vector<animation::Animation> animations;
    std::vector<Deformation> deformations;  // Draw::deformation
    std::vector<glm::mat4> instances;       // Draw::firstInstance: each instance's TRS in its node's space
    // Parallel to `instances`: each instance's index in its node's EXT_mesh_gpu_instancing
    // accessors (the loader groups a node's instances by whether they mirror, so the order differs).
    std::vector<uint32_t> instanceIndices;
    std::vector<Skin> skins;                // Draw::skin
    std::vector<LodChain> lodChains;        // Draw::lod
    // The file's scenes by name (unnamed ones as "scene N") and the one loaded; empty for files
    // without scenes and for built-in scenes.
    std::vector<std::string> sceneNames;
    uint32_t sceneIndex = 0;
    // KHR_materials_variants: the file's variant names (in file order), and each draw whose material
    // a variant changes. Draw::material holds the selected variant's material
    // (scene/material_variants.h selects one; after loading, every draw has its default).
    std::vector<std::string> variants;
    std::vector<DrawVariants> drawVariants;
    // World space, over the drawn draws (not hidden); over every draw when all are hidden.
    Aabb bounds;
    // The direction (θ°, φ°) the orbit camera frames this scene from by default, when it has one of
    // its own (the built-in sphere grid, a chart: head-on); none: scene::defaultOrbitAngles.
    std::optional<glm::vec2> framingAngles;
    // What loading met and cost. Not the model: nothing is drawn from it.
    SceneLoadReport report;
};

}  // namespace candela::scene
