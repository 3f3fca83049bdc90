// Loads the Khronos sample models from ../shared/assets/models (each test skips when that folder is
// absent). Expected counts and values come from the models' JSON.
#include "gltf_test_util.h"

#include "geometry/tangents.h"
#include "scene/texture_transform.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <map>
#include <set>

namespace candela::assets::test {
namespace {

fs::path model(const std::string& name, const std::string& variant, const std::string& file) {
    return sharedModels() / name / variant / file;
}

void expectVec(const glm::vec3& actual, const glm::vec3& expected, float eps = 1e-6f) {
    EXPECT_NEAR(actual.x, expected.x, eps);
    EXPECT_NEAR(actual.y, expected.y, eps);
    EXPECT_NEAR(actual.z, expected.z, eps);
}

// Every vertex a draw references: unit tangent orthogonal to its (unit) normal, w = ±1.
void expectTangentFrames(const scene::Scene& scene, float orthoEps = 1e-4f) {
    size_t checked = 0;
    for (const scene::Draw& draw : scene.draws)
        for (uint32_t i = 0; i < draw.indexCount; ++i) {
            const scene::Vertex& v = scene.vertices[scene.indices[draw.firstIndex + i]];
            ASSERT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
            ASSERT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, orthoEps);
            ASSERT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f) << v.tangent.w;
            ++checked;
        }
    EXPECT_GT(checked, 0u);
}

TEST(GltfModels, BoxInAllThreeVariants) {
    REQUIRE_MODELS();
    const scene::Scene gltf = loadGltf(model("Box", "glTF", "Box.gltf"));
    const scene::Scene glb = loadGltf(model("Box", "glTF-Binary", "Box.glb"));
    const scene::Scene embedded = loadGltf(model("Box", "glTF-Embedded", "Box.gltf"));
    for (const scene::Scene* s : {&gltf, &glb, &embedded}) {
        EXPECT_EQ(s->vertices.size(), 24u);
        EXPECT_EQ(s->indices.size(), 36u);
        ASSERT_EQ(s->draws.size(), 1u);
        ASSERT_EQ(s->materials.size(), 1u);
        EXPECT_EQ(s->materials[0].name, "Red");
        EXPECT_EQ(s->materials[0].baseColorFactor, glm::vec4(0.8f, 0.0f, 0.0f, 1.0f));
        EXPECT_EQ(s->materials[0].metallicFactor, 0.0f);
        EXPECT_TRUE(s->report.warnings.empty());
        // The root's matrix turns +Y into −Z (Z-up to Y-up); the cube is ±0.5.
        expectVec(glm::vec3(s->draws[0].world * glm::vec4(0, 1, 0, 0)), {0, 0, -1});
        EXPECT_FALSE(s->draws[0].flipWinding);
        expectVec(s->bounds.min, glm::vec3(-0.5f));
        expectVec(s->bounds.max, glm::vec3(0.5f));
    }
    for (size_t i = 0; i < gltf.vertices.size(); ++i) {
        EXPECT_EQ(gltf.vertices[i].position, glb.vertices[i].position);
        EXPECT_EQ(gltf.vertices[i].normal, embedded.vertices[i].normal);
    }
    EXPECT_EQ(gltf.indices, glb.indices);
    EXPECT_EQ(gltf.indices, embedded.indices);
}

