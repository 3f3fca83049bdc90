// The loader's KHR_materials_diffuse_transmission and KHR_materials_dispersion: factors, textures
// (channels and colour spaces), defaults, clamping with the warning the other layers give, and the
// layers a material pays for (Material::layers) — each on a tiny glTF written by the test itself.
// The malformed inputs are rows of gltf_bad_input_test.cpp.
#include "gltf_test_util.h"

#include <string>
#include <vector>

namespace candela::assets::test::gltf_transmission_layers_test {
namespace {

bool hasLine(const std::vector<std::string>& lines, const std::string& fragment) {
    for (const std::string& line : lines)
        if (line.find(fragment) != std::string::npos) return true;
    return false;
}

TEST(GltfFeatures, DiffuseTransmissionExtension) {
    // Factor (texture A, linear), colour (texture RGB, sRGB), the defaults (factor 0: no layer;
    // colour white), clamping, and a volume beneath it (no transmission needed).
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng());
    b.doc["extensionsUsed"] = {"KHR_materials_diffuse_transmission", "KHR_materials_volume"};
    b.doc["materials"] = Json::array({
        {{"extensions",
          {{"KHR_materials_diffuse_transmission",
            {{"diffuseTransmissionFactor", 0.25}, {"diffuseTransmissionTexture", {{"index", 0}}},
             {"diffuseTransmissionColorFactor", {1.0, 0.9, 0.85}}, {"diffuseTransmissionColorTexture", {{"index", 0}}}}}}}},
        {{"extensions", {{"KHR_materials_diffuse_transmission", Json::object()}}}},
        {{"extensions", {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 1}}},
                         {"KHR_materials_volume", {{"thicknessFactor", 0.5}, {"attenuationColor", {1.0, 0.5, 0.25}}}}}}},
        {{"extensions",
          {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 2}, {"diffuseTransmissionColorFactor", {-1, 0.5, 3}}}}}}}});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 4u);
    const scene::Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.diffuseTransmissionFactor, 0.25f);
    EXPECT_EQ(m.diffuseTransmissionColorFactor, glm::vec3(1.0f, 0.9f, 0.85f));
    ASSERT_TRUE(m.diffuseTransmission.present() && m.diffuseTransmissionColor.present());
    EXPECT_FALSE(scene.images.at(size_t(m.diffuseTransmission.image)).srgb);
    EXPECT_TRUE(scene.images.at(size_t(m.diffuseTransmissionColor.image)).srgb);
    EXPECT_EQ(m.layers(), uint32_t(scene::kLayerDiffuseTransmission));
    EXPECT_EQ(scene.materials[1].diffuseTransmissionColorFactor, glm::vec3(1.0f));
    EXPECT_EQ(scene.materials[1].layers(), 0u);  // factor 0
    EXPECT_EQ(scene.materials[2].layers(), uint32_t(scene::kLayerDiffuseTransmission | scene::kLayerVolume));
    EXPECT_FLOAT_EQ(scene.materials[3].diffuseTransmissionFactor, 1.0f);
    EXPECT_EQ(scene.materials[3].diffuseTransmissionColorFactor, glm::vec3(0.0f, 0.5f, 1.0f));
    EXPECT_TRUE(hasLine(scene.report.warnings, "diffuseTransmissionFactor 2 is outside [0, 1] (using 1)"));
    EXPECT_TRUE(hasLine(scene.report.warnings, "diffuseTransmissionColorFactor -1 is outside [0, 1] (using 0)"));
    EXPECT_TRUE(hasLine(scene.report.warnings, "diffuseTransmissionColorFactor 3 is outside [0, 1] (using 1)"));
    EXPECT_EQ(scene.report.warnings.size(), 3u);
}

TEST(GltfFeatures, DispersionExtension) {
    // The dispersion (20 / Abbe number, default 0: none) is a layer only beneath a transmitting
    // surface with a volume; without one it has nothing to refract (a note, not a warning: the
    // render is what the file asks for); a negative one is clamped to 0 with a warning; a large one
    // is kept.
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng());
    b.doc["extensionsUsed"] = {"KHR_materials_dispersion", "KHR_materials_transmission", "KHR_materials_volume"};
    const Json glass = {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}, {"KHR_materials_volume", {{"thicknessFactor", 1}}}};
    const auto with = [](Json extensions, Json dispersion) {
        extensions["KHR_materials_dispersion"] = dispersion;
        return Json{{"extensions", extensions}};
    };
    b.doc["materials"] = Json::array({with(glass, {{"dispersion", 0.33}}), with(glass, Json::object()),
                                      with({{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}, {{"dispersion", 1}}),
                                      with(glass, {{"dispersion", -0.5}}), with(glass, {{"dispersion", 100}})});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 5u);
    EXPECT_FLOAT_EQ(scene.materials[0].dispersion, 0.33f);
    EXPECT_EQ(scene.materials[0].layers(), uint32_t(scene::kLayerTransmission | scene::kLayerVolume | scene::kLayerDispersion));
    EXPECT_EQ(scene.materials[1].dispersion, 0.0f);
    EXPECT_EQ(scene.materials[1].layers(), uint32_t(scene::kLayerTransmission | scene::kLayerVolume));
    EXPECT_EQ(scene.materials[2].layers(), uint32_t(scene::kLayerTransmission));  // thin-walled: nothing to disperse
    EXPECT_TRUE(hasLine(scene.report.notes, "material 2 dispersion 1 has no effect without KHR_materials_transmission and a "
                                     "KHR_materials_volume thickness (thin-walled)"))
        << testing::PrintToString(scene.report.notes);
    EXPECT_EQ(scene.materials[3].dispersion, 0.0f);
    EXPECT_EQ(scene.materials[3].layers(), uint32_t(scene::kLayerTransmission | scene::kLayerVolume));
    EXPECT_FLOAT_EQ(scene.materials[4].dispersion, 100.0f);
    EXPECT_TRUE(hasLine(scene.report.warnings, "dispersion -0.5 is outside [0, inf] (using 0)"));
    EXPECT_EQ(scene.report.warnings.size(), 1u) << testing::PrintToString(scene.report.warnings);
}

}  // namespace
}  // namespace candela::assets::test::gltf_transmission_layers_test
