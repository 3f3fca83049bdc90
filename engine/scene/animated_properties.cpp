#include "scene/animated_properties.h"

#include "core/errors.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace candela::scene {
namespace {

constexpr float kMax = std::numeric_limits<float>::max();
constexpr float kHalfPi = 1.57079632679f;
constexpr float kPi = 3.14159265359f;

// The material extensions KHR_animation_pointer reaches, as pointer parts.
constexpr std::string_view kEmissiveStrength = "/extensions/KHR_materials_emissive_strength";
constexpr std::string_view kIor = "/extensions/KHR_materials_ior";
constexpr std::string_view kSpecular = "/extensions/KHR_materials_specular";
constexpr std::string_view kClearcoat = "/extensions/KHR_materials_clearcoat";
constexpr std::string_view kSheen = "/extensions/KHR_materials_sheen";
constexpr std::string_view kAnisotropy = "/extensions/KHR_materials_anisotropy";
constexpr std::string_view kTransmission = "/extensions/KHR_materials_transmission";
constexpr std::string_view kVolume = "/extensions/KHR_materials_volume";
constexpr std::string_view kIridescence = "/extensions/KHR_materials_iridescence";
constexpr std::string_view kDiffuseTransmission = "/extensions/KHR_materials_diffuse_transmission";
constexpr std::string_view kDispersion = "/extensions/KHR_materials_dispersion";

// Where each texture slot's textureInfo sits in a glTF material, in slot order (its key is the
// slot's sampler name, kCoreTextureSlots / kLayerTextureSlots: "baseColorTexture", …).
constexpr std::string_view kCoreTextureParents[] = {"/pbrMetallicRoughness", "/pbrMetallicRoughness", "", "", ""};
constexpr std::string_view kLayerTextureParents[] = {kSpecular,    kSpecular,    kClearcoat,   kClearcoat,
                                                     kClearcoat,   kSheen,       kSheen,       kAnisotropy,
                                                     kTransmission, kVolume,     kIridescence, kIridescence,
                                                     kDiffuseTransmission, kDiffuseTransmission};
static_assert(std::size(kCoreTextureParents) == CANDELA_TEX_COUNT);
static_assert(std::size(kLayerTextureParents) == CANDELA_LAYER_TEX_COUNT);

constexpr int kTextureSlots = CANDELA_TEX_COUNT + CANDELA_LAYER_TEX_COUNT;

TextureRef& textureOf(Material& m, int slot) {
    return slot < CANDELA_TEX_COUNT ? m.*kCoreTextureSlots[slot].field : m.*kLayerTextureSlots[slot - CANDELA_TEX_COUNT].field;
}

std::string cat(std::string_view a, std::string_view b) { return std::string(a) + std::string(b); }

using MaterialField = AnimatedField<Material>;

// A factor of the material: `Field` is the member, `width` its floats.
#define CANDELA_FACTOR(member) [](Material& m, int) { return &(m.member)[0]; }
#define CANDELA_SCALAR(member) [](Material& m, int) { return &m.member; }

std::vector<MaterialField> makeMaterialFields() {
    std::vector<MaterialField> out = {
        {"/pbrMetallicRoughness/baseColorFactor", 4, 0.0f, 1.0f, CANDELA_FACTOR(baseColorFactor)},
        {"/pbrMetallicRoughness/metallicFactor", 1, 0.0f, 1.0f, CANDELA_SCALAR(metallicFactor)},
        {"/pbrMetallicRoughness/roughnessFactor", 1, 0.0f, 1.0f, CANDELA_SCALAR(roughnessFactor)},
        {"/emissiveFactor", 3, 0.0f, 1.0f, CANDELA_FACTOR(emissiveFactor)},
        {"/alphaCutoff", 1, 0.0f, 1e6f, CANDELA_SCALAR(alphaCutoff)},
        {texturePointer(CANDELA_TEX_NORMAL) + "/scale", 1, -1e6f, 1e6f, CANDELA_SCALAR(normalScale)},
        {texturePointer(CANDELA_TEX_OCCLUSION) + "/strength", 1, 0.0f, 1.0f, CANDELA_SCALAR(occlusionStrength)},
        {cat(kEmissiveStrength, "/emissiveStrength"), 1, 0.0f, 1e9f, CANDELA_SCALAR(emissiveStrength)},
        // The layers: each factor that can switch its layer on says with what value.
        {cat(kIor, "/ior"), 1, 1.0f, kMax, CANDELA_SCALAR(ior), 0, true, 1.6f},
        {cat(kSpecular, "/specularFactor"), 1, 0.0f, 1.0f, CANDELA_SCALAR(specularFactor), 0, true, 0.5f},
        {cat(kSpecular, "/specularColorFactor"), 3, 0.0f, kMax, CANDELA_FACTOR(specularColorFactor), 0, true, 0.5f},
        {cat(kClearcoat, "/clearcoatFactor"), 1, 0.0f, 1.0f, CANDELA_SCALAR(clearcoatFactor), 0, true, 1.0f},
        {cat(kClearcoat, "/clearcoatRoughnessFactor"), 1, 0.0f, 1.0f, CANDELA_SCALAR(clearcoatRoughnessFactor), 0, true},
        {texturePointer(CANDELA_TEX_COUNT + CANDELA_LAYER_TEX_CLEARCOAT_NORMAL) + "/scale", 1, -1e6f, 1e6f,
         CANDELA_SCALAR(clearcoatNormalScale), 0, true},
        {cat(kSheen, "/sheenColorFactor"), 3, 0.0f, 1.0f, CANDELA_FACTOR(sheenColorFactor), 0, true, 1.0f},
        {cat(kSheen, "/sheenRoughnessFactor"), 1, 0.0f, 1.0f, CANDELA_SCALAR(sheenRoughnessFactor), 0, true},
        {cat(kAnisotropy, "/anisotropyStrength"), 1, 0.0f, 1.0f, CANDELA_SCALAR(anisotropyStrength), 0, true, 1.0f},
        {cat(kAnisotropy, "/anisotropyRotation"), 1, -kMax, kMax, CANDELA_SCALAR(anisotropyRotation), 0, true},
        {cat(kTransmission, "/transmissionFactor"), 1, 0.0f, 1.0f, CANDELA_SCALAR(transmissionFactor), 0, true, 1.0f},
        {cat(kVolume, "/thicknessFactor"), 1, 0.0f, kMax, CANDELA_SCALAR(thicknessFactor), 0, true, 1.0f},
        // 0 stands for the specification's infinity (no absorption), as in the loader.
        {cat(kVolume, "/attenuationDistance"), 1, 0.0f, kMax, CANDELA_SCALAR(attenuationDistance), 0, true},
        {cat(kVolume, "/attenuationColor"), 3, 0.0f, 1.0f, CANDELA_FACTOR(attenuationColor), 0, true},
        {cat(kIridescence, "/iridescenceFactor"), 1, 0.0f, 1.0f, CANDELA_SCALAR(iridescenceFactor), 0, true, 1.0f},
        {cat(kIridescence, "/iridescenceIor"), 1, 1.0f, kMax, CANDELA_SCALAR(iridescenceIor), 0, true},
        {cat(kIridescence, "/iridescenceThicknessMinimum"), 1, 0.0f, kMax, CANDELA_SCALAR(iridescenceThicknessMinimum), 0, true,
         100.0f},
        {cat(kIridescence, "/iridescenceThicknessMaximum"), 1, 0.0f, kMax, CANDELA_SCALAR(iridescenceThicknessMaximum), 0, true,
         400.0f},
        {cat(kDiffuseTransmission, "/diffuseTransmissionFactor"), 1, 0.0f, 1.0f, CANDELA_SCALAR(diffuseTransmissionFactor), 0,
         true, 1.0f},
        {cat(kDiffuseTransmission, "/diffuseTransmissionColorFactor"), 3, 0.0f, 1.0f,
         CANDELA_FACTOR(diffuseTransmissionColorFactor), 0, true},
        {cat(kDispersion, "/dispersion"), 1, 0.0f, kMax, CANDELA_SCALAR(dispersion), 0, true, 1.0f},
    };
    // KHR_texture_transform of every texture slot.
    for (int slot = 0; slot < kTextureSlots; ++slot) {
        const std::string transform = texturePointer(slot) + "/extensions/KHR_texture_transform";
        const bool layer = slot >= CANDELA_TEX_COUNT;
        out.push_back({transform + "/offset", 2, -kMax, kMax,
                       [](Material& m, int s) { return &textureOf(m, s).transform.offset[0]; }, slot, layer});
        out.push_back({transform + "/rotation", 1, -kMax, kMax,
                       [](Material& m, int s) { return &textureOf(m, s).transform.rotation; }, slot, layer});
        out.push_back({transform + "/scale", 2, -kMax, kMax,
                       [](Material& m, int s) { return &textureOf(m, s).transform.scale[0]; }, slot, layer});
    }
    return out;
}
#undef CANDELA_FACTOR
#undef CANDELA_SCALAR

const std::vector<MaterialField>& materialTable() {
    static const std::vector<MaterialField> table = makeMaterialFields();
    return table;
}

const std::vector<AnimatedField<Light>>& lightTable() {
    static const std::vector<AnimatedField<Light>> table = {
        {"/color", 3, 0.0f, kMax, [](Light& l, int) { return &l.color[0]; }},
        {"/intensity", 1, 0.0f, kMax, [](Light& l, int) { return &l.intensity; }},
        {"/range", 1, 0.0f, kMax, [](Light& l, int) { return &l.range; }},  // 0: infinite
        {"/spot/innerConeAngle", 1, 0.0f, kHalfPi, [](Light& l, int) { return &l.innerConeAngle; }},
        {"/spot/outerConeAngle", 1, 1e-4f, kHalfPi, [](Light& l, int) { return &l.outerConeAngle; }},
    };
    return table;
}

const std::vector<AnimatedField<Camera>>& cameraTable() {
    static const std::vector<AnimatedField<Camera>> table = {
        {"/perspective/yfov", 1, 1e-4f, kPi - 1e-4f, [](Camera& c, int) { return &c.yfov; }},
        {"/perspective/aspectRatio", 1, 0.0f, kMax, [](Camera& c, int) { return &c.aspectRatio; }},  // 0: the viewport's
        {"/perspective/znear", 1, 1e-6f, kMax, [](Camera& c, int) { return &c.znear; }},
        {"/perspective/zfar", 1, 0.0f, kMax, [](Camera& c, int) { return &c.zfar; }},  // 0: infinite
        {"/orthographic/xmag", 1, 1e-6f, kMax, [](Camera& c, int) { return &c.xmag; }},
        {"/orthographic/ymag", 1, 1e-6f, kMax, [](Camera& c, int) { return &c.ymag; }},
        {"/orthographic/znear", 1, 0.0f, kMax, [](Camera& c, int) { return &c.znear; }},
        {"/orthographic/zfar", 1, 0.0f, kMax, [](Camera& c, int) { return &c.zfar; }},
    };
    return table;
}

// The row of `table` whose suffix is `suffix`, by a map built once per table.
template <class T>
std::optional<uint16_t> rowOf(const std::vector<AnimatedField<T>>& table, const std::string& suffix) {
    static const std::unordered_map<std::string, uint16_t> rows = [&] {
        std::unordered_map<std::string, uint16_t> out;
        for (size_t i = 0; i < table.size(); ++i) out.emplace(table[i].suffix, uint16_t(i));
        return out;
    }();
    const auto it = rows.find(suffix);
    return it == rows.end() ? std::nullopt : std::optional(it->second);
}

template <class T>
void write(const std::vector<AnimatedField<T>>& table, T& object, uint16_t field, std::span<const float> values) {
    if (field >= table.size() || values.size() != table[field].width)
        throw InternalError("animated property: field " + std::to_string(field) + " with " + std::to_string(values.size()) +
                            " values does not fit its table");
    const AnimatedField<T>& f = table[field];
    float* out = f.locate(object, f.slot);
    for (size_t c = 0; c < values.size(); ++c) out[c] = std::clamp(values[c], f.lo, f.hi);
}

// The tokens of an RFC 6901 pointer, decoded ("~1" is '/', "~0" is '~'); nullopt when it is not
// one. A decoded token holding '/' or '~' names a JSON key with that character, which no supported
// pointer has: it is refused here, so that joining the tokens again cannot make a false match.
std::optional<std::vector<std::string>> tokens(std::string_view pointer) {
    if (pointer.empty() || pointer[0] != '/') return std::nullopt;
    std::vector<std::string> out(1);
    for (size_t i = 1; i < pointer.size(); ++i) {
        if (pointer[i] == '/') {
            out.emplace_back();
            continue;
        }
        if (pointer[i] != '~') {
            out.back() += pointer[i];
            continue;
        }
        if (i + 1 >= pointer.size() || (pointer[i + 1] != '0' && pointer[i + 1] != '1')) return std::nullopt;
        out.back() += pointer[++i] == '0' ? '~' : '/';
    }
    for (const std::string& token : out)
        if (token.find_first_of("/~") != std::string::npos) return std::nullopt;
    return out;
}

// An array index token: "0" or digits without a leading zero, below 2^31.
std::optional<uint32_t> indexOf(const std::string& token) {
    if (token.empty() || (token.size() > 1 && token[0] == '0')) return std::nullopt;
    uint32_t value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || value > uint32_t(INT32_MAX)) return std::nullopt;
    return value;
}