TEST(GltfModels, BoxTexturedInAllThreeVariants) {
    REQUIRE_MODELS();
    std::vector<scene::Scene> scenes;
    scenes.push_back(assets::loadGltf(model("BoxTextured", "glTF", "BoxTextured.gltf")));
    scenes.push_back(loadGltf(model("BoxTextured", "glTF-Binary", "BoxTextured.glb")));
    scenes.push_back(loadGltf(model("BoxTextured", "glTF-Embedded", "BoxTextured.gltf")));
    for (const scene::Scene& s : scenes) {
        ASSERT_EQ(s.images.size(), 1u);
        EXPECT_EQ(s.images[0].width, 256u);
        EXPECT_EQ(s.images[0].height, 256u);
        EXPECT_EQ(s.images[0].rgba8.size(), 256u * 256u * 4u);
        EXPECT_TRUE(s.images[0].srgb);
        EXPECT_EQ(s.images[0].rgba8, scenes[0].images[0].rgba8);  // same pixels from file, GLB and data URI
        ASSERT_EQ(s.samplers.size(), 1u);
        EXPECT_EQ(s.samplers[0].magFilter, scene::Filter::Linear);
        EXPECT_EQ(s.samplers[0].minFilter, scene::Filter::Nearest);  // NEAREST_MIPMAP_LINEAR
        EXPECT_EQ(s.samplers[0].mipFilter, scene::Filter::Linear);
        EXPECT_TRUE(s.samplers[0].mipmaps);
        const scene::Material& m = s.materials.at(0);
        EXPECT_EQ(m.baseColor.image, 0);
        EXPECT_EQ(m.baseColor.sampler, 0);
        EXPECT_FALSE(m.normal.present());
        EXPECT_EQ(s.vertices.size(), 24u);
        EXPECT_TRUE(s.report.warnings.empty());
    }
    EXPECT_EQ(scenes[0].images[0].name, "CesiumLogoFlat.png");
}

TEST(GltfModels, EverySampleModelLoadsWithAtMostThreeWarningLines) {
    // Warnings are for what makes the render differ from the file's intent, folded per kind
    // (docs/scenes.md lists each model's lines beside the glTF-Validator's report). Geometry
    // preparation is left out: it prints nothing and takes most of the time.
    REQUIRE_MODELS();
    size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(sharedModels())) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".gltf" && extension != ".glb") continue;
        ++files;
        const scene::Scene s = loadGltf(entry.path(), {.prepareGeometry = false});
        std::string lines;
        for (const std::string& w : s.report.warnings) lines += "\n  " + w;
        EXPECT_LE(s.report.warnings.size(), 3u) << entry.path() << lines;
    }
    EXPECT_GT(files, 50u);
}

TEST(GltfModels, Cameras) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("Cameras", "glTF", "Cameras.gltf"));
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_TRUE(s.cameras[0].perspective);
    EXPECT_FLOAT_EQ(s.cameras[0].yfov, 0.7f);
    EXPECT_FLOAT_EQ(s.cameras[0].aspectRatio, 1.0f);
    EXPECT_FLOAT_EQ(s.cameras[0].znear, 0.01f);
    EXPECT_FLOAT_EQ(s.cameras[0].zfar, 100.0f);
    EXPECT_FALSE(s.cameras[1].perspective);
    EXPECT_FLOAT_EQ(s.cameras[1].xmag, 1.0f);
    for (const scene::Camera& c : s.cameras) expectVec(glm::vec3(c.world[3]), {0.5f, 0.5f, 3.0f});
    // The quad has no normals: 2 flat triangles → 6 vertices, plus the default material.
    EXPECT_EQ(s.vertices.size(), 6u);
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].name, "default");
}

TEST(GltfModels, TriangleWithoutIndices) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("TriangleWithoutIndices", "glTF", "TriangleWithoutIndices.gltf"));
    EXPECT_EQ(s.indices, (std::vector<uint32_t>{0, 1, 2}));
    ASSERT_EQ(s.vertices.size(), 3u);
    for (const scene::Vertex& v : s.vertices) expectVec(v.normal, {0, 0, 1});
    expectVec(s.vertices[1].position, {1, 0, 0});
}

