#include "assets/gltf_materials.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>

namespace candela::assets::gltf {
namespace {

scene::Filter magFilter(int filter) { return filter == TINYGLTF_TEXTURE_FILTER_NEAREST ? scene::Filter::Nearest : scene::Filter::Linear; }

scene::Wrap wrapMode(const LoadContext& ctx, int wrap, const std::string& what) {
    switch (wrap) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return scene::Wrap::Repeat;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return scene::Wrap::MirroredRepeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return scene::Wrap::ClampToEdge;
        default: ctx.warn(what + ": unknown wrap mode " + std::to_string(wrap) + ", using REPEAT"); return scene::Wrap::Repeat;
    }
}

std::optional<double> number(const tinygltf::Value& object, const char* key) {
    if (!object.Has(key)) return std::nullopt;
    const tinygltf::Value& v = object.Get(key);
    // Values a float cannot hold are treated as missing, like non-finite ones.
    if (!v.IsNumber() || !fitsFloat(v.GetNumberAsDouble())) return std::nullopt;
    return v.GetNumberAsDouble();
}

std::optional<glm::vec2> vec2(const tinygltf::Value& object, const char* key) {
    if (!object.Has(key)) return std::nullopt;
    const tinygltf::Value& v = object.Get(key);
    if (v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber()) return std::nullopt;
    const glm::dvec2 d(v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble());
    if (!fitsFloat(d.x) || !fitsFloat(d.y)) return std::nullopt;
    return glm::vec2(d);
}

// A finite factor, clamped to the range the specification allows.
float factor(const LoadContext& ctx, double value, double lo, double hi, const std::string& what) {
    if (!std::isfinite(value)) ctx.fail(what + " is not a finite number");
    return float(std::clamp(value, lo, hi));
}

// Resolves one textureInfo (index, texCoord, extensions) to a TextureRef.
scene::TextureRef textureRef(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images, int index, int texCoord,
                      const tinygltf::ExtensionMap& extensions, bool srgb, const std::string& what) {
    scene::TextureRef ref;
    if (index < 0) return ref;
    if (size_t(index) >= model.textures.size()) ctx.fail(what + ": texture " + std::to_string(index) + " does not exist");
    const tinygltf::Texture& texture = model.textures[size_t(index)];
    const int source = textureImage(texture);
    if (source < 0) {
        ctx.warn(what + ": texture " + std::to_string(index) + " has no image source (ignored)");
        return ref;
    }
    if (size_t(source) >= model.images.size())
        ctx.fail(what + ": texture " + std::to_string(index) + " names image " + std::to_string(source) +
                 ", which does not exist");
    if (texture.sampler >= 0 && size_t(texture.sampler) >= model.samplers.size())
        ctx.fail(what + ": texture " + std::to_string(index) + " names sampler " + std::to_string(texture.sampler) +
                 ", which does not exist");

    double set = texCoord;
    if (auto it = extensions.find("KHR_texture_transform"); it != extensions.end() && it->second.IsObject()) {
        const tinygltf::Value& t = it->second;
        if (auto offset = vec2(t, "offset")) ref.transform.offset = *offset;
        if (auto rotation = number(t, "rotation")) ref.transform.rotation = float(*rotation);
        if (auto scale = vec2(t, "scale")) ref.transform.scale = *scale;
        if (auto override = number(t, "texCoord")) set = *override;
    }
    if (set < 0 || set != std::floor(set)) ctx.fail(what + ": invalid texCoord");
    if (set > 1) {
        ctx.warn(what + ": TEXCOORD_" + (set < 1e6 ? std::to_string(int64_t(set)) : std::string("N")) +
                 " is not supported (texture ignored)");
        return scene::TextureRef{};
    }
    ref.texCoord = uint32_t(set);
    ref.sampler = texture.sampler;
    ref.image = images.resolve(source, srgb);
    return ref;
}

// The object of extension `name` in `extensions`, or null.
const tinygltf::Value* findExtension(const tinygltf::ExtensionMap& extensions, const char* name) {
    const auto it = extensions.find(name);
    return it == extensions.end() ? nullptr : &it->second;
}

// Every (glTF image, srgb) pair the materials' textures name, skipping indices out of range.
std::set<std::pair<int, bool>> imageUses(const tinygltf::Model& model) {
    std::set<std::pair<int, bool>> uses;
    auto add = [&](int texture, bool srgb) {
        if (texture >= 0 && size_t(texture) < model.textures.size()) uses.insert({textureImage(model.textures[size_t(texture)]), srgb});
    };
    for (const tinygltf::Material& m : model.materials) {
        add(m.pbrMetallicRoughness.baseColorTexture.index, true);
        add(m.emissiveTexture.index, true);
        add(m.pbrMetallicRoughness.metallicRoughnessTexture.index, false);
        add(m.normalTexture.index, false);
        add(m.occlusionTexture.index, false);
        // The texture index of extension `name`'s textureInfo `key` (-1 without one).
        const auto index = [&](const char* name, const char* key) {
            const tinygltf::Value* e = findExtension(m.extensions, name);
            return e && e->Has(key) && e->Get(key).Has("index") ? e->Get(key).Get("index").GetNumberAsInt() : -1;
        };
        add(index("KHR_materials_specular", "specularTexture"), false);
        add(index("KHR_materials_specular", "specularColorTexture"), true);
        for (const char* key : {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"})
            add(index("KHR_materials_clearcoat", key), false);
        add(index("KHR_materials_sheen", "sheenColorTexture"), true);
        add(index("KHR_materials_sheen", "sheenRoughnessTexture"), false);
        add(index("KHR_materials_anisotropy", "anisotropyTexture"), false);
        add(index("KHR_materials_transmission", "transmissionTexture"), false);
        add(index("KHR_materials_volume", "thicknessTexture"), false);
        add(index("KHR_materials_iridescence", "iridescenceTexture"), false);
        add(index("KHR_materials_iridescence", "iridescenceThicknessTexture"), false);
        add(index("KHR_materials_diffuse_transmission", "diffuseTransmissionTexture"), false);
        add(index("KHR_materials_diffuse_transmission", "diffuseTransmissionColorTexture"), true);
        add(index("KHR_materials_pbrSpecularGlossiness", "diffuseTexture"), true);
        add(index("KHR_materials_pbrSpecularGlossiness", "specularGlossinessTexture"), true);
    }
    return uses;
}

// A textureInfo inside an extension object (the schema check has vetted its types).
scene::TextureRef extensionTexture(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
                            const tinygltf::Value& extension, const char* key, bool srgb, const std::string& what) {
    if (!extension.Has(key)) return {};
    const tinygltf::Value& info = extension.Get(key);
    const int index = info.Has("index") ? info.Get("index").GetNumberAsInt() : -1;
    if (index < 0) ctx.fail(what + " " + key + ": no texture index");
    const int texCoord = info.Has("texCoord") ? info.Get("texCoord").GetNumberAsInt() : 0;
    tinygltf::ExtensionMap extensions;
    if (info.Has("extensions") && info.Get("extensions").IsObject())
        for (const std::string& name : info.Get("extensions").Keys()) extensions[name] = info.Get("extensions").Get(name);
    return textureRef(ctx, model, images, index, texCoord, extensions, srgb, what + " " + key);
}

// `value` as the shortest "%g" text ("1.5", "1e+30", "inf").
std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// A factor an extension defines on [lo, hi] (hi may be infinite: then up to the largest float):
// out-of-range values are clamped with a warning, since the render then differs from what the
// file asks for.
float clampedFactor(const LoadContext& ctx, double value, double lo, double hi, const std::string& what) {
    if (!std::isfinite(value)) ctx.fail(what + " is not a finite number");
    const double clamped = std::clamp(value, lo, std::min(hi, double(std::numeric_limits<float>::max())));
    if (clamped != value)
        ctx.warn(what + " " + shortNumber(value) + " is outside [" + shortNumber(lo) + ", " + shortNumber(hi) + "] (using " +
                 shortNumber(clamped) + ")");
    return float(clamped);
}

// The array factor `key` of extension object `e`, when present, into `out`, each component
// clamped to [lo, hi] with a warning as clampedFactor does (the schema check vetted its length).
template <int N>
void clampedFactors(const LoadContext& ctx, const tinygltf::Value& e, const char* key, double lo, double hi,
                    const std::string& what, glm::vec<N, float>& out) {
    if (!e.Has(key)) return;
    for (int i = 0; i < N; ++i) out[i] = clampedFactor(ctx, e.Get(key).Get(i).GetNumberAsDouble(), lo, hi, what + " " + key);
}

// KHR_materials_ior and KHR_materials_specular into `out`.
void loadSpecular(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
                  const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what) {
    if (auto it = extensions.find("KHR_materials_ior"); it != extensions.end()) {
        if (auto ior = number(it->second, "ior")) {
            // 0 is allowed (f0 = 1: the specular-glossiness conversion); otherwise at least 1.
            if (*ior == 0.0) out.ior = 0.0f;
            else out.ior = clampedFactor(ctx, *ior, 1.0, INFINITY, what + " ior");
        }
    }
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_specular");
    if (!found) return;
    const tinygltf::Value& e = *found;
    if (auto specular = number(e, "specularFactor"))
        out.specularFactor = clampedFactor(ctx, *specular, 0.0, 1.0, what + " specularFactor");
    clampedFactors(ctx, e, "specularColorFactor", 0.0, INFINITY, what, out.specularColorFactor);
    out.specular = extensionTexture(ctx, model, images, e, "specularTexture", false, what);
    out.specularColor = extensionTexture(ctx, model, images, e, "specularColorTexture", true, what);
}

// KHR_materials_clearcoat into `out`.
void loadClearcoat(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
                   const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what) {
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_clearcoat");
    if (!found) return;
    const tinygltf::Value& e = *found;
    if (auto factor = number(e, "clearcoatFactor"))
        out.clearcoatFactor = clampedFactor(ctx, *factor, 0.0, 1.0, what + " clearcoatFactor");
    if (auto roughness = number(e, "clearcoatRoughnessFactor"))
        out.clearcoatRoughnessFactor = clampedFactor(ctx, *roughness, 0.0, 1.0, what + " clearcoatRoughnessFactor");
    out.clearcoat = extensionTexture(ctx, model, images, e, "clearcoatTexture", false, what);
    out.clearcoatRoughness = extensionTexture(ctx, model, images, e, "clearcoatRoughnessTexture", false, what);
    out.clearcoatNormal = extensionTexture(ctx, model, images, e, "clearcoatNormalTexture", false, what);
    if (e.Has("clearcoatNormalTexture"))
        if (auto scale = number(e.Get("clearcoatNormalTexture"), "scale"))
            out.clearcoatNormalScale = factor(ctx, *scale, -1e6, 1e6, what + " clearcoatNormalTexture.scale");
}

// KHR_materials_sheen into `out`.
void loadSheen(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
               const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what) {
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_sheen");
    if (!found) return;
    const tinygltf::Value& e = *found;
    clampedFactors(ctx, e, "sheenColorFactor", 0.0, 1.0, what, out.sheenColorFactor);
    if (auto roughness = number(e, "sheenRoughnessFactor"))
        out.sheenRoughnessFactor = clampedFactor(ctx, *roughness, 0.0, 1.0, what + " sheenRoughnessFactor");
    out.sheenColor = extensionTexture(ctx, model, images, e, "sheenColorTexture", true, what);
    out.sheenRoughness = extensionTexture(ctx, model, images, e, "sheenRoughnessTexture", false, what);
}

// KHR_materials_anisotropy into `out`.
void loadAnisotropy(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
                    const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what) {
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_anisotropy");
    if (!found) return;
    const tinygltf::Value& e = *found;
    if (auto strength = number(e, "anisotropyStrength"))
        out.anisotropyStrength = clampedFactor(ctx, *strength, 0.0, 1.0, what + " anisotropyStrength");
    if (auto rotation = number(e, "anisotropyRotation")) out.anisotropyRotation = float(std::remainder(*rotation, 2.0 * std::numbers::pi));
    out.anisotropy = extensionTexture(ctx, model, images, e, "anisotropyTexture", false, what);
}

// KHR_materials_transmission and KHR_materials_volume into `out`.
void loadTransmission(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
                      const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what) {
    if (const tinygltf::Value* found = findExtension(extensions, "KHR_materials_transmission")) {
        const tinygltf::Value& e = *found;
        if (auto transmission = number(e, "transmissionFactor"))
            out.transmissionFactor = clampedFactor(ctx, *transmission, 0.0, 1.0, what + " transmissionFactor");
        out.transmission = extensionTexture(ctx, model, images, e, "transmissionTexture", false, what);
    }
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_volume");
    if (!found) return;
    const tinygltf::Value& e = *found;
    if (auto thickness = number(e, "thicknessFactor"))
        out.thicknessFactor = clampedFactor(ctx, *thickness, 0.0, INFINITY, what + " thicknessFactor");
    out.thickness = extensionTexture(ctx, model, images, e, "thicknessTexture", false, what);
    clampedFactors(ctx, e, "attenuationColor", 0.0, 1.0, what, out.attenuationColor);
    if (auto distance = number(e, "attenuationDistance")) {
        if (!std::isfinite(*distance)) ctx.fail(what + " attenuationDistance is not a finite number");
        // The specification: > 0, infinity when absent. 0 keeps that meaning here.
        if (*distance <= 0.0) ctx.warn(what + " attenuationDistance " + shortNumber(*distance) + " is not > 0: no absorption");
        else out.attenuationDistance = float(*distance);
    }
}

// KHR_materials_diffuse_transmission into `out`.
void loadDiffuseTransmission(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
                             const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what) {
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_diffuse_transmission");
    if (!found) return;
    const tinygltf::Value& e = *found;
    if (auto factor = number(e, "diffuseTransmissionFactor"))
        out.diffuseTransmissionFactor = clampedFactor(ctx, *factor, 0.0, 1.0, what + " diffuseTransmissionFactor");
    clampedFactors(ctx, e, "diffuseTransmissionColorFactor", 0.0, 1.0, what, out.diffuseTransmissionColorFactor);
    out.diffuseTransmission = extensionTexture(ctx, model, images, e, "diffuseTransmissionTexture", false, what);
    out.diffuseTransmissionColor = extensionTexture(ctx, model, images, e, "diffuseTransmissionColorTexture", true, what);
}

// KHR_materials_dispersion into `out` (after the transmission and the volume: without a volume
// beneath a transmitting surface it has nothing to spread, which a note says).
void loadDispersion(const LoadContext& ctx, const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what) {
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_dispersion");
    if (!found) return;
    if (auto dispersion = number(*found, "dispersion"))
        out.dispersion = clampedFactor(ctx, *dispersion, 0.0, INFINITY, what + " dispersion");
    if (out.dispersion > 0.0f && !(out.transmissionFactor > 0.0f && out.thicknessFactor > 0.0f))
        ctx.note(what + " dispersion " + shortNumber(out.dispersion) +
                 " has no effect without KHR_materials_transmission and a KHR_materials_volume thickness (thin-walled)");
}

// KHR_materials_iridescence into `out`.
void loadIridescence(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
                     const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what) {
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_iridescence");
    if (!found) return;
    const tinygltf::Value& e = *found;
    if (auto factor = number(e, "iridescenceFactor"))
        out.iridescenceFactor = clampedFactor(ctx, *factor, 0.0, 1.0, what + " iridescenceFactor");
    if (auto ior = number(e, "iridescenceIor")) out.iridescenceIor = clampedFactor(ctx, *ior, 1.0, INFINITY, what + " iridescenceIor");
    if (auto minimum = number(e, "iridescenceThicknessMinimum"))
        out.iridescenceThicknessMinimum = clampedFactor(ctx, *minimum, 0.0, INFINITY, what + " iridescenceThicknessMinimum");
    if (auto maximum = number(e, "iridescenceThicknessMaximum"))
        out.iridescenceThicknessMaximum = clampedFactor(ctx, *maximum, 0.0, INFINITY, what + " iridescenceThicknessMaximum");
    out.iridescence = extensionTexture(ctx, model, images, e, "iridescenceTexture", false, what);
    out.iridescenceThickness = extensionTexture(ctx, model, images, e, "iridescenceThicknessTexture", false, what);
}

// A copy of image `source` whose G channel holds 1 − glossiness · A (roughness, as the
// metallic-roughness texture's G), B = 0 (metallic) and R, A = 255; appended to scene.images once
// per (image, glossiness) through `made`.
int roughnessFromGlossiness(scene::Scene& scene, int source, float glossiness, std::map<std::pair<int, float>, int>& made) {
    const auto key = std::pair{source, glossiness};
    if (auto it = made.find(key); it != made.end()) return it->second;
    const scene::Image& from = scene.images[size_t(source)];
    scene::Image out;
    out.name = from.name + " (roughness = 1 - glossiness)";
    out.width = from.width;
    out.height = from.height;
    out.rgba8.resize(from.rgba8.size());
    for (size_t i = 0; i + 3 < from.rgba8.size(); i += 4) {
        const float gloss = glossiness * float(from.rgba8[i + 3]) / 255.0f;
        out.rgba8[i] = 255;
        out.rgba8[i + 1] = uint8_t(std::lround(255.0f * (1.0f - gloss)));
        out.rgba8[i + 2] = 0;
        out.rgba8[i + 3] = 255;
    }
    scene.images.push_back(std::move(out));
    return made[key] = int(scene.images.size() - 1);
}

// KHR_materials_pbrSpecularGlossiness (archived), converted to metallic-roughness with the specular
// layer, which KHR_materials_ior's IOR 0 defines for this purpose: base colour = diffuse, metallic
// 0, roughness = 1 − glossiness, f0 = specular colour (IOR 0, specular 1, f90 1). The textures:
// diffuseTexture becomes the base colour texture; specularGlossinessTexture's RGB (sRGB) the
// specular colour texture and its A a derived roughness texture (docs/materials.md). Replaces the
// material's metallic-roughness values.
void loadSpecularGlossiness(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images,
                            const tinygltf::ExtensionMap& extensions, scene::Material& out, const std::string& what, scene::Scene& scene,
                            std::map<std::pair<int, float>, int>& derived) {
    const tinygltf::Value* found = findExtension(extensions, "KHR_materials_pbrSpecularGlossiness");
    if (!found) return;
    const tinygltf::Value& e = *found;
    out.baseColorFactor = glm::vec4(1.0f);
    clampedFactors(ctx, e, "diffuseFactor", 0.0, 1.0, what, out.baseColorFactor);
    out.specularColorFactor = glm::vec3(1.0f);
    clampedFactors(ctx, e, "specularFactor", 0.0, 1.0, what, out.specularColorFactor);
    float glossiness = 1.0f;
    if (auto g = number(e, "glossinessFactor")) glossiness = clampedFactor(ctx, *g, 0.0, 1.0, what + " glossinessFactor");
    out.metallicFactor = 0.0f;
    out.ior = 0.0f;
    out.specularFactor = 1.0f;
    out.specular = {};
    out.baseColor = extensionTexture(ctx, model, images, e, "diffuseTexture", true, what);
    out.specularColor = extensionTexture(ctx, model, images, e, "specularGlossinessTexture", true, what);
    out.metallicRoughness = out.specularColor;
    if (out.specularColor.present()) {
        images.finishDecodes();  // the pixels are needed now
        out.metallicRoughness.image = roughnessFromGlossiness(scene, out.specularColor.image, glossiness, derived);
        out.roughnessFactor = 1.0f;
    } else {
        out.roughnessFactor = 1.0f - glossiness;
    }
}

}  // namespace

void loadSamplers(const LoadContext& ctx, const tinygltf::Model& model, scene::Scene& scene) {
    for (size_t i = 0; i < model.samplers.size(); ++i) {
        const tinygltf::Sampler& s = model.samplers[i];
        const std::string what = label("sampler", int(i), s.name);
        scene::Sampler out;
        out.magFilter = magFilter(s.magFilter);
        switch (s.minFilter) {
            case -1: break;  // undefined: our default, trilinear
            case TINYGLTF_TEXTURE_FILTER_NEAREST: out.minFilter = scene::Filter::Nearest, out.mipmaps = false; break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR: out.minFilter = scene::Filter::Linear, out.mipmaps = false; break;
            case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
                out.minFilter = scene::Filter::Nearest, out.mipFilter = scene::Filter::Nearest;
                break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
                out.minFilter = scene::Filter::Linear, out.mipFilter = scene::Filter::Nearest;
                break;
            case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
                out.minFilter = scene::Filter::Nearest, out.mipFilter = scene::Filter::Linear;
                break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
                out.minFilter = scene::Filter::Linear, out.mipFilter = scene::Filter::Linear;
                break;
            default: ctx.warn(what + ": unknown minFilter " + std::to_string(s.minFilter) + ", using trilinear");
        }
        out.wrapU = wrapMode(ctx, s.wrapS, what);
        out.wrapV = wrapMode(ctx, s.wrapT, what);
        scene.samplers.push_back(out);
    }
}

void loadMaterials(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images, scene::Scene& scene) {
    const std::set<std::pair<int, bool>> uses = imageUses(model);
    images.checkDecodedSize(uses);
    images.decodeAll(uses);  // beside the rest of the load, until loadInto takes it in
    std::map<std::pair<int, float>, int> derivedImages;  // roughness images made from glossiness
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& m = model.materials[i];
        const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
        const std::string what = label("material", int(i), m.name);
        scene::Material out;
        out.name = m.name.empty() ? "material " + std::to_string(i) : m.name;
        if (pbr.baseColorFactor.size() != 4) ctx.fail(what + ": baseColorFactor must have 4 components");
        for (int c = 0; c < 4; ++c) out.baseColorFactor[c] = factor(ctx, pbr.baseColorFactor[size_t(c)], 0, 1, what + " baseColorFactor");
        out.metallicFactor = factor(ctx, pbr.metallicFactor, 0, 1, what + " metallicFactor");
        out.roughnessFactor = factor(ctx, pbr.roughnessFactor, 0, 1, what + " roughnessFactor");
        if (m.emissiveFactor.size() != 3) ctx.fail(what + ": emissiveFactor must have 3 components");
        for (int c = 0; c < 3; ++c) out.emissiveFactor[c] = factor(ctx, m.emissiveFactor[size_t(c)], 0, 1, what + " emissiveFactor");
        out.normalScale = factor(ctx, m.normalTexture.scale, -1e6, 1e6, what + " normalTexture.scale");
        out.occlusionStrength = factor(ctx, m.occlusionTexture.strength, 0, 1, what + " occlusionTexture.strength");
        out.alphaCutoff = factor(ctx, m.alphaCutoff, 0, 1e6, what + " alphaCutoff");
        out.doubleSided = m.doubleSided;
        if (m.alphaMode == "OPAQUE") out.alphaMode = scene::AlphaMode::Opaque;
        else if (m.alphaMode == "MASK") out.alphaMode = scene::AlphaMode::Mask;
        else if (m.alphaMode == "BLEND") out.alphaMode = scene::AlphaMode::Blend;
        else ctx.warn(what + ": unknown alphaMode '" + m.alphaMode + "', using OPAQUE");

        if (auto it = m.extensions.find("KHR_materials_emissive_strength"); it != m.extensions.end()) {
            if (auto strength = number(it->second, "emissiveStrength"))
                out.emissiveStrength = factor(ctx, *strength, 0, 1e9, what + " emissiveStrength");
        }
        out.unlit = m.extensions.count("KHR_materials_unlit") > 0;
        loadSpecular(ctx, model, images, m.extensions, out, what);
        loadClearcoat(ctx, model, images, m.extensions, out, what);
        loadSheen(ctx, model, images, m.extensions, out, what);
        loadAnisotropy(ctx, model, images, m.extensions, out, what);
        loadTransmission(ctx, model, images, m.extensions, out, what);
        loadIridescence(ctx, model, images, m.extensions, out, what);
        loadDiffuseTransmission(ctx, model, images, m.extensions, out, what);
        loadDispersion(ctx, m.extensions, out, what);

        out.baseColor = textureRef(ctx, model, images, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                   pbr.baseColorTexture.extensions, true, what + " baseColorTexture");
        out.metallicRoughness =
            textureRef(ctx, model, images, pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                       pbr.metallicRoughnessTexture.extensions, false, what + " metallicRoughnessTexture");
        out.normal = textureRef(ctx, model, images, m.normalTexture.index, m.normalTexture.texCoord,
                                m.normalTexture.extensions, false, what + " normalTexture");
        out.occlusion = textureRef(ctx, model, images, m.occlusionTexture.index, m.occlusionTexture.texCoord,
                                   m.occlusionTexture.extensions, false, what + " occlusionTexture");
        out.emissive = textureRef(ctx, model, images, m.emissiveTexture.index, m.emissiveTexture.texCoord,
                                  m.emissiveTexture.extensions, true, what + " emissiveTexture");
        loadSpecularGlossiness(ctx, model, images, m.extensions, out, what, scene, derivedImages);
        scene.materials.push_back(std::move(out));
    }
}

void loadVariantNames(const LoadContext& ctx, const tinygltf::Model& model, scene::Scene& scene) {
    const auto it = model.extensions.find("KHR_materials_variants");
    if (it == model.extensions.end() || !it->second.Has("variants")) return;
    const tinygltf::Value& variants = it->second.Get("variants");
    for (int i = 0; i < int(variants.ArrayLen()); ++i) {
        const tinygltf::Value& v = variants.Get(i);
        std::string name = v.Get("name").Get<std::string>();  // required (the schema check)
        if (std::find(scene.variants.begin(), scene.variants.end(), name) != scene.variants.end())
            ctx.warn("KHR_materials_variants: variant name '" + name + "' is used twice (--variant selects the first)");
        scene.variants.push_back(std::move(name));
    }
}

std::vector<std::pair<uint32_t, uint32_t>> primitiveVariants(const LoadContext& ctx, const tinygltf::Primitive& primitive,
                                                             const scene::Scene& scene, const std::string& what) {
    std::vector<std::pair<uint32_t, uint32_t>> out;
    const auto it = primitive.extensions.find("KHR_materials_variants");
    if (it == primitive.extensions.end() || !it->second.Has("mappings")) return out;
    const tinygltf::Value& mappings = it->second.Get("mappings");
    for (int i = 0; i < int(mappings.ArrayLen()); ++i) {
        const tinygltf::Value& mapping = mappings.Get(i);
        const std::string where = what + " KHR_materials_variants mapping " + std::to_string(i);
        if (!mapping.Has("material")) ctx.fail(where + ": no material");
        const int material = mapping.Get("material").GetNumberAsInt();
        if (material < 0 || size_t(material) >= scene.materials.size())
            ctx.fail(where + ": material " + std::to_string(material) + " does not exist");
        const tinygltf::Value& variants = mapping.Get("variants");
        for (int j = 0; j < int(variants.ArrayLen()); ++j) {
            const int variant = variants.Get(j).GetNumberAsInt();
            if (variant < 0 || size_t(variant) >= scene.variants.size())
                ctx.fail(where + ": variant " + std::to_string(variant) + " does not exist (the file defines " +
                         std::to_string(scene.variants.size()) + ")");
            out.emplace_back(uint32_t(variant), uint32_t(material));
        }
    }
    return out;
}

}  // namespace candela::assets::gltf