// "/" + tokens[first…] joined by "/".
std::string suffixOf(const std::vector<std::string>& t, size_t first) {
    std::string out;
    for (size_t i = first; i < t.size(); ++i) out += "/" + t[i];
    return out;
}

// The node properties a pointer names after "/nodes/{}" (weights/{k} aside).
constexpr std::pair<std::string_view, animation::AnimatedProperty> kNodeProperties[] = {
    {"/translation", animation::AnimatedProperty::Translation},
    {"/rotation", animation::AnimatedProperty::Rotation},
    {"/scale", animation::AnimatedProperty::Scale},
    {"/weights", animation::AnimatedProperty::Weights},
    {"/extensions/KHR_node_visibility/visible", animation::AnimatedProperty::Visibility},
};

}  // namespace

std::span<const AnimatedField<Material>> materialFields() { return materialTable(); }
std::span<const AnimatedField<Light>> lightFields() { return lightTable(); }
std::span<const AnimatedField<Camera>> cameraFields() { return cameraTable(); }

std::string texturePointer(int slot) {
    if (slot < CANDELA_TEX_COUNT) return cat(kCoreTextureParents[slot], "/") + kCoreTextureSlots[slot].sampler;
    const int layer = slot - CANDELA_TEX_COUNT;
    return cat(kLayerTextureParents[layer], "/") + kLayerTextureSlots[layer].sampler;
}