TEST(GltfModels, MeshPrimitiveModes) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("MeshPrimitiveModes", "glTF", "MeshPrimitiveModes.gltf"));
    // Seven primitives over the same hexagon: POINTS (7 points), LINES (6 lines), LINE_LOOP (7),
    // LINE_STRIP (6), TRIANGLES (6), the strip (6 indices → 4 triangles) and the fan (8 → 6).
    ASSERT_EQ(s.draws.size(), 7u);
    const std::vector<std::pair<scene::Topology, uint32_t>> expected = {
        {scene::Topology::Points, 7},     {scene::Topology::Lines, 12},     {scene::Topology::Lines, 14},
        {scene::Topology::Lines, 12},     {scene::Topology::Triangles, 18}, {scene::Topology::Triangles, 12},
        {scene::Topology::Triangles, 18}};
    for (size_t d = 0; d < expected.size(); ++d) {
        EXPECT_EQ(s.draws[d].topology, expected[d].first) << d;
        EXPECT_EQ(s.draws[d].indexCount, expected[d].second) << d;
        // No normals: points and lines unshaded, triangles flat (one vertex per corner, facing +Z).
        EXPECT_EQ(s.draws[d].unshaded, expected[d].first != scene::Topology::Triangles) << d;
    }
    EXPECT_EQ(s.vertices.size(), 4 * 7u + 48u);
    for (size_t d = 4; d < 7; ++d)
        for (uint32_t i = 0; i < s.draws[d].indexCount; ++i) expectVec(s.vertices[s.indices[s.draws[d].firstIndex + i]].normal, {0, 0, 1});
    EXPECT_TRUE(s.report.warnings.empty());
    expectVec(glm::vec3(s.draws[5].world[3]), {0, -3, 0});
}

TEST(GltfModels, SimpleMeshesShareGeometry) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("SimpleMeshes", "glTF", "SimpleMeshes.gltf"));
    ASSERT_EQ(s.draws.size(), 2u);
    EXPECT_EQ(s.vertices.size(), 3u);
    EXPECT_EQ(s.draws[0].firstIndex, s.draws[1].firstIndex);
    expectVec(glm::vec3(s.draws[1].world[3]), {1, 0, 0});
    expectVec(s.bounds.max, {2, 1, 0});
}

TEST(GltfModels, NormalTangentTestGeneratesTangents) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("NormalTangentTest", "glTF", "NormalTangentTest.gltf"));
    ASSERT_EQ(s.draws.size(), 1u);
    EXPECT_EQ(s.draws[0].indexCount, 23322u);
    EXPECT_GE(s.vertices.size(), 3983u);  // split only where corners disagree
    EXPECT_TRUE(s.report.warnings.empty());
    expectTangentFrames(s);
    // Every triangle of this model maps the texture without mirroring: w = +1 throughout.
    for (const scene::Vertex& v : s.vertices) ASSERT_EQ(v.tangent.w, 1.0f);
    // Three images: base colour sRGB; occlusion-roughness-metallic and normal linear.
    ASSERT_EQ(s.images.size(), 3u);
    const scene::Material& m = s.materials.at(0);
    EXPECT_TRUE(s.images[size_t(m.baseColor.image)].srgb);
    EXPECT_FALSE(s.images[size_t(m.normal.image)].srgb);
    EXPECT_EQ(m.occlusion.image, m.metallicRoughness.image);
    EXPECT_TRUE(m.doubleSided);
}

// Corner-by-corner agreement of generated tangents with given ones.
struct Agreement {
    size_t corners = 0, signMatches = 0, within1Degree = 0;
    float worstDegrees = 0.0f;
};

Agreement compareWithGenerated(const scene::Scene& s) {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    for (const scene::Vertex& v : s.vertices) {
        positions.push_back(v.position);
        normals.push_back(v.normal);
        uvs.push_back(v.uv0);
    }
    const std::vector<glm::vec4> generated = geometry::generateTangents(positions, normals, uvs, s.indices);
    Agreement a;
    for (size_t c = 0; c < s.indices.size(); ++c) {
        const glm::vec4 given = s.vertices[s.indices[c]].tangent;
        const float cosine = std::clamp(glm::dot(glm::vec3(given), glm::vec3(generated[c])), -1.0f, 1.0f);
        const float degrees = std::acos(cosine) * 180.0f / float(M_PI);
        ++a.corners;
        a.signMatches += given.w == generated[c].w;
        a.within1Degree += degrees <= 1.0f;
        a.worstDegrees = std::max(a.worstDegrees, degrees);
    }
    return a;
}

