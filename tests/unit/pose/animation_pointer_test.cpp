// KHR_animation_pointer read by the loader and played by ScenePose: node transforms through a
// pointer equal the core channels; material factors, texture transforms, light and camera
// properties take the sampled values at a time; unsupported pointers warn once each; a factor
// animated from 0 keeps its layer from the start.
#include "animation_pointer_util.h"

#include "pose/scene_pose.h"

#include <algorithm>
#include <cmath>

namespace candela::pose::test::animation_pointer_test {
namespace {

// The lines of `warnings` containing `fragment`.
size_t linesWith(const std::vector<std::string>& warnings, const std::string& fragment) {
    return size_t(std::count_if(warnings.begin(), warnings.end(),
                                [&](const std::string& w) { return w.find(fragment) != std::string::npos; }));
}

// The canonical triangle with material 0 (baseColorFactor red) on it.
assets::test::GltfBuilder redTriangle() {
    assets::test::GltfBuilder b;
    b.addTriangle();
    b.doc["materials"] = assets::test::Json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    return b;
}

TEST(AnimationPointer, NodeTransformsThroughPointersEqualTheCoreChannels) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = redTriangle();
    const std::vector<float> times = {0, 1, 2};
    const std::vector<float> t = {0, 0, 0, 1, 2, 3, -1, 0, 4};
    const std::vector<float> r = {0, 0, 0, 1, 0, 0.7071068f, 0, 0.7071068f, 0, 1, 0, 0};
    const std::vector<float> s = {1, 1, 1, 2, 1, 0.5f, 1, 3, 1};
    // Animation 0: core channels; animation 1: the same samplers' data through pointers.
    const int input = b.addFloats(times, "SCALAR", 1);
    assets::test::Json core = {{"samplers", assets::test::Json::array()}, {"channels", assets::test::Json::array()}};
    for (const auto& [path, values, type] : {std::tuple{"translation", t, "VEC3"}, {"rotation", r, "VEC4"}, {"scale", s, "VEC3"}}) {
        core["samplers"].push_back({{"input", input}, {"output", b.addFloats(values, type, type == std::string("VEC4") ? 4 : 3)}});
        core["channels"].push_back({{"sampler", core["samplers"].size() - 1}, {"target", {{"node", 0}, {"path", path}}}});
    }
    b.doc["animations"].push_back(core);
    assets::test::addPointerAnimation(b, {{.pointer = "/nodes/0/translation", .times = times, .values = t, .type = "VEC3"},
                            {.pointer = "/nodes/0/rotation", .times = times, .values = r, .type = "VEC4"},
                            {.pointer = "/nodes/0/scale", .times = times, .values = s, .type = "VEC3"}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.animations.size(), 2u);
    EXPECT_EQ(scene.animations[1].channels.size(), 3u);
    EXPECT_TRUE(scene.animations[1].properties.empty());
    ScenePose corePose(scene, {0}), pointerPose(scene, {1});
    EXPECT_TRUE(pointerPose.movesNodes());
    for (double time : {0.0, 0.3, 1.0, 1.45, 2.0}) {
        corePose.evaluate(time, false);
        pointerPose.evaluate(time, false);
        EXPECT_EQ(pointerPose.draws()[0].world, corePose.draws()[0].world) << time;
        EXPECT_EQ(pointerPose.draws()[0].bounds.max, corePose.draws()[0].bounds.max) << time;
    }
    EXPECT_NE(pointerPose.draws()[0].world, scene.draws[0].world);
}

TEST(AnimationPointer, MaterialFactorsAndTextureTransformsAnimate) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = assets::test::texturedTriangle("", assets::test::smallPng());
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1, 0, 0, 1};
    const std::string texture = "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/";
    assets::test::addPointerAnimation(b, {{.pointer = "/materials/0/pbrMetallicRoughness/baseColorFactor", .times = {0, 1},
                             .values = {1, 0, 0, 1, 0, 0, 1, 1}, .type = "VEC4"},
                            {.pointer = "/materials/0/pbrMetallicRoughness/roughnessFactor", .times = {0, 1}, .values = {0.2f, 0.6f},
                             .interpolation = "STEP"},
                            {.pointer = texture + "offset", .times = {0, 2}, .values = {0, 0, 1, -2}, .type = "VEC2"},
                            {.pointer = texture + "rotation", .times = {0, 2}, .values = {0, 1}}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.animations[0].properties.size(), 4u);
    EXPECT_NEAR(scene.animations[0].duration, 2.0, 1e-9);
    ScenePose pose(scene, {0});
    EXPECT_TRUE(pose.animated());
    EXPECT_FALSE(pose.movesNodes());
    EXPECT_EQ(pose.animatedMaterials(), std::vector<uint32_t>{0});
    EXPECT_FALSE(pose.animatesMaterialLayers());
    pose.evaluate(0.25, false);
    const scene::Material& m = pose.materials()[0];
    EXPECT_NEAR(m.baseColorFactor.r, 0.75f, 1e-6f);
    EXPECT_NEAR(m.baseColorFactor.b, 0.25f, 1e-6f);
    EXPECT_EQ(m.baseColorFactor.a, 1.0f);
    EXPECT_EQ(m.roughnessFactor, 0.2f);  // STEP
    EXPECT_NEAR(m.baseColor.transform.offset.x, 0.125f, 1e-6f);
    EXPECT_NEAR(m.baseColor.transform.offset.y, -0.25f, 1e-6f);
    EXPECT_NEAR(m.baseColor.transform.rotation, 0.125f, 1e-6f);
    EXPECT_EQ(m.baseColor.transform.scale, glm::vec2(1.0f));
    pose.evaluate(1.5, false);
    EXPECT_EQ(pose.materials()[0].roughnessFactor, 0.6f);
    EXPECT_EQ(pose.materials()[0].baseColorFactor, glm::vec4(0, 0, 1, 1));
    // The scene keeps its rest values.
    EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(1, 0, 0, 1));
    EXPECT_TRUE(scene.materials[0].baseColor.transform.identity());
}

