#include "assets/gltf_schema.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace candela::assets::gltf {
namespace {

using Json = nlohmann::json;

enum class Kind { Index, Count, Integer, Number, Bool, String, Object, IndexArray, NumberArray, StringArray };

// A property of an object: its key, kind, and for NumberArray the exact length (0: any).
struct Property {
    const char* key;
    Kind kind;
    size_t length = 0;
};

class Checker {
public:
    explicit Checker(const LoadContext& ctx) : mCtx(ctx) {}

    [[noreturn]] void fail(const std::string& path, const std::string& expected, const Json& got) const {
        mCtx.fail("invalid glTF: " + path + ": expected " + expected + ", got " + describe(got));
    }

    static std::string describe(const Json& value) {
        if (value.is_number_integer() || value.is_number_unsigned()) return "the integer " + value.dump();
        if (value.is_number()) return "the number " + value.dump();
        if (value.is_string()) {
            const std::string text = value.get<std::string>();
            return "the string \"" + (text.size() > 32 ? text.substr(0, 32) + "..." : text) + "\"";
        }
        const std::string type = value.type_name();
        return (type == "array" || type == "object" ? "an " : "a ") + type;
    }

    void check(const Json& value, const std::string& path, Kind kind, size_t length = 0) const {
        switch (kind) {
            case Kind::Index:
            case Kind::Count:
                if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<int64_t>() >= 0))
                    fail(path, kind == Kind::Index ? "an index (an integer >= 0)" : "an integer >= 0", value);
                if (kind == Kind::Index && value.get<uint64_t>() > uint64_t(INT32_MAX))
                    fail(path, "an index below 2^31", value);
                return;
            case Kind::Integer:
                if (!value.is_number_integer()) fail(path, "an integer", value);
                return;
            case Kind::Number:
                if (!value.is_number()) fail(path, "a number", value);
                return;
            case Kind::Bool:
                if (!value.is_boolean()) fail(path, "true or false", value);
                return;
            case Kind::String:
                if (!value.is_string()) fail(path, "a string", value);
                return;
            case Kind::Object:
                if (!value.is_object()) fail(path, "an object", value);
                return;
            case Kind::IndexArray:
            case Kind::NumberArray:
            case Kind::StringArray: {
                const std::string what = kind == Kind::IndexArray ? "indices" : kind == Kind::NumberArray ? "numbers" : "strings";
                const std::string expected = length ? "an array of " + std::to_string(length) + " " + what : "an array of " + what;
                if (!value.is_array() || (length && value.size() != length)) fail(path, expected, value);
                const Kind element = kind == Kind::IndexArray ? Kind::Index : kind == Kind::NumberArray ? Kind::Number : Kind::String;
                for (size_t i = 0; i < value.size(); ++i) check(value[i], path + "[" + std::to_string(i) + "]", element);
                return;
            }
        }
    }

    // "PATH.KEY", or "KEY" at the root (PATH "").
    static std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

    // Checks the listed properties of `object` (those present) and returns it.
    const Json& properties(const Json& object, const std::string& path, std::initializer_list<Property> list) const {
        check(object, path.empty() ? "the document" : path, Kind::Object);
        for (const Property& p : list)
            if (auto it = object.find(p.key); it != object.end()) check(*it, join(path, p.key), p.kind, p.length);
        return object;
    }

    // `object[key]`, when present, as an object with the listed properties; returns it or null.
    const Json* child(const Json& object, const std::string& path, const char* key, std::initializer_list<Property> list) const {
        auto it = object.find(key);
        if (it == object.end()) return nullptr;
        return &properties(*it, join(path, key), list);
    }

    // Each element of the array `key` of `object` (at `path`; "" for the document) is, when
    // present, an object checked by `each`.
    void array(const Json& object, const char* key, const std::function<void(const Json&, const std::string&)>& each,
               const std::string& path = "") const {
        auto it = object.find(key);
        if (it == object.end()) return;
        const std::string where = join(path, key);
        if (!it->is_array()) fail(where, "an array of objects", *it);
        for (size_t i = 0; i < it->size(); ++i) {
            const std::string element = where + "[" + std::to_string(i) + "]";
            check((*it)[i], element, Kind::Object);
            each((*it)[i], element);
        }
    }

    void textureInfo(const Json& object, const std::string& path, const char* key, bool normal = false, bool occlusion = false) const {
        const Json* info = child(object, path, key, {{"index", Kind::Index}, {"texCoord", Kind::Count}});
        if (!info) return;
        if (normal) properties(*info, path + "." + key, {{"scale", Kind::Number}});
        if (occlusion) properties(*info, path + "." + key, {{"strength", Kind::Number}});
        if (const Json* ext = child(*info, path + "." + key, "extensions", {}))
            child(*ext, path + "." + key + ".extensions", "KHR_texture_transform",
                  {{"offset", Kind::NumberArray, 2}, {"rotation", Kind::Number}, {"scale", Kind::NumberArray, 2}, {"texCoord", Kind::Count}});
    }