TEST(GltfModels, NormalTangentMirrorTestMatchesExportedMikkTSpace) {
    REQUIRE_MODELS();
    // This model ships Blender's MikkTSpace tangents; regenerate them from the same vertices (in
    // the file's order: no geometry preparation).
    const scene::Scene s = loadGltf(model("NormalTangentMirrorTest", "glTF", "NormalTangentMirrorTest.gltf"), {.prepareGeometry = false});
    ASSERT_EQ(s.indices.size(), 15720u);
    EXPECT_EQ(s.vertices.size(), 2770u);  // tangents supplied: kept, nothing split
    const Agreement a = compareWithGenerated(s);
    RecordProperty("signMatches", std::to_string(a.signMatches) + "/" + std::to_string(a.corners));
    RecordProperty("within1Degree", std::to_string(a.within1Degree) + "/" + std::to_string(a.corners));
    RecordProperty("worstDegrees", std::to_string(a.worstDegrees));
    EXPECT_EQ(a.signMatches, a.corners);
    EXPECT_EQ(a.within1Degree, a.corners) << "worst " << a.worstDegrees << "°";
}

TEST(GltfModels, NormalTangentMirrorTestWithoutTangentsGetsBothHandedness) {
    REQUIRE_MODELS();
    // A copy of the model with its TANGENT attribute removed, so the loader must generate them.
    test::TempDir dir;
    const fs::path source = model("NormalTangentMirrorTest", "glTF", "");
    for (const auto& entry : fs::directory_iterator(source)) fs::copy_file(entry.path(), dir / entry.path().filename().string());
    Json doc = Json::parse(readBytes(source / "NormalTangentMirrorTest.gltf"));
    doc["meshes"][0]["primitives"][0]["attributes"].erase("TANGENT");
    writeFile(dir / "NormalTangentMirrorTest.gltf", doc.dump());
    // Corner by corner: both in the file's triangle order (no geometry preparation).
    const scene::Scene generated = loadGltf(dir / "NormalTangentMirrorTest.gltf", {.prepareGeometry = false});
    const scene::Scene supplied = loadGltf(source / "NormalTangentMirrorTest.gltf", {.prepareGeometry = false});
    EXPECT_TRUE(generated.report.warnings.empty());
    expectTangentFrames(generated);
    ASSERT_EQ(generated.indices.size(), supplied.indices.size());
    // 40 of its 5240 triangles map the texture mirrored: their corners get w = −1, as in the
    // supplied tangents, corner by corner, and the directions agree.
    size_t negative = 0, signMatches = 0, within1Degree = 0;
    for (size_t c = 0; c < generated.indices.size(); ++c) {
        const glm::vec4 g = generated.vertices[generated.indices[c]].tangent;
        const glm::vec4 t = supplied.vertices[supplied.indices[c]].tangent;
        negative += g.w < 0.0f;
        signMatches += g.w == t.w;
        within1Degree += glm::dot(glm::vec3(g), glm::vec3(t)) >= std::cos(float(M_PI) / 180.0f);
    }
    EXPECT_EQ(negative, 40u * 3u);
    EXPECT_EQ(signMatches, generated.indices.size());
    EXPECT_EQ(within1Degree, generated.indices.size());
    // The generated vertex set is the supplied one: same splits where handedness or direction differ.
    EXPECT_EQ(generated.vertices.size(), supplied.vertices.size());
}

