#pragma once
// Internal to the glTF loader: the JSON types of the glTF 2.0 properties Candela reads, checked
// before tinygltf sees the document. tinygltf 2.7 skips a property of the wrong type without a
// word ("scale": ["1", "1", "1"] loads as no scale, "indices": -4 as no indices), so a broken
// file would render wrongly instead of failing; here it fails with the property's JSON path.

#include "assets/gltf_context.h"

#include <string_view>

namespace candela::assets::gltf {

// Parses `json` and checks it: the root is an object with an "asset" object whose "version" is a
// string; every top-level array is an array of objects; indices are non-negative integers;
// counts, offsets and lengths are non-negative integers; numbers, booleans, strings and fixed-size
// number arrays (translation 3, rotation 4, scale 3, matrix 16, baseColorFactor 4,
// emissiveFactor 3, ...) have their types; KHR_lights_punctual, KHR_texture_transform,
// KHR_materials_emissive_strength, KHR_node_visibility (visible: a bool) and
// KHR_animation_pointer (pointer: a string) likewise. Unknown properties, extras and other extensions are
// not checked. Fails via ctx with "invalid glTF: PATH: expected ..." or the JSON parser's message.
void checkGltfJson(const LoadContext& ctx, std::string_view json);

}  // namespace candela::assets::gltf