TEST(AnimationPointer, LayerFactorsAndLayerTextureTransformsAnimate) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = redTriangle();
    b.doc["materials"][0]["extensions"]["KHR_materials_sheen"] = {{"sheenColorFactor", {1, 1, 1}}};
    assets::test::addPointerAnimation(b, {{.pointer = "/materials/0/extensions/KHR_materials_sheen/sheenRoughnessFactor", .times = {0, 1},
                             .values = {0, 1}},
                            {.pointer = "/materials/0/extensions/KHR_materials_sheen/sheenColorTexture/extensions/"
                                        "KHR_texture_transform/scale",
                             .times = {0, 1}, .values = {1, 1, 3, 5}, .type = "VEC2"}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ScenePose pose(scene, {0});
    EXPECT_TRUE(pose.animatesMaterialLayers());
    pose.evaluate(0.5, false);
    EXPECT_NEAR(pose.materials()[0].sheenRoughnessFactor, 0.5f, 1e-6f);
    EXPECT_EQ(pose.materials()[0].sheenColor.transform.scale, glm::vec2(2, 3));
}

// Two nodes share glTF light 0 (a spot): both Scene lights follow its animated properties.
TEST(AnimationPointer, LightPropertiesAnimate) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = redTriangle();
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] =
        assets::test::Json::array({{{"type", "spot"}, {"intensity", 10}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.5}}}}});
    assets::test::useExtension(b, "KHR_lights_punctual");
    const int a = b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    const int c = b.addNode({{"translation", {0, 1, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.doc["scenes"][0]["nodes"].push_back(a);
    b.doc["scenes"][0]["nodes"].push_back(c);
    const std::string light = "/extensions/KHR_lights_punctual/lights/0/";
    assets::test::addPointerAnimation(b, {{.pointer = light + "intensity", .times = {0, 1}, .values = {10, 30}},
                            {.pointer = light + "color", .times = {0, 1}, .values = {1, 1, 1, 0, 0.5f, 1}, .type = "VEC3"},
                            {.pointer = light + "spot/outerConeAngle", .times = {0, 1}, .values = {0.5f, 1.0f}},
                            {.pointer = light + "spot/innerConeAngle", .times = {0, 1}, .values = {0.1f, 0.3f}},
                            {.pointer = light + "range", .times = {0, 1}, .values = {0, 8}}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].source, 0);
    EXPECT_EQ(scene.lights[1].source, 0);
    ScenePose pose(scene, {0});
    EXPECT_EQ(pose.animatedLightProperties(), (std::vector<uint32_t>{0, 1}));
    EXPECT_TRUE(pose.animatedLights().empty());  // nothing moves them
    pose.evaluate(0.5, false);
    for (const scene::Light& l : pose.lights()) {
        EXPECT_NEAR(l.intensity, 20.0f, 1e-5f);
        EXPECT_NEAR(l.color.r, 0.5f, 1e-6f);
        EXPECT_NEAR(l.color.g, 0.75f, 1e-6f);
        EXPECT_NEAR(l.outerConeAngle, 0.75f, 1e-6f);
        EXPECT_NEAR(l.innerConeAngle, 0.2f, 1e-6f);
        EXPECT_NEAR(l.range, 4.0f, 1e-6f);
    }
    EXPECT_EQ(pose.lights()[1].position, glm::vec3(0, 1, 0));  // placement untouched
}

TEST(AnimationPointer, CameraProjectionAnimates) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = redTriangle();
    b.doc["cameras"] = assets::test::Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}},
                                    {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0}, {"zfar", 10}}}}});
    b.doc["scenes"][0]["nodes"].push_back(b.addNode({{"camera", 0}, {"translation", {0, 0, 3}}}));
    b.doc["scenes"][0]["nodes"].push_back(b.addNode({{"camera", 1}, {"translation", {0, 0, 3}}}));
    assets::test::addPointerAnimation(b, {{.pointer = "/cameras/0/perspective/yfov", .times = {0, 2}, .values = {0.5f, 1.5f}},
                            {.pointer = "/cameras/1/orthographic/ymag", .times = {0, 2}, .values = {1, 3}},
                            {.pointer = "/cameras/0/orthographic/xmag", .times = {0, 2}, .values = {1, 3}}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    // The orthographic property of the perspective camera is left out, with a warning.
    ASSERT_EQ(scene.report.warnings.size(), 1u);
    EXPECT_NE(scene.report.warnings[0].find("pointer '/cameras/0/orthographic/xmag': camera 0 is perspective (ignored)"), std::string::npos)
        << scene.report.warnings[0];
    EXPECT_EQ(scene.animations[0].properties.size(), 2u);
    ASSERT_EQ(scene.cameras.size(), 2u);
    ScenePose pose(scene, {0});
    EXPECT_EQ(pose.animatedCameraProperties(), (std::vector<uint32_t>{0, 1}));
    pose.evaluate(0.5, false);
    EXPECT_NEAR(pose.cameras()[0].yfov, 0.75f, 1e-6f);
    EXPECT_NEAR(pose.cameras()[1].ymag, 1.5f, 1e-6f);
    EXPECT_EQ(pose.cameras()[1].xmag, 1.0f);
    EXPECT_EQ(scene.cameras[0].yfov, 0.5f);
}

TEST(AnimationPointer, MorphWeightsOfNodesAndMeshesAnimate) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int d0 = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    const int d1 = b.addFloats({1, 0, 0, 1, 0, 0, 1, 0, 0}, "VEC3", 3);
    const int mesh = b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 2}));
    b.doc["meshes"][size_t(mesh)]["primitives"][0]["targets"] = assets::test::Json::array({{{"POSITION", d0}}, {{"POSITION", d1}}});
    const int own = b.addNode({{"mesh", mesh}, {"weights", {0.5, 0.5}}});  // its own weights: the mesh's do not apply
    const int shared = b.addNode({{"mesh", mesh}});
    b.setScene({own, shared});
    assets::test::addPointerAnimation(b, {{.pointer = "/meshes/0/weights", .times = {0, 1}, .values = {0, 0, 1, 0.5f}},
                            {.pointer = "/nodes/0/weights/1", .times = {0, 1}, .values = {0.5f, 0}}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.animations[0].channels.size(), 2u);
    ScenePose pose(scene, {0});
    pose.evaluate(0.5, false);
    EXPECT_EQ(pose.nodes()[0].weights, (std::vector<float>{0.5f, 0.25f}));
    EXPECT_EQ(pose.nodes()[1].weights, (std::vector<float>{0.5f, 0.25f}));
}