TEST(GltfModels, AlphaBlendModeTest) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("AlphaBlendModeTest", "glTF-Binary", "AlphaBlendModeTest.glb"));
    EXPECT_EQ(s.draws.size(), 9u);
    ASSERT_EQ(s.materials.size(), 6u);
    const std::map<std::string, std::pair<scene::AlphaMode, float>> expected = {
        {"MatBed", {scene::AlphaMode::Opaque, 0.5f}},       {"MatBlend", {scene::AlphaMode::Blend, 0.5f}},
        {"MatCutoff25", {scene::AlphaMode::Mask, 0.25f}},   {"MatCutoff75", {scene::AlphaMode::Mask, 0.75f}},
        {"MatCutoffDefault", {scene::AlphaMode::Mask, 0.5f}}, {"MatOpaque", {scene::AlphaMode::Opaque, 0.5f}}};
    for (const scene::Material& m : s.materials) {
        SCOPED_TRACE(m.name);
        ASSERT_TRUE(expected.count(m.name));
        EXPECT_EQ(m.alphaMode, expected.at(m.name).first);
        EXPECT_FLOAT_EQ(m.alphaCutoff, expected.at(m.name).second);
        EXPECT_EQ(m.doubleSided, m.name != "MatBed");
    }
    // JPEG/PNG images from bufferViews: 2 linear (normal; occlusion-roughness-metallic), 2 sRGB.
    ASSERT_EQ(s.images.size(), 4u);
    EXPECT_EQ(std::count_if(s.images.begin(), s.images.end(), [](const scene::Image& i) { return i.srgb; }), 2);
    for (const scene::Image& i : s.images) EXPECT_EQ(i.rgba8.size(), size_t(i.width) * i.height * 4);
    EXPECT_TRUE(s.report.warnings.empty());
}

TEST(GltfModels, TextureTransformTest) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("TextureTransformTest", "glTF", "TextureTransformTest.gltf"));
    EXPECT_TRUE(s.report.warnings.empty());
    EXPECT_EQ(s.draws.size(), 12u);
    ASSERT_EQ(s.materials.size(), 9u);
    EXPECT_EQ(s.materials[0].baseColor.transform.offset, glm::vec2(0.5f, 0.0f));
    EXPECT_FLOAT_EQ(s.materials[3].baseColor.transform.rotation, 0.39269908169872414f);
    EXPECT_EQ(s.materials[4].baseColor.transform.scale, glm::vec2(1.5f));
    const scene::TextureTransform& all = s.materials[5].baseColor.transform;
    EXPECT_EQ(all.offset, glm::vec2(-0.2f, -0.1f));
    EXPECT_FLOAT_EQ(all.rotation, 0.3f);
    EXPECT_EQ(all.scale, glm::vec2(1.5f));
    EXPECT_TRUE(s.materials[6].baseColor.transform.identity());
    ASSERT_EQ(s.samplers.size(), 1u);
    EXPECT_EQ(s.samplers[0].wrapU, scene::Wrap::ClampToEdge);
    EXPECT_FALSE(s.samplers[0].mipmaps);
    EXPECT_EQ(s.images.size(), 5u);
}

TEST(GltfModels, TextureTransformRotatesTowardTheCorrectMarker) {
    REQUIRE_MODELS();
    // The model marks where the arrow's tip must land: a "Correct" marker, and an "Error" marker
    // where the opposite rotation puts it. Without a transform the tip shows at the "Not
    // Supported" marker, so the tip's texture coordinate is that marker's. Each quad maps
    // u = x + 0.5, v = 0.5 − y (checked below). The transform is right when the "Correct"
    // marker's surface point samples the tip.
    const scene::Scene s = loadGltf(model("TextureTransformTest", "glTF", "TextureTransformTest.gltf"));
    ASSERT_EQ(s.draws.size(), 12u);  // 0–2 offsets; 3 rotation (+4 correct, 5 not supported, 6 error);
                                     // 7 scale (+8 correct, 9 not supported); 10 all (+11 correct)
    auto uvOf = [&](size_t quad, size_t marker) {
        const glm::vec3 p = glm::inverse(s.draws[quad].world) * s.draws[marker].world[3];
        return glm::vec2(p.x + 0.5f, 0.5f - p.y);
    };
    for (uint32_t i = 0; i < s.draws[3].indexCount; ++i) {
        const scene::Vertex& v = s.vertices[s.indices[s.draws[3].firstIndex + i]];
        EXPECT_EQ(v.uv0, glm::vec2(v.position.x + 0.5f, 0.5f - v.position.y));
    }
    const glm::vec2 tip = uvOf(3, 5);
    const scene::TextureTransform& rotation = s.materials[3].baseColor.transform;
    EXPECT_LT(glm::length(scene::applyTextureTransform(rotation, uvOf(3, 4)) - tip), 1e-3f);
    EXPECT_GT(glm::length(scene::applyTextureTransform(rotation, uvOf(3, 6)) - tip), 0.2f);
    EXPECT_LT(glm::length(scene::applyTextureTransform(s.materials[4].baseColor.transform, uvOf(7, 8)) - uvOf(7, 9)), 1e-3f);
    // "All" combines offset, rotation and scale; its marker is placed by eye (about 0.03 off).
    EXPECT_LT(glm::length(scene::applyTextureTransform(s.materials[5].baseColor.transform, uvOf(10, 11)) - tip), 0.04f);
}

