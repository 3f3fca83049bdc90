#pragma once
// KHR_animation_pointer's targets in the scene model: which JSON pointers of the glTF Asset Object
// Model Candela animates, and how a sampled value is written into a Material, Light or Camera.
// Each object kind has one table of fields — pointer suffix, width, where it goes, clamp range —
// declared once here (animated_properties.cpp); the loader parses pointers against them
// (parsePointer) and stores PropertyChannels naming their rows, ScenePose writes with them
// (writeMaterial, writeLight, writeCamera). Node pointers (TRS, weights, KHR_node_visibility)
// become ordinary AnimationChannels. Plain CPU code, no Vulkan.
//
//   const std::optional<PointerTarget> t = parsePointer("/materials/0/pbrMetallicRoughness/baseColorFactor");
//   // t->kind == PointerKind::Material, t->index == 0, materialFields()[t->field].width == 4
//   writeMaterial(material, t->field, values);

#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace candela::scene {

// What a pointer names: a node (translation, rotation, scale, weights, weight k, visibility), a
// mesh's default weights, or a field of a material, a KHR_lights_punctual light or a camera.
enum class PointerKind : uint8_t { Node, Mesh, Material, Light, Camera };

// PropertyChannel::object: the kinds that are not nodes.
enum class AnimatedObject : uint8_t { Material, Light, Camera };

// One parsed pointer. `index` is the glTF array index it names (nodes, meshes, materials,
// KHR_lights_punctual lights, cameras). Node and Mesh: `property` (Translation, Rotation, Scale,
// Weights, Weight with `element`, Visibility); Material, Light, Camera: `field`, the row of that
// kind's table.
struct PointerTarget {
    PointerKind kind = PointerKind::Node;
    uint32_t index = 0;
    animation::AnimatedProperty property = animation::AnimatedProperty::Values;
    uint32_t element = 0;
    uint16_t field = 0;
    bool operator==(const PointerTarget&) const = default;
};

// One animatable field of a T (Material, Light, Camera): its pointer after the object
// ("/pbrMetallicRoughness/baseColorFactor" after "/materials/{i}"), its width in floats, the range
// each component is clamped to, and where its value goes (`locate` returns the first float of the
// field; `slot` is its argument, the texture slot for texture transforms).
template <class T>
struct AnimatedField {
    std::string suffix;
    uint32_t width = 1;
    float lo = -3.4e38f, hi = 3.4e38f;
    float* (*locate)(T&, int) = nullptr;
    int slot = 0;
    // Materials only: the field lives in the layer data (shading::MaterialLayerData) rather than
    // the core data, and, for a factor that can switch a layer on, a value that does (used by
    // layersAnimationMayNeed; empty for other fields).
    bool layerData = false;
    std::optional<float> switchesOn;
};

// The tables, in a fixed order (PointerTarget::field and PropertyChannel::field index them):
// every material factor of Material (core, emissive strength, IOR, specular, clearcoat, sheen,
// anisotropy, transmission, volume, iridescence, diffuse transmission, dispersion) and the
// KHR_texture_transform offset, rotation
// and scale of every texture slot; a light's colour, intensity, range and spot cone angles; a
// camera's perspective yfov, aspectRatio, znear, zfar and orthographic xmag, ymag, znear, zfar.
std::span<const AnimatedField<Material>> materialFields();
std::span<const AnimatedField<Light>> lightFields();
std::span<const AnimatedField<Camera>> cameraFields();

// Where texture slot `slot` (a core slot, or CANDELA_TEX_COUNT + a layer slot) lives in a glTF
// material: "/pbrMetallicRoughness/baseColorTexture", "/normalTexture",
// "/extensions/KHR_materials_clearcoat/clearcoatNormalTexture", ….
std::string texturePointer(int slot);

// Parses `pointer` (RFC 6901: '/'-separated tokens, "~1" for '/', "~0" for '~'; array indices in
// decimal without leading zeros, below 2^31) against the supported templates:
//   /nodes/{}/translation | rotation | scale | weights | weights/{} | extensions/KHR_node_visibility/visible
//   /meshes/{}/weights | weights/{}
//   /materials/{}/…, /extensions/KHR_lights_punctual/lights/{}/…, /cameras/{}/… (the tables' suffixes)
// nullopt for anything else (not a pointer, a template Candela has no property for, a bad escape).
// Indices are not range-checked (the loader does that against the file).
std::optional<PointerTarget> parsePointer(std::string_view pointer);

// The pointer `target` stands for (parsePointer's inverse): what messages and tests print.
std::string pointerOf(const PointerTarget& target);

// The value width a pointer's sampler must have: its field's width, 3 for translation and scale,
// 4 for rotation, 1 for a weight or a visibility; 0 for Weights (the mesh's target count).
uint32_t pointerWidth(const PointerTarget& target);

// Writes `values` (the field's width of floats) into field `field` of the object, each component
// clamped to the field's range; a light's inner cone angle is then kept below its outer one, and a
// camera's finite zfar beyond its znear. Preconditions: `field` is a row of the kind's table and
// values.size() is its width.
void writeMaterial(Material& material, uint16_t field, std::span<const float> values);
void writeLight(Light& light, uint16_t field, std::span<const float> values);
void writeCamera(Camera& camera, uint16_t field, std::span<const float> values);

// The layers (MaterialLayer bits) `material` may use while the fields `fields` (rows of
// materialFields()) animate: its layers() with each of those factors switched on. The loader
// stores the difference in Material::animatedLayers.
uint32_t layersAnimationMayNeed(const Material& material, std::span<const uint16_t> fields);

}  // namespace candela::scene