TEST(AnimationPointer, AnUnsupportedPointerWarnsOncePerPointer) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = redTriangle();
    assets::test::addPointerAnimation(b, {{.pointer = "/materials/0/foo", .times = {0, 1}, .values = {0, 1}},
                            {.pointer = "/materials/0/foo", .times = {0, 1}, .values = {0, 1}},
                            {.pointer = "/materials/0/extensions/KHR_materials_volume_scatter/scatterAnisotropy", .times = {0, 1}, .values = {0, 1}},
                            {.pointer = "/materials/0/pbrMetallicRoughness/metallicFactor", .times = {0, 1}, .values = {0, 1}}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_EQ(linesWith(scene.report.warnings, "animation 0: pointer '/materials/0/foo' is not supported (ignored)"), 1u);
    EXPECT_EQ(linesWith(scene.report.warnings, "pointer '/materials/0/extensions/KHR_materials_volume_scatter/scatterAnisotropy' is not supported"), 1u);
    EXPECT_EQ(scene.report.warnings.size(), 2u);  // and none about the extension itself
    ASSERT_EQ(scene.animations[0].properties.size(), 1u);  // the metallic factor's
}

TEST(AnimationPointer, AFactorAnimatedFromZeroKeepsItsLayer) {
    candela::test::TempDir dir;
    assets::test::GltfBuilder b = redTriangle();
    b.doc["materials"].push_back({{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0}}}}}});
    b.doc["materials"].push_back(assets::test::Json::object());  // no extension: the factor's default, 0
    assets::test::addPointerAnimation(b, {{.pointer = "/materials/1/extensions/KHR_materials_clearcoat/clearcoatFactor", .times = {0, 1}, .values = {0, 1}},
                            {.pointer = "/materials/2/extensions/KHR_materials_anisotropy/anisotropyStrength", .times = {0, 1},
                             .values = {0, 1}}});
    const scene::Scene scene = assets::loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    EXPECT_EQ(scene.materials[0].layers(), 0u);
    EXPECT_EQ(scene.materials[1].clearcoatFactor, 0.0f);
    EXPECT_EQ(scene.materials[1].animatedLayers, uint32_t(scene::kLayerClearcoat));
    EXPECT_EQ(scene.materials[1].layers(), uint32_t(scene::kLayerClearcoat));
    EXPECT_EQ(scene.materials[2].layers(), uint32_t(scene::kLayerAnisotropy));
    // The layer stays while the factor is 0 in the pose.
    ScenePose pose(scene, {0});
    pose.evaluate(0.0);
    EXPECT_EQ(pose.materials()[1].clearcoatFactor, 0.0f);
    EXPECT_EQ(pose.materials()[1].layers(), uint32_t(scene::kLayerClearcoat));
}