TEST(GltfModels, DamagedHelmet) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("DamagedHelmet", "glTF-Binary", "DamagedHelmet.glb"));
    ASSERT_EQ(s.draws.size(), 1u);
    EXPECT_EQ(s.draws[0].indexCount, 46356u);
    EXPECT_GE(s.vertices.size(), 14556u);
    EXPECT_TRUE(s.report.warnings.empty());
    expectTangentFrames(s);  // no TANGENT in the file, a normal texture: generated
    ASSERT_EQ(s.images.size(), 5u);
    const scene::Material& m = s.materials.at(0);
    EXPECT_TRUE(s.images[size_t(m.baseColor.image)].srgb);
    EXPECT_TRUE(s.images[size_t(m.emissive.image)].srgb);
    EXPECT_FALSE(s.images[size_t(m.normal.image)].srgb);
    EXPECT_FALSE(s.images[size_t(m.occlusion.image)].srgb);
    EXPECT_FALSE(s.images[size_t(m.metallicRoughness.image)].srgb);
    for (const scene::Image& i : s.images) EXPECT_EQ(i.width, 2048u);
    expectVec(glm::vec3(s.draws[0].world * glm::vec4(0, 1, 0, 0)), {0, 0, 1}, 1e-6f);  // +90° about X
}

TEST(GltfModels, EmissiveStrengthTest) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("EmissiveStrengthTest", "glTF-Binary", "EmissiveStrengthTest.glb"));
    EXPECT_TRUE(s.report.warnings.empty());
    ASSERT_EQ(s.materials.size(), 6u);
    const std::vector<float> strengths = {4, 1, 2, 1, 8, 16};
    for (size_t i = 0; i < strengths.size(); ++i) EXPECT_FLOAT_EQ(s.materials[i].emissiveStrength, strengths[i]) << i;
    expectVec(s.materials[0].emissiveFactor, {0.1f, 0.5f, 0.9f});
    EXPECT_EQ(s.draws.size(), 6u);
}

TEST(GltfModels, UnlitTestRequiresASupportedExtension) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("UnlitTest", "glTF", "UnlitTest.gltf"));
    EXPECT_TRUE(s.report.warnings.empty());
    ASSERT_EQ(s.materials.size(), 2u);
    EXPECT_TRUE(s.materials[0].unlit);
    EXPECT_TRUE(s.materials[1].unlit);
    EXPECT_EQ(s.materials[0].baseColorFactor, glm::vec4(1.0f, 0.217637640824031f, 0.0f, 1.0f));
}

TEST(GltfModels, OrientationTestMatrixAndTrsNodes) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("OrientationTest", "glTF", "OrientationTest.gltf"));
    ASSERT_EQ(s.draws.size(), 13u);
    EXPECT_EQ(s.materials.size(), 7u);
    // Scene root order [5, 12, 10, ...]: draw 0 is node 5 ('ArrowZ2', a matrix), draw 9 node 0
    // ('ArrowX1', TRS with translation (5, 0, 0)).
    expectVec(glm::vec3(s.draws[0].world[3]), {0, 0, -5});
    expectVec(glm::vec3(s.draws[0].world[0]), {0.9563047863767122f, -0.2923716890963366f, 0});
    expectVec(glm::vec3(s.draws[9].world[3]), {5, 0, 0});
    for (const scene::Draw& d : s.draws) EXPECT_FALSE(d.flipWinding);
}

