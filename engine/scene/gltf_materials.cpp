#include "scene/gltf_materials.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

namespace candela::scene::gltf {
namespace {

Filter magFilter(int filter) { return filter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear; }

Wrap wrapMode(const LoadContext& ctx, int wrap, const std::string& what) {
    switch (wrap) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return Wrap::Repeat;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return Wrap::MirroredRepeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return Wrap::ClampToEdge;
        default: ctx.warn(what + ": unknown wrap mode " + std::to_string(wrap) + ", using REPEAT"); return Wrap::Repeat;
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
TextureRef textureRef(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images, int index, int texCoord,
                      const tinygltf::ExtensionMap& extensions, bool srgb, const std::string& what) {
    TextureRef ref;
    if (index < 0) return ref;
    if (size_t(index) >= model.textures.size()) ctx.fail(what + ": texture " + std::to_string(index) + " does not exist");
    const tinygltf::Texture& texture = model.textures[size_t(index)];
    if (texture.source < 0) {
        ctx.warn(what + ": texture " + std::to_string(index) + " has no PNG/JPEG source (ignored)");
        return ref;
    }
    if (size_t(texture.source) >= model.images.size())
        ctx.fail(what + ": texture " + std::to_string(index) + " names image " + std::to_string(texture.source) +
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
        return TextureRef{};
    }
    ref.texCoord = uint32_t(set);
    ref.sampler = texture.sampler;
    ref.image = images.resolve(texture.source, srgb);
    return ref;
}

// Every (glTF image, srgb) pair the materials' textures name, skipping indices out of range.
std::set<std::pair<int, bool>> imageUses(const tinygltf::Model& model) {
    std::set<std::pair<int, bool>> uses;
    auto add = [&](int texture, bool srgb) {
        if (texture >= 0 && size_t(texture) < model.textures.size()) uses.insert({model.textures[size_t(texture)].source, srgb});
    };
    for (const tinygltf::Material& m : model.materials) {
        add(m.pbrMetallicRoughness.baseColorTexture.index, true);
        add(m.emissiveTexture.index, true);
        add(m.pbrMetallicRoughness.metallicRoughnessTexture.index, false);
        add(m.normalTexture.index, false);
        add(m.occlusionTexture.index, false);
    }
    return uses;
}

}  // namespace

void loadSamplers(const LoadContext& ctx, const tinygltf::Model& model, Scene& scene) {
    for (size_t i = 0; i < model.samplers.size(); ++i) {
        const tinygltf::Sampler& s = model.samplers[i];
        const std::string what = label("sampler", int(i), s.name);
        Sampler out;
        out.magFilter = magFilter(s.magFilter);
        switch (s.minFilter) {
            case -1: break;  // undefined: our default, trilinear
            case TINYGLTF_TEXTURE_FILTER_NEAREST: out.minFilter = Filter::Nearest, out.mipmaps = false; break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR: out.minFilter = Filter::Linear, out.mipmaps = false; break;
            case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
                out.minFilter = Filter::Nearest, out.mipFilter = Filter::Nearest;
                break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
                out.minFilter = Filter::Linear, out.mipFilter = Filter::Nearest;
                break;
            case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
                out.minFilter = Filter::Nearest, out.mipFilter = Filter::Linear;
                break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
                out.minFilter = Filter::Linear, out.mipFilter = Filter::Linear;
                break;
            default: ctx.warn(what + ": unknown minFilter " + std::to_string(s.minFilter) + ", using trilinear");
        }
        out.wrapU = wrapMode(ctx, s.wrapS, what);
        out.wrapV = wrapMode(ctx, s.wrapT, what);
        scene.samplers.push_back(out);
    }
}

void loadMaterials(const LoadContext& ctx, const tinygltf::Model& model, ImageTable& images, Scene& scene) {
    images.checkDecodedSize(imageUses(model));
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& m = model.materials[i];
        const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
        const std::string what = label("material", int(i), m.name);
        Material out;
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
        if (m.alphaMode == "OPAQUE") out.alphaMode = AlphaMode::Opaque;
        else if (m.alphaMode == "MASK") out.alphaMode = AlphaMode::Mask;
        else if (m.alphaMode == "BLEND") out.alphaMode = AlphaMode::Blend;
        else ctx.warn(what + ": unknown alphaMode '" + m.alphaMode + "', using OPAQUE");

        if (auto it = m.extensions.find("KHR_materials_emissive_strength"); it != m.extensions.end()) {
            if (auto strength = number(it->second, "emissiveStrength"))
                out.emissiveStrength = factor(ctx, *strength, 0, 1e9, what + " emissiveStrength");
        }
        out.unlit = m.extensions.count("KHR_materials_unlit") > 0;

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
        scene.materials.push_back(std::move(out));
    }
}

}  // namespace candela::scene::gltf