private:
    const LoadContext& mCtx;
};

void checkDocument(const Checker& c, const Json& root) {
    if (!root.is_object()) c.fail("the document", "a JSON object", root);
    auto asset = root.find("asset");
    if (asset == root.end()) c.fail("asset", "an object", Json());
    c.properties(*asset, "asset", {{"version", Kind::String}, {"minVersion", Kind::String}});
    if (!asset->contains("version")) c.fail("asset.version", "a string", Json());
    c.properties(root, "", {{"scene", Kind::Index}, {"extensionsUsed", Kind::StringArray}, {"extensionsRequired", Kind::StringArray}});
    if (const Json* ext = c.child(root, "", "extensions", {}))
        if (const Json* variants = c.child(*ext, "extensions", "KHR_materials_variants", {}))
            c.array(*variants, "variants", [&](const Json& v, const std::string& p) {
                c.properties(v, p, {{"name", Kind::String}});
                if (!v.contains("name")) c.fail(p + ".name", "a string (a variant's name is required)", Json());
            }, "extensions.KHR_materials_variants");

    c.array(root, "accessors", [&](const Json& a, const std::string& p) {
        c.properties(a, p, {{"bufferView", Kind::Index}, {"byteOffset", Kind::Count}, {"componentType", Kind::Integer},
                            {"normalized", Kind::Bool}, {"count", Kind::Count}, {"type", Kind::String},
                            {"max", Kind::NumberArray}, {"min", Kind::NumberArray}});
        if (const Json* sparse = c.child(a, p, "sparse", {{"count", Kind::Count}})) {
            c.child(*sparse, p + ".sparse", "indices", {{"bufferView", Kind::Index}, {"byteOffset", Kind::Count}, {"componentType", Kind::Integer}});
            c.child(*sparse, p + ".sparse", "values", {{"bufferView", Kind::Index}, {"byteOffset", Kind::Count}});
        }
    });
    c.array(root, "buffers", [&](const Json& b, const std::string& p) {
        c.properties(b, p, {{"byteLength", Kind::Count}, {"uri", Kind::String}});
        if (const Json* ext = c.child(b, p, "extensions", {}))
            c.child(*ext, p + ".extensions", "EXT_meshopt_compression", {{"fallback", Kind::Bool}});
    });
    c.array(root, "bufferViews", [&](const Json& v, const std::string& p) {
        c.properties(v, p, {{"buffer", Kind::Index}, {"byteOffset", Kind::Count}, {"byteLength", Kind::Count},
                            {"byteStride", Kind::Count}, {"target", Kind::Integer}});
        if (const Json* ext = c.child(v, p, "extensions", {}))
            c.child(*ext, p + ".extensions", "EXT_meshopt_compression",
                    {{"buffer", Kind::Index}, {"byteOffset", Kind::Count}, {"byteLength", Kind::Count}, {"byteStride", Kind::Count},
                     {"count", Kind::Count}, {"mode", Kind::String}, {"filter", Kind::String}});
    });
    c.array(root, "cameras", [&](const Json& cam, const std::string& p) {
        c.properties(cam, p, {{"type", Kind::String}});
        c.child(cam, p, "perspective", {{"aspectRatio", Kind::Number}, {"yfov", Kind::Number}, {"zfar", Kind::Number}, {"znear", Kind::Number}});
        c.child(cam, p, "orthographic", {{"xmag", Kind::Number}, {"ymag", Kind::Number}, {"zfar", Kind::Number}, {"znear", Kind::Number}});
    });
    c.array(root, "images", [&](const Json& i, const std::string& p) {
        c.properties(i, p, {{"uri", Kind::String}, {"mimeType", Kind::String}, {"bufferView", Kind::Index}});
    });
    c.array(root, "materials", [&](const Json& m, const std::string& p) {
        c.properties(m, p, {{"name", Kind::String}, {"emissiveFactor", Kind::NumberArray, 3}, {"alphaMode", Kind::String},
                            {"alphaCutoff", Kind::Number}, {"doubleSided", Kind::Bool}});
        if (const Json* pbr = c.child(m, p, "pbrMetallicRoughness", {{"baseColorFactor", Kind::NumberArray, 4},
                                                                     {"metallicFactor", Kind::Number}, {"roughnessFactor", Kind::Number}})) {
            c.textureInfo(*pbr, p + ".pbrMetallicRoughness", "baseColorTexture");
            c.textureInfo(*pbr, p + ".pbrMetallicRoughness", "metallicRoughnessTexture");
        }
        c.textureInfo(m, p, "normalTexture", true);
        c.textureInfo(m, p, "occlusionTexture", false, true);
        c.textureInfo(m, p, "emissiveTexture");
        if (const Json* ext = c.child(m, p, "extensions", {})) {
            const std::string pe = p + ".extensions";
            c.child(*ext, pe, "KHR_materials_emissive_strength", {{"emissiveStrength", Kind::Number}});
            c.child(*ext, pe, "KHR_materials_ior", {{"ior", Kind::Number}});
            if (const Json* specular = c.child(*ext, pe, "KHR_materials_specular",
                                               {{"specularFactor", Kind::Number}, {"specularColorFactor", Kind::NumberArray, 3}})) {
                c.textureInfo(*specular, pe + ".KHR_materials_specular", "specularTexture");
                c.textureInfo(*specular, pe + ".KHR_materials_specular", "specularColorTexture");
            }
            if (const Json* coat = c.child(*ext, pe, "KHR_materials_clearcoat",
                                           {{"clearcoatFactor", Kind::Number}, {"clearcoatRoughnessFactor", Kind::Number}})) {
                const std::string pc = pe + ".KHR_materials_clearcoat";
                c.textureInfo(*coat, pc, "clearcoatTexture");
                c.textureInfo(*coat, pc, "clearcoatRoughnessTexture");
                c.textureInfo(*coat, pc, "clearcoatNormalTexture", true);
            }
            if (const Json* sheen = c.child(*ext, pe, "KHR_materials_sheen",
                                            {{"sheenColorFactor", Kind::NumberArray, 3}, {"sheenRoughnessFactor", Kind::Number}})) {
                c.textureInfo(*sheen, pe + ".KHR_materials_sheen", "sheenColorTexture");
                c.textureInfo(*sheen, pe + ".KHR_materials_sheen", "sheenRoughnessTexture");
            }
            if (const Json* an = c.child(*ext, pe, "KHR_materials_anisotropy",
                                         {{"anisotropyStrength", Kind::Number}, {"anisotropyRotation", Kind::Number}}))
                c.textureInfo(*an, pe + ".KHR_materials_anisotropy", "anisotropyTexture");
            if (const Json* tr = c.child(*ext, pe, "KHR_materials_transmission", {{"transmissionFactor", Kind::Number}}))
                c.textureInfo(*tr, pe + ".KHR_materials_transmission", "transmissionTexture");
            if (const Json* volume = c.child(*ext, pe, "KHR_materials_volume",
                                             {{"thicknessFactor", Kind::Number}, {"attenuationDistance", Kind::Number},
                                              {"attenuationColor", Kind::NumberArray, 3}}))
                c.textureInfo(*volume, pe + ".KHR_materials_volume", "thicknessTexture");
            if (const Json* film = c.child(*ext, pe, "KHR_materials_iridescence",
                                           {{"iridescenceFactor", Kind::Number}, {"iridescenceIor", Kind::Number},
                                            {"iridescenceThicknessMinimum", Kind::Number},
                                            {"iridescenceThicknessMaximum", Kind::Number}})) {
                c.textureInfo(*film, pe + ".KHR_materials_iridescence", "iridescenceTexture");
                c.textureInfo(*film, pe + ".KHR_materials_iridescence", "iridescenceThicknessTexture");
            }
            if (const Json* dt = c.child(*ext, pe, "KHR_materials_diffuse_transmission",
                                         {{"diffuseTransmissionFactor", Kind::Number},
                                          {"diffuseTransmissionColorFactor", Kind::NumberArray, 3}})) {
                c.textureInfo(*dt, pe + ".KHR_materials_diffuse_transmission", "diffuseTransmissionTexture");
                c.textureInfo(*dt, pe + ".KHR_materials_diffuse_transmission", "diffuseTransmissionColorTexture");
            }
            c.child(*ext, pe, "KHR_materials_dispersion", {{"dispersion", Kind::Number}});
            if (const Json* sg = c.child(*ext, pe, "KHR_materials_pbrSpecularGlossiness",
                                         {{"diffuseFactor", Kind::NumberArray, 4}, {"specularFactor", Kind::NumberArray, 3},
                                          {"glossinessFactor", Kind::Number}})) {
                c.textureInfo(*sg, pe + ".KHR_materials_pbrSpecularGlossiness", "diffuseTexture");
                c.textureInfo(*sg, pe + ".KHR_materials_pbrSpecularGlossiness", "specularGlossinessTexture");
            }
        }
    });
    c.array(root, "meshes", [&](const Json& mesh, const std::string& p) {
        c.properties(mesh, p, {{"weights", Kind::NumberArray}});
        auto primitives = mesh.find("primitives");
        if (primitives == mesh.end() || !primitives->is_array()) c.fail(p + ".primitives", "an array of objects", primitives == mesh.end() ? Json() : *primitives);
        for (size_t i = 0; i < primitives->size(); ++i) {
            const std::string pp = p + ".primitives[" + std::to_string(i) + "]";
            const Json& prim = c.properties((*primitives)[i], pp, {{"indices", Kind::Index}, {"material", Kind::Index}, {"mode", Kind::Integer}});
            auto attributes = prim.find("attributes");
            if (attributes == prim.end()) c.fail(pp + ".attributes", "an object", Json());
            c.check(*attributes, pp + ".attributes", Kind::Object);
            for (auto it = attributes->begin(); it != attributes->end(); ++it) c.check(it.value(), pp + ".attributes." + it.key(), Kind::Index);
            if (const Json* ext = c.child(prim, pp, "extensions", {})) {
                if (const Json* draco = c.child(*ext, pp + ".extensions", "KHR_draco_mesh_compression",
                                                {{"bufferView", Kind::Index}, {"attributes", Kind::Object}})) {
                    const std::string dp = pp + ".extensions.KHR_draco_mesh_compression";
                    if (!draco->contains("bufferView")) c.fail(dp + ".bufferView", "an index (an integer >= 0)", Json());
                    if (!draco->contains("attributes")) c.fail(dp + ".attributes", "an object", Json());
                    const Json& ids = draco->at("attributes");
                    for (auto it = ids.begin(); it != ids.end(); ++it) c.check(it.value(), dp + ".attributes." + it.key(), Kind::Index);
                }
                const std::string vp = pp + ".extensions.KHR_materials_variants";
                if (const Json* variants = c.child(*ext, pp + ".extensions", "KHR_materials_variants", {}))
                    c.array(*variants, "mappings", [&](const Json& m, const std::string& mp) {
                        c.properties(m, mp, {{"material", Kind::Index}, {"variants", Kind::IndexArray}, {"name", Kind::String}});
                        if (!m.contains("material")) c.fail(mp + ".material", "an index (an integer >= 0)", Json());
                        if (!m.contains("variants")) c.fail(mp + ".variants", "an array of indices", Json());
                    }, vp);
            }
        }
    });
    c.array(root, "nodes", [&](const Json& n, const std::string& p) {
        c.properties(n, p, {{"camera", Kind::Index}, {"children", Kind::IndexArray}, {"skin", Kind::Index},
                            {"matrix", Kind::NumberArray, 16}, {"mesh", Kind::Index}, {"rotation", Kind::NumberArray, 4},
                            {"scale", Kind::NumberArray, 3}, {"translation", Kind::NumberArray, 3}, {"weights", Kind::NumberArray}});
        if (const Json* ext = c.child(n, p, "extensions", {})) {
            c.child(*ext, p + ".extensions", "KHR_lights_punctual", {{"light", Kind::Index}});
            c.child(*ext, p + ".extensions", "KHR_node_visibility", {{"visible", Kind::Bool}});
        }
    });
    c.array(root, "samplers", [&](const Json& s, const std::string& p) {
        c.properties(s, p, {{"magFilter", Kind::Integer}, {"minFilter", Kind::Integer}, {"wrapS", Kind::Integer}, {"wrapT", Kind::Integer}});
    });
    c.array(root, "scenes", [&](const Json& s, const std::string& p) { c.properties(s, p, {{"nodes", Kind::IndexArray}}); });
    c.array(root, "textures", [&](const Json& t, const std::string& p) {
        c.properties(t, p, {{"sampler", Kind::Index}, {"source", Kind::Index}});
        if (const Json* ext = c.child(t, p, "extensions", {}))
            for (const char* name : {"KHR_texture_basisu", "EXT_texture_webp"})
                c.child(*ext, p + ".extensions", name, {{"source", Kind::Index}});
    });
    c.array(root, "skins", [&](const Json& s, const std::string& p) {
        c.properties(s, p, {{"inverseBindMatrices", Kind::Index}, {"skeleton", Kind::Index}, {"joints", Kind::IndexArray},
                            {"name", Kind::String}});
    });
    c.array(root, "animations", [&](const Json& a, const std::string& p) {
        c.properties(a, p, {{"name", Kind::String}});
        auto each = [&](const char* key, const std::function<void(const Json&, const std::string&)>& check) {
            auto list = a.find(key);
            if (list == a.end() || !list->is_array()) c.fail(p + "." + key, "an array of objects", list == a.end() ? Json() : *list);
            for (size_t i = 0; i < list->size(); ++i) check((*list)[i], p + "." + key + "[" + std::to_string(i) + "]");
        };
        each("channels", [&](const Json& channel, const std::string& cp) {
            c.properties(channel, cp, {{"sampler", Kind::Index}});
            auto target = channel.find("target");
            if (target == channel.end()) c.fail(cp + ".target", "an object", Json());
            c.properties(*target, cp + ".target", {{"node", Kind::Index}, {"path", Kind::String}});
            if (const Json* ext = c.child(*target, cp + ".target", "extensions", {}))
                c.child(*ext, cp + ".target.extensions", "KHR_animation_pointer", {{"pointer", Kind::String}});
        });
        each("samplers", [&](const Json& sampler, const std::string& sp) {
            c.properties(sampler, sp, {{"input", Kind::Index}, {"output", Kind::Index}, {"interpolation", Kind::String}});
        });
    });
    if (const Json* ext = c.child(root, "", "extensions", {}))
        if (const Json* lights = c.child(*ext, "extensions", "KHR_lights_punctual", {})) {
            auto list = lights->find("lights");
            if (list != lights->end()) {
                if (!list->is_array()) c.fail("extensions.KHR_lights_punctual.lights", "an array of objects", *list);
                for (size_t i = 0; i < list->size(); ++i) {
                    const std::string p = "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]";
                    c.properties((*list)[i], p, {{"type", Kind::String}, {"color", Kind::NumberArray, 3}, {"intensity", Kind::Number}, {"range", Kind::Number}});
                    c.child((*list)[i], p, "spot", {{"innerConeAngle", Kind::Number}, {"outerConeAngle", Kind::Number}});
                }
            }
        }
}

}  // namespace

void checkGltfJson(const LoadContext& ctx, std::string_view json) {
    Json root;
    try {
        root = Json::parse(json.begin(), json.end());
    } catch (const Json::exception& e) {
        ctx.fail(std::string("invalid glTF: ") + e.what());
    }
    checkDocument(Checker(ctx), root);
}

}  // namespace candela::assets::gltf