TEST(GltfModels, NegativeScaleTestFlipsTheRightDraws) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("NegativeScaleTest", "glTF-Binary", "NegativeScaleTest.glb"));
    // Roots [0, 1, 2, 3, 4, 7→(5, 6), 10→(8, 9), 13→(11, 12)]. A mirrored node flips; a mirrored
    // node under a mirrored parent does not.
    const std::vector<bool> flips = {false, false, false, false, true, false, true, true, false, true, false};
    ASSERT_EQ(s.draws.size(), flips.size());
    for (size_t i = 0; i < flips.size(); ++i) EXPECT_EQ(s.draws[i].flipWinding, flips[i]) << "draw " << i;
    EXPECT_EQ(s.images.size(), 2u);
}

TEST(GltfModels, VertexColorTest) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("VertexColorTest", "glTF", "VertexColorTest.gltf"));
    ASSERT_EQ(s.draws.size(), 2u);
    std::set<std::array<float, 4>> colors;
    const scene::Draw& d = s.draws[1];
    for (uint32_t i = 0; i < d.indexCount; ++i) {
        const glm::vec4 c = s.vertices[s.indices[d.firstIndex + i]].color;
        colors.insert({c.r, c.g, c.b, c.a});
    }
    EXPECT_GT(colors.size(), 1u);  // COLOR_0 read, not the white default
    for (uint32_t i = 0; i < s.draws[0].indexCount; ++i)
        EXPECT_EQ(s.vertices[s.indices[s.draws[0].firstIndex + i]].color, glm::vec4(1.0f));  // no COLOR_0
}

TEST(GltfModels, MultiUVTest) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("MultiUVTest", "glTF-Binary", "MultiUVTest.glb"));
    const scene::Material& m = s.materials.at(0);
    EXPECT_EQ(m.baseColor.texCoord, 0u);
    EXPECT_EQ(m.emissive.texCoord, 1u);
    EXPECT_NE(s.vertices.at(0).uv0, s.vertices.at(0).uv1);
    // The camera sits under a parent node: its world transform composes both.
    ASSERT_EQ(s.cameras.size(), 1u);
    expectVec(glm::vec3(s.cameras[0].world[3]), {7.481131553649902f, 5.34366512298584f, 6.5076398849487305f}, 1e-5f);
    EXPECT_NEAR(s.cameras[0].aspectRatio, 1.7777778f, 1e-6f);
}

TEST(GltfModels, TextureSettingsTest) {
    REQUIRE_MODELS();
    const scene::Scene s = loadGltf(model("TextureSettingsTest", "glTF", "TextureSettingsTest.gltf"));
    EXPECT_EQ(s.draws.size(), 10u);
    ASSERT_EQ(s.samplers.size(), 5u);
    std::set<scene::Wrap> wraps;
    for (const scene::Sampler& sampler : s.samplers) wraps.insert(sampler.wrapU), wraps.insert(sampler.wrapV);
    EXPECT_EQ(wraps.size(), 3u);  // REPEAT, MIRRORED_REPEAT and CLAMP_TO_EDGE all appear
    EXPECT_TRUE(s.materials[7].doubleSided);
    EXPECT_FALSE(s.materials[8].doubleSided);
}