std::optional<PointerTarget> parsePointer(std::string_view pointer) {
    const std::optional<std::vector<std::string>> parsed = tokens(pointer);
    if (!parsed || parsed->size() < 3) return std::nullopt;
    const std::vector<std::string>& t = *parsed;
    PointerTarget out;
    // /extensions/KHR_lights_punctual/lights/{}/…
    if (t[0] == "extensions") {
        if (t.size() < 5 || t[1] != "KHR_lights_punctual" || t[2] != "lights") return std::nullopt;
        const std::optional<uint32_t> index = indexOf(t[3]);
        const std::optional<uint16_t> field = index ? rowOf(lightTable(), suffixOf(t, 4)) : std::nullopt;
        if (!field) return std::nullopt;
        return PointerTarget{.kind = PointerKind::Light, .index = *index, .field = *field};
    }
    const std::optional<uint32_t> index = indexOf(t[1]);
    if (!index) return std::nullopt;
    out.index = *index;
    const std::string suffix = suffixOf(t, 2);
    if (t[0] == "nodes" || t[0] == "meshes") {
        out.kind = t[0] == "nodes" ? PointerKind::Node : PointerKind::Mesh;
        if (t.size() == 4 && t[2] == "weights") {
            const std::optional<uint32_t> element = indexOf(t[3]);
            if (!element) return std::nullopt;
            out.property = animation::AnimatedProperty::Weight;
            out.element = *element;
            return out;
        }
        for (const auto& [name, property] : kNodeProperties)
            if (suffix == name && (out.kind == PointerKind::Node || property == animation::AnimatedProperty::Weights)) {
                out.property = property;
                return out;
            }
        return std::nullopt;
    }
    std::optional<uint16_t> field;
    if (t[0] == "materials") out.kind = PointerKind::Material, field = rowOf(materialTable(), suffix);
    else if (t[0] == "cameras") out.kind = PointerKind::Camera, field = rowOf(cameraTable(), suffix);
    if (!field) return std::nullopt;
    out.field = *field;
    return out;
}