TEST(AnimationPointer, PointersNameWhatTheFileHas) {
    candela::test::TempDir dir;
    const auto error = [&](const std::string& pointer, const std::string& type = "SCALAR", std::vector<float> values = {0, 1}) {
        assets::test::GltfBuilder b = redTriangle();
        assets::test::addPointerAnimation(b, {{.pointer = pointer, .times = {0, 1}, .values = std::move(values), .type = type}});
        return assets::test::loadError(b.writeGltf(dir.path()));
    };
    EXPECT_NE(error("/materials/1/pbrMetallicRoughness/roughnessFactor").find(
                  "animation 0 channel 0: pointer '/materials/1/pbrMetallicRoughness/roughnessFactor': material 1 does not exist"),
              std::string::npos);
    EXPECT_NE(error("/extensions/KHR_lights_punctual/lights/0/intensity").find("KHR_lights_punctual light 0 does not exist"),
              std::string::npos);
    EXPECT_NE(error("/cameras/2/perspective/yfov").find("camera 2 does not exist"), std::string::npos);
    EXPECT_NE(error("/nodes/4/translation", "VEC3", {0, 0, 0, 1, 1, 1}).find("node 4 does not exist"), std::string::npos);
    EXPECT_NE(error("/nodes/0/weights").find("whose mesh has no morph targets"), std::string::npos);
    EXPECT_NE(error("/materials/0/emissiveFactor").find("takes VEC3 values, but sampler 0's output accessor 4 is SCALAR"),
              std::string::npos);
    EXPECT_EQ(error("/materials/0/emissiveFactor", "VEC3", {0, 0, 0, 1, 1, 1}), "");
}

}  // namespace
}  // namespace candela::pose::test::animation_pointer_test