TEST(GltfModels, SpecGlossVsMetalRoughConvertsItsSpecularGlossinessMaterials) {
    REQUIRE_MODELS();
    // Its extensionsRequired lists KHR_materials_pbrSpecularGlossiness (archived): converted on
    // load to the specular layer (docs/materials.md), quietly.
    const fs::path path = model("SpecGlossVsMetalRough", "glTF", "SpecGlossVsMetalRough.gltf");
    const scene::Scene s = loadGltf(path);
    ASSERT_EQ(s.materials.size(), 4u);
    EXPECT_EQ(s.materials[0].name, "BottleMat_SpecGloss");
    EXPECT_EQ(s.materials[0].ior, 0.0f);
    EXPECT_EQ(s.materials[0].metallicFactor, 0.0f);
    EXPECT_TRUE(s.materials[0].baseColor.present() && s.materials[0].specularColor.present() &&
                s.materials[0].metallicRoughness.present());
    EXPECT_EQ(s.materials[1].layers(), 0u);  // the metallic-roughness bottle stays core
    EXPECT_EQ(s.materials[3].roughnessFactor, 1.0f);  // glossiness 0
    EXPECT_TRUE(s.report.warnings.empty());
}

TEST(GltfModels, NodesAreKeptParentsFirstWithTheTransformsTheDrawsWerePlacedWith) {
    REQUIRE_MODELS();
    for (const fs::path& path : {model("CesiumMilkTruck", "glTF-Binary", "CesiumMilkTruck.glb"),
                                 model("OrientationTest", "glTF-Binary", "OrientationTest.glb"),
                                 model("Cameras", "glTF", "Cameras.gltf"),
                                 model("LightsPunctualLamp", "glTF", "LightsPunctualLamp.gltf")}) {
        SCOPED_TRACE(path.string());
        const scene::Scene scene = loadGltf(path);
        ASSERT_FALSE(scene.nodes.empty());
        for (size_t i = 0; i < scene.nodes.size(); ++i) {
            EXPECT_LT(scene.nodes[i].parent, int32_t(i));
            EXPECT_GE(scene.nodes[i].source, 0);
        }
        for (const scene::Draw& draw : scene.draws) {
            ASSERT_GE(draw.node, 0);
            ASSERT_LT(size_t(draw.node), scene.nodes.size());
            EXPECT_EQ(draw.world, glm::mat4(scene.nodes[size_t(draw.node)].world));
        }
        for (const scene::Light& light : scene.lights) EXPECT_GE(light.node, 0);
        for (const scene::Camera& camera : scene.cameras) EXPECT_GE(camera.node, 0);
        // Recomputing every world transform from the local ones gives the loaded ones exactly:
        // what animation will do each frame for the animated subtrees.
        std::vector<animation::SceneNode> nodes = scene.nodes;
        std::vector<uint32_t> all;
        for (animation::SceneNode& node : nodes) {
            all.push_back(uint32_t(all.size()));
            node.world = glm::dmat4(0.0);
        }
        animation::updateWorldTransforms(nodes, all);
        for (size_t i = 0; i < nodes.size(); ++i) EXPECT_EQ(nodes[i].world, scene.nodes[i].world) << "node " << i;
    }
}

}  // namespace
}  // namespace candela::assets::test

namespace candela::assets::test {
namespace {

TEST(GltfModels, MultipleScenesDefaultAndChosen) {
    if (sharedModels().empty()) GTEST_SKIP() << "../shared/assets not present";
    const fs::path path = sharedModels() / "MultipleScenes/glTF/MultipleScenes.gltf";
    // The file names scene 1 (one node); scene 0 holds the other node.
    const scene::Scene byDefault = loadGltf(path);
    EXPECT_EQ(byDefault.sceneIndex, 1u);
    EXPECT_EQ(byDefault.sceneNames, (std::vector<std::string>{"scene 0", "scene 1"}));
    ASSERT_EQ(byDefault.nodes.size(), 1u);
    EXPECT_EQ(byDefault.nodes[0].source, 1);
    const scene::Scene first = loadGltf(path, {.sceneIndex = 0u});
    EXPECT_EQ(first.sceneIndex, 0u);
    ASSERT_EQ(first.nodes.size(), 1u);
    EXPECT_EQ(first.nodes[0].source, 0);
    EXPECT_NE(first.indices.size(), byDefault.indices.size());  // a triangle and a square
    try {
        assets::loadGltf(path, {.sceneIndex = 2u});
        FAIL() << "no error";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("scene 2 does not exist (the file has 2 scenes)"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace candela::assets::test
