#pragma once
// Helpers for the KHR_animation_pointer and KHR_node_visibility tests (unit, bad-input and GPU):
// animations whose channels are pointers, and node visibility flags, written into a GltfBuilder.

#include "gltf_test_util.h"

#include <string>
#include <vector>

namespace candela::assets::test {

// One pointer channel with a sampler of its own: key times, values (`type` of floats per key, or
// unsigned bytes with kUnsignedByte), interpolation.
struct PointerKeys {
    std::string pointer;
    std::vector<float> times;
    std::vector<float> values;
    std::string type = "SCALAR";
    std::string interpolation = "LINEAR";
    int componentType = kFloat;
};

// Declares `extension` in extensionsUsed (once).
inline void useExtension(GltfBuilder& b, const std::string& extension) {
    Json& used = b.doc["extensionsUsed"];
    if (!used.is_array()) used = Json::array();
    for (const Json& e : used)
        if (e == extension) return;
    used.push_back(extension);
}

// Appends an animation (named `name` when given) with one KHR_animation_pointer channel per entry
// of `channels`, each with its own sampler; returns the animation's index.
inline int addPointerAnimation(GltfBuilder& b, const std::vector<PointerKeys>& channels, const std::string& name = "") {
    Json animation = {{"channels", Json::array()}, {"samplers", Json::array()}};
    if (!name.empty()) animation["name"] = name;
    for (const PointerKeys& c : channels) {
        const int input = b.addFloats(c.times, "SCALAR", 1);
        const size_t components = c.type == "SCALAR" ? 1 : size_t(c.type.back() - '0');
        int output = -1;
        if (c.componentType == kUnsignedByte) {
            std::vector<uint8_t> bytes;
            for (float v : c.values) bytes.push_back(uint8_t(v));
            output = b.addAccessor(b.addView(bytes), kUnsignedByte, bytes.size() / components, c.type);
        } else {
            output = b.addFloats(c.values, c.type, int(components));
        }
        const int sampler = int(animation["samplers"].size());
        animation["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", c.interpolation}});
        animation["channels"].push_back(
            {{"sampler", sampler},
             {"target", {{"path", "pointer"}, {"extensions", {{"KHR_animation_pointer", {{"pointer", c.pointer}}}}}}}});
    }
    b.doc["animations"].push_back(animation);
    useExtension(b, "KHR_animation_pointer");
    return int(b.doc["animations"].size() - 1);
}

// Sets KHR_node_visibility's flag of node `node`.
inline void setVisible(GltfBuilder& b, int node, bool visible) {
    b.doc["nodes"][size_t(node)]["extensions"]["KHR_node_visibility"]["visible"] = visible;
    useExtension(b, "KHR_node_visibility");
}

}  // namespace candela::assets::test
