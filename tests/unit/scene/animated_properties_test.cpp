// KHR_animation_pointer's targets in the scene model (scene/animated_properties.h): every supported
// pointer parses to its field and prints back the same; the Object Model's templates Candela has a
// property for parse, the others do not; values are written where they belong, clamped; a factor
// animated from 0 asks for its layer.
#include "scene/animated_properties.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace candela::scene {
namespace {

// Every pointer the tables and node templates make, with index 7 (and weight 2).
std::vector<PointerTarget> everyTarget() {
    std::vector<PointerTarget> out;
    for (PointerKind kind : {PointerKind::Node, PointerKind::Mesh})
        for (animation::AnimatedProperty p : {animation::AnimatedProperty::Translation, animation::AnimatedProperty::Rotation, animation::AnimatedProperty::Scale,
                                   animation::AnimatedProperty::Weights, animation::AnimatedProperty::Weight, animation::AnimatedProperty::Visibility})
            if (kind == PointerKind::Node || p == animation::AnimatedProperty::Weights || p == animation::AnimatedProperty::Weight)
                out.push_back({.kind = kind, .index = 7, .property = p, .element = p == animation::AnimatedProperty::Weight ? 2u : 0u});
    for (uint16_t f = 0; f < materialFields().size(); ++f) out.push_back({.kind = PointerKind::Material, .index = 7, .field = f});
    for (uint16_t f = 0; f < lightFields().size(); ++f) out.push_back({.kind = PointerKind::Light, .index = 7, .field = f});
    for (uint16_t f = 0; f < cameraFields().size(); ++f) out.push_back({.kind = PointerKind::Camera, .index = 7, .field = f});
    return out;
}

TEST(AnimatedProperties, EverySupportedPointerRoundTrips) {
    std::set<std::string> seen;
    for (const PointerTarget& target : everyTarget()) {
        const std::string pointer = pointerOf(target);
        EXPECT_TRUE(seen.insert(pointer).second) << "twice: " << pointer;
        const std::optional<PointerTarget> parsed = parsePointer(pointer);
        ASSERT_TRUE(parsed.has_value()) << pointer;
        EXPECT_EQ(*parsed, target) << pointer;
    }
    // 8 core factors and 21 of the layers, and offset, rotation and scale of 19 texture slots.
    EXPECT_EQ(materialFields().size(), 8u + 21u + 3u * (CANDELA_TEX_COUNT + CANDELA_LAYER_TEX_COUNT));
    EXPECT_EQ(lightFields().size(), 5u);
    EXPECT_EQ(cameraFields().size(), 8u);
}

// Pointers as the glTF Asset Object Model and the extensions write them, with their widths.
TEST(AnimatedProperties, TheObjectModelsTemplatesParse) {
    const std::pair<const char*, uint32_t> pointers[] = {
        {"/nodes/0/translation", 3},
        {"/nodes/12/rotation", 4},
        {"/nodes/3/scale", 3},
        {"/nodes/3/weights", 0},
        {"/nodes/3/weights/1", 1},
        {"/nodes/5/extensions/KHR_node_visibility/visible", 1},
        {"/meshes/2/weights", 0},
        {"/meshes/2/weights/0", 1},
        {"/cameras/0/perspective/yfov", 1},
        {"/cameras/0/perspective/aspectRatio", 1},
        {"/cameras/0/orthographic/xmag", 1},
        {"/cameras/1/orthographic/zfar", 1},
        {"/materials/0/alphaCutoff", 1},
        {"/materials/0/emissiveFactor", 3},
        {"/materials/0/normalTexture/scale", 1},
        {"/materials/0/occlusionTexture/strength", 1},
        {"/materials/0/pbrMetallicRoughness/baseColorFactor", 4},
        {"/materials/0/pbrMetallicRoughness/metallicFactor", 1},
        {"/materials/0/pbrMetallicRoughness/roughnessFactor", 1},
        {"/materials/0/normalTexture/extensions/KHR_texture_transform/offset", 2},
        {"/materials/0/occlusionTexture/extensions/KHR_texture_transform/rotation", 1},
        {"/materials/0/emissiveTexture/extensions/KHR_texture_transform/scale", 2},
        {"/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/offset", 2},
        {"/materials/0/pbrMetallicRoughness/metallicRoughnessTexture/extensions/KHR_texture_transform/scale", 2},
        {"/extensions/KHR_lights_punctual/lights/0/color", 3},
        {"/extensions/KHR_lights_punctual/lights/0/intensity", 1},
        {"/extensions/KHR_lights_punctual/lights/0/range", 1},
        {"/extensions/KHR_lights_punctual/lights/0/spot/innerConeAngle", 1},
        {"/extensions/KHR_lights_punctual/lights/0/spot/outerConeAngle", 1},
        {"/materials/0/extensions/KHR_materials_anisotropy/anisotropyStrength", 1},
        {"/materials/0/extensions/KHR_materials_anisotropy/anisotropyRotation", 1},
        {"/materials/0/extensions/KHR_materials_anisotropy/anisotropyTexture/extensions/KHR_texture_transform/rotation", 1},
        {"/materials/0/extensions/KHR_materials_clearcoat/clearcoatFactor", 1},
        {"/materials/0/extensions/KHR_materials_clearcoat/clearcoatRoughnessFactor", 1},
        {"/materials/0/extensions/KHR_materials_clearcoat/clearcoatNormalTexture/scale", 1},
        {"/materials/0/extensions/KHR_materials_clearcoat/clearcoatTexture/extensions/KHR_texture_transform/offset", 2},
        {"/materials/0/extensions/KHR_materials_clearcoat/clearcoatNormalTexture/extensions/KHR_texture_transform/scale", 2},
        {"/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength", 1},
        {"/materials/0/extensions/KHR_materials_ior/ior", 1},
        {"/materials/0/extensions/KHR_materials_iridescence/iridescenceFactor", 1},
        {"/materials/0/extensions/KHR_materials_iridescence/iridescenceIor", 1},
        {"/materials/0/extensions/KHR_materials_iridescence/iridescenceThicknessMinimum", 1},
        {"/materials/0/extensions/KHR_materials_iridescence/iridescenceThicknessMaximum", 1},
        {"/materials/0/extensions/KHR_materials_iridescence/iridescenceThicknessTexture/extensions/KHR_texture_transform/offset", 2},
        {"/materials/0/extensions/KHR_materials_sheen/sheenColorFactor", 3},
        {"/materials/0/extensions/KHR_materials_sheen/sheenRoughnessFactor", 1},
        {"/materials/0/extensions/KHR_materials_sheen/sheenRoughnessTexture/extensions/KHR_texture_transform/scale", 2},
        {"/materials/0/extensions/KHR_materials_specular/specularFactor", 1},
        {"/materials/0/extensions/KHR_materials_specular/specularColorFactor", 3},
        {"/materials/0/extensions/KHR_materials_specular/specularColorTexture/extensions/KHR_texture_transform/rotation", 1},
        {"/materials/0/extensions/KHR_materials_transmission/transmissionFactor", 1},
        {"/materials/0/extensions/KHR_materials_transmission/transmissionTexture/extensions/KHR_texture_transform/offset", 2},
        {"/materials/0/extensions/KHR_materials_volume/thicknessFactor", 1},
        {"/materials/0/extensions/KHR_materials_volume/attenuationDistance", 1},
        {"/materials/0/extensions/KHR_materials_volume/attenuationColor", 3},
        {"/materials/0/extensions/KHR_materials_volume/thicknessTexture/extensions/KHR_texture_transform/scale", 2},
        {"/materials/0/extensions/KHR_materials_diffuse_transmission/diffuseTransmissionFactor", 1},
        {"/materials/0/extensions/KHR_materials_diffuse_transmission/diffuseTransmissionColorFactor", 3},
        {"/materials/0/extensions/KHR_materials_diffuse_transmission/diffuseTransmissionTexture/extensions/KHR_texture_transform/offset", 2},
        {"/materials/0/extensions/KHR_materials_diffuse_transmission/diffuseTransmissionColorTexture/extensions/KHR_texture_transform/rotation", 1},
        {"/materials/0/extensions/KHR_materials_dispersion/dispersion", 1},
    };
    for (const auto& [pointer, width] : pointers) {
        const std::optional<PointerTarget> target = parsePointer(pointer);
        ASSERT_TRUE(target.has_value()) << pointer;
        EXPECT_EQ(pointerWidth(*target), width) << pointer;
        EXPECT_EQ(pointerOf(*target), pointer);
    }
}

// Templates Candela has no property for, pointers to components, and what RFC 6901 refuses or
// decodes to another key.
TEST(AnimatedProperties, OtherPointersDoNotParse) {
    for (const char* pointer : {
             "/materials/0/extensions/KHR_materials_volume_scatter/multiscatterColor",  // no volume scattering in Candela
             "/nodes/0/extensions/EXT_lights_ies/multiplier",
             "/extensions/EXT_lights_image_based/lights/0/intensity",
             "/nodes/0/matrix", "/nodes/0/globalMatrix", "/nodes.length", "/animations.length",
             "/materials/0/foo", "/materials/0/pbrMetallicRoughness/baseColorFactor/0",  // a component
             "/materials/0/pbrMetallicRoughness", "/materials/0", "/materials", "", "/", "materials/0/alphaCutoff",
             "/materials/00/alphaCutoff", "/materials/-1/alphaCutoff", "/materials/x/alphaCutoff",
             "/materials/2147483648/alphaCutoff",                                 // beyond 2^31 − 1
             "/materials/0/pbrMetallicRoughness~1baseColorFactor",                // one key "pbrMetallicRoughness/baseColorFactor"
             "/materials/0/alpha~0Cutoff", "/materials/0/alphaCutoff~", "/materials/0/alphaCutoff~2",
             "/cameras/0/perspective/xmag", "/extensions/KHR_lights_punctual/lights/0/spot",
             "/extensions/KHR_lights_punctual/0/color", "/meshes/0/translation",
         })
        EXPECT_FALSE(parsePointer(pointer).has_value()) << pointer;
    EXPECT_TRUE(parsePointer("/materials/2147483647/alphaCutoff").has_value());
}

TEST(AnimatedProperties, ValuesGoWhereTheyBelongClamped) {
    Material m;
    const auto field = [](const char* pointer) { return parsePointer(pointer)->field; };
    const float color[4] = {2.0f, -1.0f, 0.25f, 1.0f};
    writeMaterial(m, field("/materials/0/pbrMetallicRoughness/baseColorFactor"), color);
    EXPECT_EQ(m.baseColorFactor, glm::vec4(1.0f, 0.0f, 0.25f, 1.0f));
    const float offset[2] = {0.5f, -3.0f}, rotation[1] = {1.25f};
    writeMaterial(m, field("/materials/0/extensions/KHR_materials_sheen/sheenRoughnessTexture/extensions/KHR_texture_transform/offset"),
                  offset);
    writeMaterial(m, field("/materials/0/emissiveTexture/extensions/KHR_texture_transform/rotation"), rotation);
    EXPECT_EQ(m.sheenRoughness.transform.offset, glm::vec2(0.5f, -3.0f));
    EXPECT_EQ(m.emissive.transform.rotation, 1.25f);
    EXPECT_TRUE(m.sheenColor.transform.identity());
    EXPECT_TRUE(m.baseColor.transform.identity());
    EXPECT_TRUE(materialFields()[field("/materials/0/extensions/KHR_materials_sheen/sheenRoughnessTexture/extensions/KHR_texture_transform/offset")].layerData);
    EXPECT_FALSE(materialFields()[field("/materials/0/emissiveTexture/extensions/KHR_texture_transform/rotation")].layerData);
    const float ior[1] = {0.5f};
    writeMaterial(m, field("/materials/0/extensions/KHR_materials_ior/ior"), ior);
    EXPECT_EQ(m.ior, 1.0f);

    Light light;
    const float outer[1] = {3.0f}, inner[1] = {2.0f};
    writeLight(light, parsePointer("/extensions/KHR_lights_punctual/lights/0/spot/innerConeAngle")->field, inner);
    writeLight(light, parsePointer("/extensions/KHR_lights_punctual/lights/0/spot/outerConeAngle")->field, outer);
    EXPECT_FLOAT_EQ(light.outerConeAngle, 1.57079632679f);  // π/2 at most
    EXPECT_LT(light.innerConeAngle, light.outerConeAngle);

    Camera camera;
    camera.znear = 1.0f;
    const float zfar[1] = {0.5f}, yfov[1] = {0.5f};
    writeCamera(camera, parsePointer("/cameras/0/perspective/zfar")->field, zfar);
    EXPECT_GT(camera.zfar, camera.znear);
    writeCamera(camera, parsePointer("/cameras/0/perspective/yfov")->field, yfov);
    EXPECT_EQ(camera.yfov, 0.5f);
}

TEST(AnimatedProperties, AFactorAnimatedFromZeroAsksForItsLayer) {
    const auto fields = [](std::initializer_list<const char*> pointers) {
        std::vector<uint16_t> out;
        for (const char* p : pointers) out.push_back(parsePointer(p)->field);
        return out;
    };
    Material m;
    EXPECT_EQ(m.layers(), 0u);
    EXPECT_EQ(layersAnimationMayNeed(m, fields({"/materials/0/pbrMetallicRoughness/baseColorFactor"})), 0u);
    EXPECT_EQ(layersAnimationMayNeed(m, fields({"/materials/0/extensions/KHR_materials_clearcoat/clearcoatFactor"})),
              uint32_t(kLayerClearcoat));
    m.clearcoatNormal.image = 0;  // with its own normal map, the coat needs that too
    EXPECT_EQ(layersAnimationMayNeed(m, fields({"/materials/0/extensions/KHR_materials_clearcoat/clearcoatFactor"})),
              uint32_t(kLayerClearcoat | kLayerClearcoatNormal));
    m = Material{};
    m.thicknessFactor = 1.0f;  // a volume beneath a transmission animated from 0
    EXPECT_EQ(layersAnimationMayNeed(m, fields({"/materials/0/extensions/KHR_materials_transmission/transmissionFactor"})),
              uint32_t(kLayerTransmission | kLayerVolume));
    // A diffuse transmission animated from 0 brings the volume beneath it; a dispersion only where the
    // volume refracts (a transmission).
    EXPECT_EQ(layersAnimationMayNeed(m, fields({"/materials/0/extensions/KHR_materials_diffuse_transmission/diffuseTransmissionFactor"})),
              uint32_t(kLayerDiffuseTransmission | kLayerVolume));
    EXPECT_EQ(layersAnimationMayNeed(m, fields({"/materials/0/extensions/KHR_materials_dispersion/dispersion"})), 0u);
    m.transmissionFactor = 1.0f;
    EXPECT_EQ(layersAnimationMayNeed(m, fields({"/materials/0/extensions/KHR_materials_dispersion/dispersion"})),
              uint32_t(kLayerTransmission | kLayerVolume | kLayerDispersion));
    EXPECT_EQ(layersAnimationMayNeed(Material{}, fields({"/materials/0/extensions/KHR_materials_sheen/sheenColorFactor",
                                                         "/materials/0/extensions/KHR_materials_ior/ior"})),
              uint32_t(kLayerSheen | kLayerSpecular));
    // Stored, the layers count as the material's.
    Material animated;
    animated.animatedLayers = kLayerAnisotropy;
    EXPECT_EQ(animated.layers(), uint32_t(kLayerAnisotropy));
    EXPECT_TRUE(animated.tangentSpaceMap().has_value());  // the anisotropy direction needs tangents
}

}  // namespace
}  // namespace candela::scene