std::string pointerOf(const PointerTarget& target) {
    const std::string index = std::to_string(target.index);
    switch (target.kind) {
        case PointerKind::Node:
        case PointerKind::Mesh: {
            std::string out = (target.kind == PointerKind::Node ? "/nodes/" : "/meshes/") + index;
            if (target.property == animation::AnimatedProperty::Weight) return out + "/weights/" + std::to_string(target.element);
            for (const auto& [name, property] : kNodeProperties)
                if (property == target.property) return out + std::string(name);
            return out;
        }
        case PointerKind::Material: return "/materials/" + index + materialTable().at(target.field).suffix;
        case PointerKind::Light: return "/extensions/KHR_lights_punctual/lights/" + index + lightTable().at(target.field).suffix;
        case PointerKind::Camera: return "/cameras/" + index + cameraTable().at(target.field).suffix;
    }
    return {};
}

uint32_t pointerWidth(const PointerTarget& target) {
    switch (target.kind) {
        case PointerKind::Node:
        case PointerKind::Mesh:
            switch (target.property) {
                case animation::AnimatedProperty::Translation:
                case animation::AnimatedProperty::Scale: return 3;
                case animation::AnimatedProperty::Rotation: return 4;
                case animation::AnimatedProperty::Weights: return 0;
                default: return 1;
            }
        case PointerKind::Material: return materialTable().at(target.field).width;
        case PointerKind::Light: return lightTable().at(target.field).width;
        case PointerKind::Camera: return cameraTable().at(target.field).width;
    }
    return 0;
}

void writeMaterial(Material& material, uint16_t field, std::span<const float> values) {
    write(materialTable(), material, field, values);
}

void writeLight(Light& light, uint16_t field, std::span<const float> values) {
    write(lightTable(), light, field, values);
    // The extension's 0 ≤ inner < outer ≤ π/2, as the loader keeps it.
    light.innerConeAngle = std::min(light.innerConeAngle, light.outerConeAngle * 0.9999f);
}

void writeCamera(Camera& camera, uint16_t field, std::span<const float> values) {
    write(cameraTable(), camera, field, values);
    // A finite far plane stays beyond the near one (a projection needs zfar > znear).
    if (camera.zfar > 0.0f && !(camera.zfar > camera.znear))
        camera.zfar = camera.znear + std::max(camera.znear * 1e-3f, 1e-6f);
}

uint32_t layersAnimationMayNeed(const Material& material, std::span<const uint16_t> fields) {
    Material probe = material;
    probe.animatedLayers = 0;
    for (uint16_t field : fields) {
        const MaterialField& f = materialTable().at(field);
        if (!f.switchesOn) continue;
        float* out = f.locate(probe, f.slot);
        std::fill(out, out + f.width, *f.switchesOn);
    }
    return probe.layers();
}

}  // namespace candela::scene
