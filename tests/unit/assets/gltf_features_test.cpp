// One positive test per loader feature, each on a tiny glTF written by the test itself.
#include "gltf_test_util.h"

#include "assets/gltf_mesh.h"
#include "scene/material_variants.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace candela::assets::test::gltf_features_test {
namespace {

constexpr float kEps = 1e-6f;

void expectVec(const glm::vec3& actual, const glm::vec3& expected, float eps = kEps) {
    EXPECT_NEAR(actual.x, expected.x, eps);
    EXPECT_NEAR(actual.y, expected.y, eps);
    EXPECT_NEAR(actual.z, expected.z, eps);
}

bool hasWarning(const scene::Scene& scene, const std::string& fragment) {
    for (const std::string& w : scene.report.warnings)
        if (w.find(fragment) != std::string::npos) return true;
    return false;
}

// The vertices of draw `d`'s triangles, in index order.
std::vector<scene::Vertex> corners(const scene::Scene& scene, size_t d = 0) {
    std::vector<scene::Vertex> out;
    const scene::Draw& draw = scene.draws.at(d);
    for (uint32_t i = 0; i < draw.indexCount; ++i) out.push_back(scene.vertices.at(scene.indices.at(draw.firstIndex + i)));
    return out;
}

// A mesh of one real triangle and one whose corners lie on a line, `copies` times (one node each,
// each over accessors of its own).
assets::test::GltfBuilder degenerateMeshes(int copies) {
    GltfBuilder b;
    std::vector<int> nodes;
    for (int i = 0; i < copies; ++i) {
        const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 3, 0, 0}, "VEC3", 3);
        nodes.push_back(b.addNode({{"mesh", b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 2, 1, 3, 4}))}}));
    }
    b.setScene(nodes);
    return b;
}

TEST(GltfFeatures, DegenerateTrianglesAreANoteFoldedIntoOneLine) {
    // The glTF-Validator reports degenerate triangles as information: they are dropped quietly,
    // with one note for --verbose however many primitives have them.
    test::TempDir dir;
    const scene::Scene one = loadGltf(degenerateMeshes(1).writeGltf(dir / "one"));
    EXPECT_TRUE(one.report.warnings.empty()) << one.report.warnings.front();
    EXPECT_EQ(one.report.notes, (std::vector<std::string>{"mesh 0 primitive 0: 1 zero-area triangle dropped"}));
    const scene::Scene many = loadGltf(degenerateMeshes(100).writeGltf(dir / "many"));
    EXPECT_TRUE(many.report.warnings.empty()) << many.report.warnings.front();
    EXPECT_EQ(many.report.notes, (std::vector<std::string>{"100 primitives: 100 zero-area triangles dropped"}));
    EXPECT_EQ(many.draws.size(), 100u);
}

TEST(GltfFeatures, TriangleInAllThreeContainers) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    for (const fs::path& path : {b.writeGltf(dir / "a"), b.writeGlb(dir / "b"), b.writeEmbedded(dir / "c")}) {
        SCOPED_TRACE(path.string());
        const scene::Scene scene = loadGltf(path);
        EXPECT_EQ(scene.source, path.string());
        ASSERT_EQ(scene.vertices.size(), 3u);
        EXPECT_EQ(scene.indices, (std::vector<uint32_t>{0, 1, 2}));
        ASSERT_EQ(scene.draws.size(), 1u);
        EXPECT_EQ(scene.draws[0].indexCount, 3u);
        EXPECT_FALSE(scene.draws[0].flipWinding);
        ASSERT_EQ(scene.materials.size(), 1u);  // the appended default material
        EXPECT_EQ(scene.materials[0].name, "default");
        EXPECT_EQ(scene.draws[0].material, 0u);
        expectVec(scene.vertices[1].position, {1, 0, 0});
        expectVec(scene.vertices[2].normal, {0, 0, 1});
        expectVec(scene.bounds.min, {0, 0, 0});
        expectVec(scene.bounds.max, {1, 1, 0});
        EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    }
}

TEST(GltfFeatures, StripAndFanIndexConversion) {
    const std::vector<uint32_t> five = {0, 1, 2, 3, 4};
    EXPECT_EQ(gltf::toTriangleList(kStrip, five), (std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4}));
    EXPECT_EQ(gltf::toTriangleList(kFan, five), (std::vector<uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0}));
    EXPECT_EQ(gltf::toTriangleList(kTriangles, five), (std::vector<uint32_t>{0, 1, 2}));
    // Stitching with repeated indices produces degenerate triangles, which are dropped.
    EXPECT_EQ(gltf::toTriangleList(kStrip, std::vector<uint32_t>{0, 1, 2, 2, 3}), (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_TRUE(gltf::toTriangleList(kStrip, std::vector<uint32_t>{0, 1}).empty());
    EXPECT_TRUE(gltf::toTriangleList(kFan, std::vector<uint32_t>{}).empty());
}

TEST(GltfFeatures, LineIndexConversion) {
    const std::vector<uint32_t> five = {0, 1, 2, 3, 4};
    EXPECT_EQ(gltf::toLineList(kLines, five), (std::vector<uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(gltf::toLineList(kLineStrip, five), (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 4}));
    EXPECT_EQ(gltf::toLineList(kLineLoop, five), (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 4, 4, 0}));
    EXPECT_TRUE(gltf::toLineList(kLineStrip, std::vector<uint32_t>{7}).empty());
    EXPECT_TRUE(gltf::toLineList(kLineLoop, std::vector<uint32_t>{7}).empty());
    EXPECT_TRUE(gltf::toLineList(kLines, std::vector<uint32_t>{}).empty());
}

TEST(GltfFeatures, StripAndFanFilesKeepCounterClockwiseWinding) {
    test::TempDir dir;
    GltfBuilder b;
    // A zig-zag strip and a fan of a unit square, all in the XY plane facing +Z; no normals, so the
    // flat normals reveal each triangle's winding.
    const int strip = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0}, "VEC3", 3);
    const int fan = b.addFloats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    const int m0 = b.addMesh({{"POSITION", strip}}, -1, -1, kStrip);
    const int m1 = b.addMesh({{"POSITION", fan}}, b.addIndices({0, 1, 2, 3}), -1, kFan);
    b.setScene({b.addNode({{"mesh", m0}}), b.addNode({{"mesh", m1}})});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    ASSERT_EQ(scene.draws.size(), 2u);
    EXPECT_EQ(scene.draws[0].indexCount, 9u);
    EXPECT_EQ(scene.draws[1].indexCount, 6u);
    for (size_t d = 0; d < 2; ++d)
        for (const scene::Vertex& v : corners(scene, d)) expectVec(v.normal, {0, 0, 1});
}

TEST(GltfFeatures, SparseAccessorsWithAndWithoutBufferView) {
    test::TempDir dir;
    GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int idx = b.addView(std::vector<uint8_t>{1, 0, 0, 0});
    const int val = b.addView(std::vector<float>{5, 6, 7});
    b.doc["accessors"][pos]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", idx}, {"componentType", kUnsignedByte}}}, {"values", {{"bufferView", val}}}};
    // TEXCOORD_0 with no bufferView: zeros, then one sparse value at vertex 2.
    const int uv = b.addAccessor(-1, kFloat, 3, "VEC2");
    const int uvIdx = b.addView(std::vector<uint32_t>{2});
    const int uvVal = b.addView(std::vector<float>{0.5f, 0.25f});
    b.doc["accessors"][uv]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", uvIdx}, {"componentType", kUnsignedInt}}}, {"values", {{"bufferView", uvVal}}}};
    b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}, {"TEXCOORD_0", uv}})}})});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    const std::vector<scene::Vertex> v = corners(scene);
    ASSERT_EQ(v.size(), 3u);
    expectVec(v[0].position, {0, 0, 0});
    expectVec(v[1].position, {5, 6, 7});
    expectVec(v[2].position, {0, 1, 0});
    EXPECT_EQ(v[0].uv0, glm::vec2(0.0f));
    EXPECT_EQ(v[1].uv0, glm::vec2(0.0f));
    EXPECT_EQ(v[2].uv0, glm::vec2(0.5f, 0.25f));
}

TEST(GltfFeatures, NormalizedIntegerTexcoordsAndColors) {
    test::TempDir dir;
    GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    // VEC2 of UNSIGNED_BYTE padded to a 4-byte stride, as vertex attributes must be.
    const int uvView = b.addView(std::vector<uint8_t>{0, 0, 99, 99, 128, 255, 99, 99, 255, 64, 99, 99}, 4);
    const int uv = b.addAccessor(uvView, kUnsignedByte, 3, "VEC2", true);
    const int colorView = b.addView(std::vector<uint16_t>{65535, 0, 32768, 0, 0, 65535, 0, 0, 0, 0, 0, 0}, 8);
    const int color = b.addAccessor(colorView, kUnsignedShort, 3, "VEC3", true);
    b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}, {"TEXCOORD_0", uv}, {"COLOR_0", color}})}})});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    const std::vector<scene::Vertex> v = corners(scene);
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[0].uv0, glm::vec2(0.0f, 0.0f));
    EXPECT_FLOAT_EQ(v[1].uv0.x, 128.0f / 255.0f);
    EXPECT_FLOAT_EQ(v[1].uv0.y, 1.0f);
    EXPECT_FLOAT_EQ(v[2].uv0.x, 1.0f);
    EXPECT_FLOAT_EQ(v[2].uv0.y, 64.0f / 255.0f);
    EXPECT_FLOAT_EQ(v[0].color.r, 1.0f);
    EXPECT_FLOAT_EQ(v[0].color.b, 32768.0f / 65535.0f);
    EXPECT_FLOAT_EQ(v[0].color.a, 1.0f);  // VEC3 colour: opaque
    EXPECT_FLOAT_EQ(v[1].color.g, 1.0f);
    EXPECT_EQ(v[2].color, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
}

TEST(GltfFeatures, MeshQuantizationIntegersAndNodeScale) {
    test::TempDir dir;
    GltfBuilder b;
    b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    // SHORT positions (not normalized) padded to 8 bytes; the node scale dequantizes them.
    const int posView = b.addView(std::vector<int16_t>{0, 0, 0, 0, 1000, 0, 0, 0, 0, -2000, 0, 0}, 8);
    const int pos = b.addAccessor(posView, kShort, 3, "VEC3");
    // Normalized BYTE normals (VEC3 padded to 4): 127 → 1, −128 → −1 (clamped).
    const int nView = b.addView(std::vector<int8_t>{0, 0, 127, 0, 0, 0, -128, 0, 0, 127, 0, 0}, 4);
    const int normal = b.addAccessor(nView, kByte, 3, "VEC3", true);
    const int uvView = b.addView(std::vector<int16_t>{-32768, 32767, 0, 16384, 0, 0});
    const int uv = b.addAccessor(uvView, kShort, 3, "VEC2", true);
    const int mesh = b.addMesh({{"POSITION", pos}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}, b.addIndices({0, 1, 2}));
    b.setScene({b.addNode({{"mesh", mesh}, {"scale", {0.001, 0.001, 0.001}}})});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty());
    const std::vector<scene::Vertex> v = corners(scene);
    ASSERT_EQ(v.size(), 3u);
    expectVec(v[1].position, {1000, 0, 0});
    expectVec(v[2].position, {0, -2000, 0});
    expectVec(v[0].normal, {0, 0, 1});
    expectVec(v[1].normal, {0, 0, -1});
    expectVec(v[2].normal, {0, 1, 0});
    EXPECT_FLOAT_EQ(v[0].uv0.x, -1.0f);
    EXPECT_FLOAT_EQ(v[0].uv0.y, 1.0f);
    EXPECT_FLOAT_EQ(v[1].uv0.y, 16384.0f / 32767.0f);
    expectVec(scene.bounds.min, {0, -2, 0}, 1e-5f);
    expectVec(scene.bounds.max, {1, 0, 0}, 1e-5f);
}

TEST(GltfFeatures, NegativeScaleFlipsWinding) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    const int a = b.addNode({{"mesh", 0}, {"scale", {-1, 1, 1}}});
    const int c = b.addNode({{"mesh", 0}, {"scale", {-1, -1, 1}}});  // two mirrors: a rotation
    const int d = b.addNode({{"children", {b.addNode({{"mesh", 0}})}}, {"scale", {1, 1, -2}}});  // inherited
    b.setScene({0, a, c, d});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    ASSERT_EQ(scene.draws.size(), 4u);
    EXPECT_FALSE(scene.draws[0].flipWinding);
    EXPECT_TRUE(scene.draws[1].flipWinding);
    EXPECT_FALSE(scene.draws[2].flipWinding);
    EXPECT_TRUE(scene.draws[3].flipWinding);
    // One primitive, converted once and shared by all four draws.
    EXPECT_EQ(scene.vertices.size(), 3u);
    for (const scene::Draw& draw : scene.draws) EXPECT_EQ(draw.firstIndex, 0u);
    expectVec(scene.draws[1].bounds.min, {-1, 0, 0});
    expectVec(scene.draws[1].bounds.max, {0, 1, 0});
}

TEST(GltfFeatures, LargeAndSmallValidScalesLoadQuietly) {
    // det(world) is 1e39 and 1e-45 here: beyond a float, but the meshes are valid and drawn (the
    // determinant and the normal matrix are taken in double).
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    const int big = b.addNode({{"mesh", 0}, {"scale", {1e13, 1e13, -1e13}}});
    const int small = b.addNode({{"mesh", 0}, {"scale", {1e-15, 1e-15, 1e-15}}});
    b.setScene({big, small});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.draws.size(), 2u);
    EXPECT_TRUE(scene.draws[0].flipWinding);
    EXPECT_FALSE(scene.draws[1].flipWinding);
    EXPECT_FLOAT_EQ(scene.draws[0].bounds.max.x, 1e13f);
}

TEST(GltfFeatures, GpuInstancesAreOneDrawPerWindingWithEveryInstanceInTheBounds) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    // Three instances: two plain, one mirrored (scale x −1) — the mirrored one gets a draw of its own.
    const int t = b.addFloats({0, 0, 0, 10, 0, 0, 0, 5, 0}, "VEC3", 3);
    const int s = b.addFloats({1, 1, 1, 2, 2, 2, -1, 1, 1}, "VEC3", 3);
    b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"TRANSLATION", t}, {"SCALE", s}};
    b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.draws.size(), 2u);
    EXPECT_EQ(scene.draws[0].instanceCount, 2u);
    EXPECT_FALSE(scene.draws[0].flipWinding);
    EXPECT_EQ(scene.draws[1].instanceCount, 1u);
    EXPECT_TRUE(scene.draws[1].flipWinding);
    ASSERT_EQ(scene.instances.size(), 3u);
    expectVec(glm::vec3(scene.instances[scene.draws[0].firstInstance + 1][3]), {10, 0, 0});
    // The triangle spans [0,1]²: instance 2 (at x = 10, scale 2) reaches x = 12; the mirrored one x = −1.
    expectVec(scene.draws[0].bounds.max, {12, 2, 0});
    expectVec(scene.draws[1].bounds.min, {-1, 5, 0});
    expectVec(scene.bounds.min, {-1, 0, 0});
}

TEST(GltfFeatures, MatrixAndTrsGiveTheSameWorldTransform) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    const glm::dquat q = glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 2, 3)));
    const glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(1, -2, 3)) * glm::mat4_cast(q) *
                         glm::scale(glm::dmat4(1), glm::dvec3(2, 3, 4));
    std::vector<double> matrix(16);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) matrix[size_t(c * 4 + r)] = m[c][r];
    const int trs = b.addNode({{"mesh", 0}, {"translation", {1, -2, 3}}, {"rotation", {q.x, q.y, q.z, q.w}}, {"scale", {2, 3, 4}}});
    const int mat = b.addNode({{"mesh", 0}, {"matrix", matrix}});
    // A child composes with its parent: parent translates, child rotates 90° about Z.
    const int child = b.addNode({{"mesh", 0}, {"rotation", {0, 0, std::sqrt(0.5), std::sqrt(0.5)}}});
    const int parent = b.addNode({{"translation", {10, 0, 0}}, {"children", {child}}});
    b.setScene({trs, mat, parent});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    ASSERT_EQ(scene.draws.size(), 3u);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(scene.draws[0].world[c][r], float(m[c][r]), 1e-5f);
            EXPECT_NEAR(scene.draws[1].world[c][r], float(m[c][r]), 1e-5f);
        }
    const glm::vec4 p = scene.draws[2].world * glm::vec4(1, 0, 0, 1);  // (1,0,0) → (0,1,0) → (10,1,0)
    expectVec(glm::vec3(p), {10, 1, 0}, 1e-6f);
}

TEST(GltfFeatures, MissingNormalsAreFlatPerTriangle) {
    test::TempDir dir;
    GltfBuilder b;
    // Two triangles sharing edge (0,1): one in the XY plane facing +Z, one in the XZ plane facing +Y.
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3", 3);
    const int mesh = b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 2, 1, 0, 3}));
    b.setScene({b.addNode({{"mesh", mesh}})});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    EXPECT_EQ(scene.vertices.size(), 6u);  // de-indexed: each triangle owns its corners
    const std::vector<scene::Vertex> v = corners(scene);
    ASSERT_EQ(v.size(), 6u);
    for (int i = 0; i < 3; ++i) expectVec(v[size_t(i)].normal, {0, 0, 1});
    for (int i = 3; i < 6; ++i) expectVec(v[size_t(i)].normal, {0, 1, 0});
}

TEST(GltfFeatures, MaterialFactorsModesAndExtensions) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength", "KHR_materials_unlit"};
    b.doc["materials"] = Json::array({
        {{"name", "m0"}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.3}, {"doubleSided", true},
         {"emissiveFactor", {0.1, 0.2, 0.3}},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 0.75}}, {"metallicFactor", 0.2}, {"roughnessFactor", 0.6}}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 5.0}}}, {"KHR_materials_unlit", Json::object()}}}},
        {{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"metallicFactor", 7}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 1;
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    ASSERT_EQ(scene.materials.size(), 2u);  // no default needed
    const scene::Material& m = scene.materials[0];
    EXPECT_EQ(m.name, "m0");
    EXPECT_EQ(m.alphaMode, scene::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_TRUE(m.unlit);
    EXPECT_FLOAT_EQ(m.emissiveStrength, 5.0f);
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_FLOAT_EQ(m.metallicFactor, 0.2f);
    EXPECT_FLOAT_EQ(m.roughnessFactor, 0.6f);
    expectVec(m.emissiveFactor, {0.1f, 0.2f, 0.3f});
    EXPECT_FALSE(m.baseColor.present());
    const scene::Material& n = scene.materials[1];
    EXPECT_EQ(n.name, "material 1");
    EXPECT_EQ(n.alphaMode, scene::AlphaMode::Blend);
    EXPECT_FALSE(n.unlit);
    EXPECT_FALSE(n.doubleSided);
    EXPECT_FLOAT_EQ(n.emissiveStrength, 1.0f);
    EXPECT_FLOAT_EQ(n.metallicFactor, 1.0f);  // 7 clamped to the allowed [0, 1]
    EXPECT_EQ(scene.draws[0].material, 1u);
}

TEST(GltfFeatures, IorAndSpecularExtensions) {
    // Factors, both textures (the colour one sRGB, with a texture transform), the IOR's special 0,
    // defaults, out-of-range values clamped with a warning, and which materials pay for the layer.
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng({10, 20, 30, 40}));
    b.doc["extensionsUsed"] = {"KHR_materials_ior", "KHR_materials_specular", "KHR_texture_transform"};
    const Json core = b.doc["materials"][0];
    b.doc["materials"] = Json::array({
        {{"extensions", {{"KHR_materials_ior", {{"ior", 1.33}}},
                         {"KHR_materials_specular",
                          {{"specularFactor", 0.5}, {"specularColorFactor", {2.0, 1.0, 0.25}},
                           {"specularTexture", {{"index", 0}}},
                           {"specularColorTexture",
                            {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {2, 2}}}}}}}}}}}}},
        {{"extensions", {{"KHR_materials_ior", {{"ior", 0}}}}}},
        {{"extensions", {{"KHR_materials_ior", {{"ior", 1.5}}}, {"KHR_materials_specular", Json::object()}}}},
        {{"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}, {"KHR_materials_specular", {{"specularFactor", 3}}}}}},
        core});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 5u);
    const scene::Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FLOAT_EQ(m.specularFactor, 0.5f);
    expectVec(m.specularColorFactor, {2.0f, 1.0f, 0.25f});
    ASSERT_TRUE(m.specular.present());
    ASSERT_TRUE(m.specularColor.present());
    EXPECT_FALSE(scene.images.at(size_t(m.specular.image)).srgb);
    EXPECT_TRUE(scene.images.at(size_t(m.specularColor.image)).srgb);
    EXPECT_EQ(m.specularColor.transform.scale, glm::vec2(2.0f));
    EXPECT_EQ(m.layers(), uint32_t(scene::kLayerSpecular));
    EXPECT_FLOAT_EQ(scene.materials[1].ior, 0.0f);  // f0 = 1: the specular-glossiness conversion
    EXPECT_EQ(scene.materials[1].layers(), uint32_t(scene::kLayerSpecular));
    // IOR 1.5 and an empty specular extension are the core Fresnel: no layer to pay for.
    EXPECT_EQ(scene.materials[2].layers(), 0u);
    EXPECT_EQ(scene.materials[4].layers(), 0u);
    EXPECT_FLOAT_EQ(scene.materials[3].ior, 1.0f);
    EXPECT_FLOAT_EQ(scene.materials[3].specularFactor, 1.0f);
    EXPECT_TRUE(hasWarning(scene, "ior 0.5 is outside [1, inf] (using 1)"));
    EXPECT_TRUE(hasWarning(scene, "specularFactor 3 is outside [0, 1] (using 1)"));
    EXPECT_EQ(scene.report.warnings.size(), 2u);
}

TEST(GltfFeatures, ClearcoatExtension) {
    // Factors, the three textures (linear, the normal map with its scale and a transform), the
    // defaults, factor 0 disabling the layer whatever its textures, clamping with a warning.
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng({10, 20, 30, 40}));
    b.doc["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_texture_transform"};
    const Json core = b.doc["materials"][0];
    b.doc["materials"] = Json::array({
        {{"extensions",
          {{"KHR_materials_clearcoat",
            {{"clearcoatFactor", 0.75}, {"clearcoatRoughnessFactor", 0.25}, {"clearcoatTexture", {{"index", 0}}},
             {"clearcoatRoughnessTexture", {{"index", 0}}},
             {"clearcoatNormalTexture",
              {{"index", 0}, {"scale", 0.5}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}}}}}}}}}}}},
        {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1}}}}}},
        {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatTexture", {{"index", 0}}}}}}}},
        {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.5}, {"clearcoatRoughnessFactor", -1}}}}}},
        core});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 5u);
    const scene::Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.clearcoatFactor, 0.75f);
    EXPECT_FLOAT_EQ(m.clearcoatRoughnessFactor, 0.25f);
    EXPECT_FLOAT_EQ(m.clearcoatNormalScale, 0.5f);
    ASSERT_TRUE(m.clearcoat.present() && m.clearcoatRoughness.present() && m.clearcoatNormal.present());
    EXPECT_FALSE(scene.images.at(size_t(m.clearcoat.image)).srgb);
    EXPECT_EQ(m.clearcoatNormal.transform.offset, glm::vec2(0.5f, 0.0f));
    EXPECT_EQ(m.layers(), uint32_t(scene::kLayerClearcoat | scene::kLayerClearcoatNormal));
    // Defaults: roughness 0, no normal map.
    EXPECT_FLOAT_EQ(scene.materials[1].clearcoatRoughnessFactor, 0.0f);
    EXPECT_EQ(scene.materials[1].layers(), uint32_t(scene::kLayerClearcoat));
    // clearcoatFactor defaults to 0, which disables the layer.
    EXPECT_EQ(scene.materials[2].layers(), 0u);
    EXPECT_EQ(scene.materials[4].layers(), 0u);
    EXPECT_FLOAT_EQ(scene.materials[3].clearcoatFactor, 1.0f);
    EXPECT_FLOAT_EQ(scene.materials[3].clearcoatRoughnessFactor, 0.0f);
    EXPECT_TRUE(hasWarning(scene, "clearcoatFactor 1.5 is outside [0, 1] (using 1)"));
    EXPECT_TRUE(hasWarning(scene, "clearcoatRoughnessFactor -1 is outside [0, 1] (using 0)"));
    EXPECT_EQ(scene.report.warnings.size(), 2u);
}

TEST(GltfFeatures, SheenExtension) {
    // Factors, both textures (colour sRGB, roughness linear), the default (black: no layer), clamping.
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng());
    b.doc["extensionsUsed"] = {"KHR_materials_sheen"};
    b.doc["materials"] = Json::array({
        {{"extensions",
          {{"KHR_materials_sheen",
            {{"sheenColorFactor", {0.5, 0.25, 1.0}}, {"sheenRoughnessFactor", 0.3}, {"sheenColorTexture", {{"index", 0}}},
             {"sheenRoughnessTexture", {{"index", 0}}}}}}}},
        {{"extensions", {{"KHR_materials_sheen", {{"sheenRoughnessFactor", 0.5}}}}}},
        {{"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {1.5, 0, 0}}, {"sheenRoughnessFactor", 2}}}}}}});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 3u);
    const scene::Material& m = scene.materials[0];
    expectVec(m.sheenColorFactor, {0.5f, 0.25f, 1.0f});
    EXPECT_FLOAT_EQ(m.sheenRoughnessFactor, 0.3f);
    ASSERT_TRUE(m.sheenColor.present() && m.sheenRoughness.present());
    EXPECT_TRUE(scene.images.at(size_t(m.sheenColor.image)).srgb);
    EXPECT_FALSE(scene.images.at(size_t(m.sheenRoughness.image)).srgb);
    EXPECT_EQ(m.layers(), uint32_t(scene::kLayerSheen));
    EXPECT_EQ(scene.materials[1].layers(), 0u);  // a black sheen colour disables the layer
    expectVec(scene.materials[2].sheenColorFactor, {1.0f, 0.0f, 0.0f});
    EXPECT_FLOAT_EQ(scene.materials[2].sheenRoughnessFactor, 1.0f);
    EXPECT_TRUE(hasWarning(scene, "sheenColorFactor 1.5 is outside [0, 1] (using 1)"));
    EXPECT_TRUE(hasWarning(scene, "sheenRoughnessFactor 2 is outside [0, 1] (using 1)"));
    EXPECT_EQ(scene.report.warnings.size(), 2u);
}

TEST(GltfFeatures, AnisotropyExtension) {
    // Strength (clamped), rotation (any angle, kept modulo 2π), the texture (linear), the default
    // (strength 0: no layer), and the tangent frame it needs though there is no normal map.
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng());
    b.doc["extensionsUsed"] = {"KHR_materials_anisotropy"};
    b.doc["materials"] = Json::array({
        {{"extensions", {{"KHR_materials_anisotropy",
                          {{"anisotropyStrength", 0.6}, {"anisotropyRotation", 1.0}, {"anisotropyTexture", {{"index", 0}}}}}}}},
        {{"extensions", {{"KHR_materials_anisotropy", {{"anisotropyRotation", 0.5}}}}}},
        {{"extensions", {{"KHR_materials_anisotropy", {{"anisotropyStrength", 4}, {"anisotropyRotation", 7.0}}}}}}});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 3u);
    const scene::Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.anisotropyStrength, 0.6f);
    EXPECT_FLOAT_EQ(m.anisotropyRotation, 1.0f);
    ASSERT_TRUE(m.anisotropy.present());
    EXPECT_FALSE(scene.images.at(size_t(m.anisotropy.image)).srgb);
    EXPECT_EQ(m.layers(), uint32_t(scene::kLayerAnisotropy));
    EXPECT_EQ(scene.materials[1].layers(), 0u);
    EXPECT_FLOAT_EQ(scene.materials[2].anisotropyStrength, 1.0f);
    EXPECT_NEAR(scene.materials[2].anisotropyRotation, 7.0 - 2.0 * std::numbers::pi, 1e-6);
    EXPECT_TRUE(hasWarning(scene, "anisotropyStrength 4 is outside [0, 1] (using 1)"));
    EXPECT_EQ(scene.report.warnings.size(), 1u);
    // The tangent frame the direction lives in: generated (MikkTSpace) though there is no normal map.
    ASSERT_TRUE(m.tangentSpaceMap().has_value());
    EXPECT_TRUE(scene.materials[1].tangentSpaceMap() == std::nullopt);
}

TEST(GltfFeatures, TransmissionAndVolumeExtensions) {
    // Transmission (factor, linear texture, default 0: no layer), volume (thickness, its linear
    // texture, attenuation; a volume without transmission or with thickness 0 is no layer), clamping
    // and the specification's infinite default attenuation distance (0 here).
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng());
    b.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume"};
    b.doc["materials"] = Json::array({
        {{"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 0.8}, {"transmissionTexture", {{"index", 0}}}}},
           {"KHR_materials_volume",
            {{"thicknessFactor", 2.5}, {"thicknessTexture", {{"index", 0}}}, {"attenuationDistance", 0.25},
             {"attenuationColor", {1.0, 0.5, 0.25}}}}}}},
        {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}},
        {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                         {"KHR_materials_volume", {{"attenuationColor", {0.5, 0.5, 0.5}}}}}}},
        {{"extensions", {{"KHR_materials_volume", {{"thicknessFactor", 1.0}}}}}},
        {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 3}}},
                         {"KHR_materials_volume",
                          {{"thicknessFactor", -1}, {"attenuationDistance", 0}, {"attenuationColor", {2, 0.5, -1}}}}}}}});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 5u);
    const scene::Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.transmissionFactor, 0.8f);
    EXPECT_FLOAT_EQ(m.thicknessFactor, 2.5f);
    EXPECT_FLOAT_EQ(m.attenuationDistance, 0.25f);
    expectVec(m.attenuationColor, {1.0f, 0.5f, 0.25f});
    ASSERT_TRUE(m.transmission.present() && m.thickness.present());
    EXPECT_FALSE(scene.images.at(size_t(m.transmission.image)).srgb);
    EXPECT_FALSE(scene.images.at(size_t(m.thickness.image)).srgb);
    EXPECT_EQ(m.layers(), uint32_t(scene::kLayerTransmission | scene::kLayerVolume));
    EXPECT_EQ(scene.materials[1].layers(), uint32_t(scene::kLayerTransmission));  // thin-walled
    EXPECT_FLOAT_EQ(scene.materials[1].attenuationDistance, 0.0f);          // infinite
    EXPECT_EQ(scene.materials[2].layers(), uint32_t(scene::kLayerTransmission));  // thickness 0: thin-walled
    EXPECT_EQ(scene.materials[3].layers(), 0u);                            // a volume needs transmission
    EXPECT_FLOAT_EQ(scene.materials[4].transmissionFactor, 1.0f);
    EXPECT_FLOAT_EQ(scene.materials[4].thicknessFactor, 0.0f);
    EXPECT_FLOAT_EQ(scene.materials[4].attenuationDistance, 0.0f);
    expectVec(scene.materials[4].attenuationColor, {1.0f, 0.5f, 0.0f});
    EXPECT_TRUE(hasWarning(scene, "transmissionFactor 3 is outside [0, 1] (using 1)"));
    EXPECT_TRUE(hasWarning(scene, "thicknessFactor -1 is outside [0, inf] (using 0)"));
    EXPECT_TRUE(hasWarning(scene, "attenuationDistance 0 is not > 0: no absorption"));
    EXPECT_TRUE(hasWarning(scene, "attenuationColor 2 is outside [0, 1] (using 1)"));
    EXPECT_TRUE(hasWarning(scene, "attenuationColor -1 is outside [0, 1] (using 0)"));
    EXPECT_EQ(scene.report.warnings.size(), 5u);
}

TEST(GltfFeatures, IridescenceExtension) {
    // Factor, IOR, thickness range, both textures (linear), the defaults (IOR 1.3, 100 … 400 nm;
    // factor 0: no layer), clamping, and a film of thickness 0 everywhere (no layer).
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng());
    b.doc["extensionsUsed"] = {"KHR_materials_iridescence"};
    b.doc["materials"] = Json::array({
        {{"extensions",
          {{"KHR_materials_iridescence",
            {{"iridescenceFactor", 0.8}, {"iridescenceIor", 1.8}, {"iridescenceThicknessMinimum", 200},
             {"iridescenceThicknessMaximum", 600}, {"iridescenceTexture", {{"index", 0}}},
             {"iridescenceThicknessTexture", {{"index", 0}}}}}}}},
        {{"extensions", {{"KHR_materials_iridescence", {{"iridescenceFactor", 1}}}}}},
        {{"extensions", {{"KHR_materials_iridescence", {{"iridescenceIor", 1.5}}}}}},
        {{"extensions", {{"KHR_materials_iridescence", {{"iridescenceFactor", 1}, {"iridescenceThicknessMaximum", 0}}}}}},
        {{"extensions",
          {{"KHR_materials_iridescence", {{"iridescenceFactor", 2}, {"iridescenceIor", 0.5}, {"iridescenceThicknessMinimum", -5}}}}}}});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 5u);
    const scene::Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.iridescenceFactor, 0.8f);
    EXPECT_FLOAT_EQ(m.iridescenceIor, 1.8f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMinimum, 200.0f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMaximum, 600.0f);
    ASSERT_TRUE(m.iridescence.present() && m.iridescenceThickness.present());
    EXPECT_FALSE(scene.images.at(size_t(m.iridescence.image)).srgb);
    EXPECT_EQ(m.layers(), uint32_t(scene::kLayerIridescence));
    const scene::Material& defaults = scene.materials[1];
    EXPECT_FLOAT_EQ(defaults.iridescenceIor, 1.3f);
    EXPECT_FLOAT_EQ(defaults.iridescenceThicknessMinimum, 100.0f);
    EXPECT_FLOAT_EQ(defaults.iridescenceThicknessMaximum, 400.0f);
    EXPECT_EQ(defaults.layers(), uint32_t(scene::kLayerIridescence));
    EXPECT_EQ(scene.materials[2].layers(), 0u);  // factor 0
    EXPECT_EQ(scene.materials[3].layers(), 0u);  // thickness 0 everywhere
    EXPECT_FLOAT_EQ(scene.materials[4].iridescenceFactor, 1.0f);
    EXPECT_FLOAT_EQ(scene.materials[4].iridescenceIor, 1.0f);
    EXPECT_FLOAT_EQ(scene.materials[4].iridescenceThicknessMinimum, 0.0f);
    EXPECT_TRUE(hasWarning(scene, "iridescenceFactor 2 is outside [0, 1] (using 1)"));
    EXPECT_TRUE(hasWarning(scene, "iridescenceIor 0.5 is outside [1, inf] (using 1)"));
    EXPECT_TRUE(hasWarning(scene, "iridescenceThicknessMinimum -5 is outside [0, inf] (using 0)"));
    EXPECT_EQ(scene.report.warnings.size(), 3u);
}

TEST(GltfFeatures, SpecularGlossinessIsConvertedToTheSpecularLayer) {
    // diffuse → base colour (factor and sRGB texture), metallic 0, roughness = 1 − glossiness (a
    // derived texture from the specularGlossiness alpha), specular colour = specularFactor × the
    // texture's sRGB RGB with IOR 0 (f0 = specular colour); without textures, factors alone.
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng({200, 100, 50, 64}));  // alpha 64: glossiness 0.25 there
    b.doc["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
    b.doc["materials"] = Json::array({
        {{"extensions",
          {{"KHR_materials_pbrSpecularGlossiness",
            {{"diffuseFactor", {0.5, 0.25, 1.0, 0.75}}, {"specularFactor", {0.5, 0.5, 0.25}}, {"glossinessFactor", 0.5},
             {"diffuseTexture", {{"index", 0}}}, {"specularGlossinessTexture", {{"index", 0}}}}}}}},
        {{"extensions", {{"KHR_materials_pbrSpecularGlossiness", {{"glossinessFactor", 0.8}, {"specularFactor", {0.04, 0.04, 0.04}}}}}}},
        {{"pbrMetallicRoughness", {{"metallicFactor", 0.3}}},
         {"extensions", {{"KHR_materials_pbrSpecularGlossiness", Json::object()}}}}});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.materials.size(), 3u);
    const scene::Material& m = scene.materials[0];
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_EQ(m.metallicFactor, 0.0f);
    EXPECT_EQ(m.ior, 0.0f);
    EXPECT_EQ(m.specularFactor, 1.0f);
    expectVec(m.specularColorFactor, {0.5f, 0.5f, 0.25f});
    ASSERT_TRUE(m.baseColor.present() && m.specularColor.present() && m.metallicRoughness.present());
    EXPECT_TRUE(scene.images.at(size_t(m.baseColor.image)).srgb);
    EXPECT_TRUE(scene.images.at(size_t(m.specularColor.image)).srgb);
    const scene::Image& roughness = scene.images.at(size_t(m.metallicRoughness.image));
    EXPECT_FALSE(roughness.srgb);
    EXPECT_EQ(m.roughnessFactor, 1.0f);
    // Texel 0: glossiness 0.5 × 64/255 → roughness G = 255 − 32 = 223; the others (alpha 255): 128.
    EXPECT_EQ(roughness.rgba8[1], 223);
    EXPECT_EQ(roughness.rgba8[2], 0);  // metallic 0
    EXPECT_EQ(roughness.rgba8[5], 128);
    EXPECT_EQ(m.layers(), uint32_t(scene::kLayerSpecular));
    EXPECT_FLOAT_EQ(scene.materials[1].roughnessFactor, 0.2f);
    EXPECT_FALSE(scene.materials[1].metallicRoughness.present());
    // The extension replaces the metallic-roughness values; its defaults: white diffuse, f0 1,
    // glossiness 1 (roughness 0).
    EXPECT_EQ(scene.materials[2].metallicFactor, 0.0f);
    EXPECT_EQ(scene.materials[2].baseColorFactor, glm::vec4(1.0f));
    EXPECT_EQ(scene.materials[2].roughnessFactor, 0.0f);
    EXPECT_TRUE(scene.report.warnings.empty());
}

TEST(GltfFeatures, MaterialVariants) {
    // Root variant names, per-primitive mappings (one mapping for two variants), selection by
    // name, back to the defaults, and the error for an unknown name.
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng());
    b.doc["extensionsUsed"] = {"KHR_materials_variants"};
    b.doc["materials"] = Json::array({Json::object(), {{"name", "red"}}, {{"name", "blue"}}});
    b.doc["meshes"][0]["primitives"][0]["extensions"] = {
        {"KHR_materials_variants", {{"mappings", {{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1, 2}}}}}}}};
    b.doc["extensions"] = {{"KHR_materials_variants", {{"variants", Json::array({Json{{"name", "Red"}}, Json{{"name", "Blue"}}, Json{{"name", "Gold"}}})}}}};
    scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.variants, (std::vector<std::string>{"Red", "Blue", "Gold"}));
    ASSERT_EQ(scene.drawVariants.size(), 1u);
    EXPECT_EQ(scene.draws[0].material, 0u);
    scene::selectVariant(scene, scene::variantIndex(scene, "Blue"));
    EXPECT_EQ(scene.draws[0].material, 2u);
    scene::selectVariant(scene, 0);
    EXPECT_EQ(scene.draws[0].material, 1u);
    scene::selectVariant(scene, std::nullopt);
    EXPECT_EQ(scene.draws[0].material, 0u);
    try {
        (void)scene::variantIndex(scene, "Green");
        ADD_FAILURE() << "no error for an unknown variant";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("has no variant 'Green' (its variants: Red, Blue, Gold)"), std::string::npos)
            << e.what();
    }
    EXPECT_TRUE(scene.report.warnings.empty());
}

// A triangle whose material uses `png` for all five textures, plus samplers.
assets::test::GltfBuilder fiveTextureModel(const Bytes& png) {
    GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int uv = b.addFloats({0, 0, 1, 0, 0, 1}, "VEC2", 2);
    b.doc["images"] = Json::array({{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}, {"name", "tex"}}});
    b.doc["samplers"] = Json::array({{{"magFilter", 9728}, {"minFilter", 9984}, {"wrapS", 33071}, {"wrapT", 33648}},
                                     {{"minFilter", 9729}},
                                     Json::object()});
    b.doc["textures"] = Json::array({{{"source", 0}, {"sampler", 0}}, {{"source", 0}, {"sampler", 1}}, {{"source", 0}}});
    b.doc["materials"] = Json::array({{
        {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 1}}}}},
        {"normalTexture", {{"index", 2}, {"scale", 0.5}}},
        {"occlusionTexture", {{"index", 1}, {"strength", 0.25}}},
        {"emissiveTexture", {{"index", 2}, {"texCoord", 1},
                             {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 0.5}, {"scale", {2, 3}}, {"texCoord", 0}}}}}}},
    }});
    b.doc["extensionsUsed"] = {"KHR_texture_transform"};
    const int mesh = b.addMesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, b.addIndices({0, 1, 2}), 0);
    b.setScene({b.addNode({{"mesh", mesh}})});
    return b;
}

TEST(GltfFeatures, PrimitivesOverTheSameAccessorsShareTheirGeometry) {
    // Three meshes over one accessor set, each with a material of its own (as exporters write a
    // material per mesh): the plain two share one conversion; the normal-mapped one gets its own,
    // with generated tangents. A fourth over other accessors has its own too.
    test::TempDir dir;
    GltfBuilder b = fiveTextureModel(makePng(1, 1, 8, 6, {255, 255, 255, 255}));
    const Json triangle = b.doc["meshes"][0]["primitives"][0];
    const int pos = triangle["attributes"]["POSITION"], uv = triangle["attributes"]["TEXCOORD_0"], indices = triangle["indices"];
    b.doc["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}});
    b.doc["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorFactor", {0, 1, 0, 1}}}}});
    const Json attributes = {{"POSITION", pos}, {"TEXCOORD_0", uv}};
    const int red = b.addMesh(attributes, indices, 1), green = b.addMesh(attributes, indices, 2);
    const int other = b.addMesh({{"POSITION", b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3)}}, indices, 1);
    b.setScene({b.addNode({{"mesh", 0}}), b.addNode({{"mesh", red}}), b.addNode({{"mesh", green}}), b.addNode({{"mesh", other}})});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()), {.prepareGeometry = false});
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    ASSERT_EQ(scene.draws.size(), 4u);
    EXPECT_EQ(scene.vertices.size(), 9u);  // three conversions of three vertices
    EXPECT_EQ(scene.indices.size(), 9u);
    const scene::Draw &mapped = scene.draws[0], &plainRed = scene.draws[1], &plainGreen = scene.draws[2], &own = scene.draws[3];
    EXPECT_EQ(plainRed.firstIndex, plainGreen.firstIndex);
    EXPECT_NE(plainRed.material, plainGreen.material);
    EXPECT_NE(mapped.firstIndex, plainRed.firstIndex);
    EXPECT_NE(own.firstIndex, plainRed.firstIndex);
    EXPECT_NE(own.firstIndex, mapped.firstIndex);
    // The note of a shared conversion is given once: one primitive's triangles were dropped.
    const scene::Scene degenerate = loadGltf(degenerateMeshes(1).writeGltf(dir / "degenerate"));
    GltfBuilder twice = degenerateMeshes(1);
    twice.doc["meshes"].push_back(twice.doc["meshes"][0]);
    twice.setScene({0, twice.addNode({{"mesh", 1}})});
    const scene::Scene shared = loadGltf(twice.writeGltf(dir / "twice"));
    EXPECT_EQ(shared.report.notes, degenerate.report.notes);
    EXPECT_EQ(shared.vertices.size(), degenerate.vertices.size());
    EXPECT_EQ(shared.draws.size(), 2u);
}

TEST(GltfFeatures, TexturesSamplersAndTextureTransform) {
    test::TempDir dir;
    const scene::Scene scene = loadGltf(fiveTextureModel(smallPng({10, 20, 30, 40})).writeGlb(dir.path()));
    // One image used as sRGB (base colour, emissive) and linear (the rest): two entries.
    ASSERT_EQ(scene.images.size(), 2u);
    const scene::Material& m = scene.materials.at(0);
    const scene::Image& srgb = scene.images.at(size_t(m.baseColor.image));
    const scene::Image& linear = scene.images.at(size_t(m.metallicRoughness.image));
    EXPECT_TRUE(srgb.srgb);
    EXPECT_FALSE(linear.srgb);
    EXPECT_EQ(m.emissive.image, m.baseColor.image);
    EXPECT_EQ(m.normal.image, m.metallicRoughness.image);
    EXPECT_EQ(m.occlusion.image, m.metallicRoughness.image);
    EXPECT_EQ(srgb.name, "tex");
    EXPECT_EQ(srgb.width, 2u);
    EXPECT_EQ(srgb.height, 2u);
    ASSERT_EQ(srgb.rgba8.size(), 16u);
    EXPECT_EQ(srgb.rgba8, linear.rgba8);
    EXPECT_EQ((std::vector<uint8_t>(srgb.rgba8.begin(), srgb.rgba8.begin() + 8)), (std::vector<uint8_t>{10, 20, 30, 40, 255, 255, 255, 255}));

    EXPECT_EQ(m.baseColor.sampler, 0);
    EXPECT_EQ(m.metallicRoughness.sampler, 1);
    EXPECT_EQ(m.normal.sampler, -1);
    EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
    EXPECT_FLOAT_EQ(m.occlusionStrength, 0.25f);
    // KHR_texture_transform, with its texCoord overriding the textureInfo's.
    EXPECT_EQ(m.emissive.texCoord, 0u);
    EXPECT_EQ(m.emissive.transform.offset, glm::vec2(0.5f, 0.25f));
    EXPECT_FLOAT_EQ(m.emissive.transform.rotation, 0.5f);
    EXPECT_EQ(m.emissive.transform.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_TRUE(m.baseColor.transform.identity());

    ASSERT_EQ(scene.samplers.size(), 3u);
    const scene::Sampler& s0 = scene.samplers[0];
    EXPECT_EQ(s0.magFilter, scene::Filter::Nearest);
    EXPECT_EQ(s0.minFilter, scene::Filter::Nearest);
    EXPECT_EQ(s0.mipFilter, scene::Filter::Nearest);
    EXPECT_TRUE(s0.mipmaps);
    EXPECT_EQ(s0.wrapU, scene::Wrap::ClampToEdge);
    EXPECT_EQ(s0.wrapV, scene::Wrap::MirroredRepeat);
    EXPECT_EQ(scene.samplers[1].minFilter, scene::Filter::Linear);
    EXPECT_FALSE(scene.samplers[1].mipmaps);  // LINEAR: no mip sampling
    EXPECT_TRUE(scene.samplers[2].mipmaps);   // undefined: trilinear default
    EXPECT_EQ(scene.samplers[2].wrapU, scene::Wrap::Repeat);
}

TEST(GltfFeatures, SixteenBitPngRoundedTo8Bits) {
    test::TempDir dir;
    // RGBA16, big-endian samples: 0x8080 → 128, 0x00FF → 1, 0xFFFF → 255, 0x7F80 → 127 (round(v / 257)).
    Bytes pixels = {0x80, 0x80, 0x00, 0xFF, 0xFF, 0xFF, 0x7F, 0x80};
    const scene::Scene scene = loadGltf(fiveTextureModel(makePng(1, 1, 16, 6, pixels)).writeGlb(dir.path()));
    ASSERT_EQ(scene.images.size(), 2u);
    EXPECT_EQ(scene.images[0].rgba8, (std::vector<uint8_t>{128, 1, 255, 127}));
}

TEST(GltfFeatures, ExternalImageFilesAndDotSegmentsInsideTheFolder) {
    test::TempDir dir;
    GltfBuilder b = fiveTextureModel(smallPng());
    b.doc["images"][0] = {{"uri", "textures/../textures/my%20tex.png"}};
    writeFile(dir / "textures" / "my tex.png", smallPng({1, 2, 3, 4}));
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    ASSERT_EQ(scene.images.size(), 2u);
    EXPECT_EQ(scene.images[0].rgba8[0], 1);
    EXPECT_EQ(scene.images[0].name, "textures/../textures/my%20tex.png");
}

TEST(GltfFeatures, ImagesBehindUnsupportedExtensionsAreNotDecoded) {
    // A texture whose only image is named by an extension Candela does not read (here a made-up
    // EXT_texture_avif-style one, whose image stb_image cannot read either) is dropped with a
    // warning, its image never decoded; a texture with a core source beside it uses that source.
    test::TempDir dir;
    GltfBuilder b = fiveTextureModel(smallPng());
    writeFile(dir / "pic.avif", std::string("....ftypavif not really"));
    assets::test::writeFile(dir / "ok.png", smallPng({7, 7, 7, 255}));
    b.doc["images"] = Json::array({{{"uri", "pic.avif"}}, {{"uri", "ok.png"}}});
    b.doc["textures"] = Json::array({{{"source", 1}, {"extensions", {{"EXT_texture_avif", {{"source", 0}}}}}},
                                     {{"extensions", {{"EXT_texture_avif", {{"source", 0}}}}}},
                                     {{"source", 1}}});
    b.doc["extensionsUsed"] = {"EXT_texture_avif", "KHR_texture_transform"};
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    const scene::Material& m = scene.materials.at(0);
    ASSERT_TRUE(m.baseColor.present());
    EXPECT_EQ(scene.images.at(size_t(m.baseColor.image)).rgba8[0], 7);
    EXPECT_FALSE(m.metallicRoughness.present());  // texture 1: no source Candela reads
    EXPECT_TRUE(hasWarning(scene, "material 0 metallicRoughnessTexture: texture 1 has no image source (ignored)"));
    EXPECT_TRUE(hasWarning(scene, "extension EXT_texture_avif is not supported (ignored)"));
    EXPECT_EQ(scene.images.size(), 2u);  // image 1 as sRGB and as linear; the AVIF never decoded
}

TEST(GltfFeatures, LightsInWorldSpace) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = Json::array({
        {{"type", "directional"}, {"color", {1, 0.5, 0.25}}, {"intensity", 3}},
        {{"type", "point"}, {"intensity", 100}, {"range", 5}},
        {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.4}}}},
    });
    auto light = [](int i) { return Json{{"KHR_lights_punctual", {{"light", i}}}}; };
    // Rotated 90° about +Y: local −Z becomes world −X.
    const int sun = b.addNode({{"extensions", light(0)}, {"rotation", {0, std::sqrt(0.5), 0, std::sqrt(0.5)}}});
    const int bulb = b.addNode({{"extensions", light(1)}, {"translation", {1, 2, 3}}});
    const int spotChild = b.addNode({{"extensions", light(2)}, {"translation", {0, 1, 0}}});
    // A scaled, translated parent: positions scale, directions stay unit.
    const int parent = b.addNode({{"translation", {0, 0, 5}}, {"scale", {2, 2, 2}}, {"rotation", {std::sqrt(0.5), 0, 0, std::sqrt(0.5)}}, {"children", {spotChild}}});
    b.setScene({0, sun, bulb, parent});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].type, scene::LightType::Directional);
    expectVec(scene.lights[0].direction, {-1, 0, 0});
    expectVec(scene.lights[0].color, {1, 0.5f, 0.25f});
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, 3.0f);
    EXPECT_EQ(scene.lights[1].type, scene::LightType::Point);
    expectVec(scene.lights[1].position, {1, 2, 3});
    EXPECT_FLOAT_EQ(scene.lights[1].range, 5.0f);
    EXPECT_FLOAT_EQ(scene.lights[1].intensity, 100.0f);
    const scene::Light& spot = scene.lights[2];
    EXPECT_EQ(spot.type, scene::LightType::Spot);
    // Parent rotates 90° about +X: local (0,1,0)·2 → (0,0,2), plus (0,0,5); −Z → +Y.
    expectVec(spot.position, {0, 0, 7}, 1e-5f);
    expectVec(spot.direction, {0, 1, 0}, 1e-6f);
    EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.1f);
    EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.4f);
}

TEST(GltfFeatures, CamerasInWorldSpaceWithoutScale) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    b.doc["cameras"] = Json::array({
        {{"type", "perspective"}, {"name", "persp"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"aspectRatio", 1.5}}}},
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 2}, {"ymag", 3}, {"znear", 0.5}, {"zfar", 50}}}},
    });
    const int c0 = b.addNode({{"camera", 0}, {"translation", {1, 2, 3}}, {"scale", {4, 4, 4}}, {"rotation", {0, std::sqrt(0.5), 0, std::sqrt(0.5)}}});
    const int c1 = b.addNode({{"camera", 1}, {"name", "orthoNode"}});
    b.setScene({0, c0, c1});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    ASSERT_EQ(scene.cameras.size(), 2u);
    const scene::Camera& p = scene.cameras[0];
    EXPECT_EQ(p.name, "persp");
    EXPECT_TRUE(p.perspective);
    EXPECT_FLOAT_EQ(p.yfov, 0.5f);
    EXPECT_FLOAT_EQ(p.aspectRatio, 1.5f);
    EXPECT_FLOAT_EQ(p.znear, 0.1f);
    EXPECT_FLOAT_EQ(p.zfar, 0.0f);  // absent: infinite
    expectVec(glm::vec3(p.world[3]), {1, 2, 3});
    expectVec(glm::vec3(p.world[0]), {0, 0, -1});  // scale removed, rotation kept
    expectVec(-glm::vec3(p.world[2]), {-1, 0, 0});  // looks down local −Z → world −X
    const scene::Camera& o = scene.cameras[1];
    EXPECT_EQ(o.name, "orthoNode");
    EXPECT_FALSE(o.perspective);
    EXPECT_FLOAT_EQ(o.xmag, 2.0f);
    EXPECT_FLOAT_EQ(o.ymag, 3.0f);
    EXPECT_FLOAT_EQ(o.zfar, 50.0f);
}

TEST(GltfFeatures, PointsAndLinesAreDrawnUnshadedWithoutNormals) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3", 3);
    const int normals = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    const int colours = b.addFloats({1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, "VEC3", 3);
    auto& primitives = b.doc["meshes"][0]["primitives"];
    primitives.push_back({{"attributes", {{"POSITION", pos}, {"COLOR_0", colours}}}, {"mode", kPoints}});
    primitives.push_back({{"attributes", {{"POSITION", pos}}}, {"mode", kLines}});
    primitives.push_back({{"attributes", {{"POSITION", pos}, {"NORMAL", normals}}}, {"mode", kLineLoop}});
    primitives.push_back({{"attributes", {{"POSITION", pos}}}, {"mode", kLineStrip}});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty());
    ASSERT_EQ(scene.draws.size(), 5u);
    const auto indicesOf = [&](const scene::Draw& d) {
        std::vector<uint32_t> out(scene.indices.begin() + d.firstIndex, scene.indices.begin() + d.firstIndex + d.indexCount);
        const uint32_t first = out.empty() ? 0 : *std::min_element(out.begin(), out.end());
        for (uint32_t& i : out) i -= first;
        return out;
    };
    EXPECT_EQ(scene.draws[0].topology, scene::Topology::Triangles);
    EXPECT_FALSE(scene.draws[0].unshaded);  // triangles get flat normals
    EXPECT_EQ(scene.draws[1].topology, scene::Topology::Points);
    EXPECT_TRUE(scene.draws[1].unshaded);
    EXPECT_EQ(indicesOf(scene.draws[1]), (std::vector<uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(scene.draws[2].topology, scene::Topology::Lines);
    EXPECT_EQ(indicesOf(scene.draws[2]), (std::vector<uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(scene.draws[3].topology, scene::Topology::Lines);
    EXPECT_FALSE(scene.draws[3].unshaded);  // it has normals: lit
    EXPECT_EQ(indicesOf(scene.draws[3]), (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 0}));
    EXPECT_EQ(indicesOf(scene.draws[4]), (std::vector<uint32_t>{0, 1, 1, 2, 2, 3}));
    // Points keep their vertices and colours (no flat-normal split).
    const uint32_t first = scene.indices[scene.draws[1].firstIndex];
    expectVec(glm::vec3(scene.vertices[first + 1].color), {0, 1, 0});
    // An odd LINES index count drops the last index, with a warning.
    primitives[2]["indices"] = b.addIndices({0, 1, 2});
    const scene::Scene odd = loadGltf(b.writeGltf(dir.path()));
    EXPECT_EQ(odd.draws[2].indexCount, 2u);
    EXPECT_EQ(odd.report.warnings, (std::vector<std::string>{"mesh 0 primitive 2: 3 indices is not a multiple of 2 (extra dropped)"}));
}

TEST(GltfFeatures, OptionalUnsupportedExtensionWarnsAndLoads) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    b.doc["extensionsUsed"] = {"EXT_made_up", "KHR_texture_transform"};
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    EXPECT_EQ(scene.draws.size(), 1u);
    EXPECT_EQ(scene.report.warnings, (std::vector<std::string>{"extension EXT_made_up is not supported (ignored)"}));
}

TEST(GltfFeatures, DefaultSceneAndSceneless) {
    test::TempDir dir;
    GltfBuilder b;
    b.addTriangle();
    const int second = b.addNode({{"mesh", 0}, {"translation", {5, 0, 0}}});
    b.doc["scenes"] = Json::array({{{"nodes", {0}}}, {{"nodes", {second}}}});
    b.doc["scene"] = 1;
    scene::Scene scene = loadGltf(b.writeGltf(dir / "a"));
    ASSERT_EQ(scene.draws.size(), 1u);
    expectVec(scene.bounds.min, {5, 0, 0});
    // Without scenes every parentless node is drawn, with a warning.
    b.doc.erase("scenes");
    b.doc.erase("scene");
    scene = assets::loadGltf(b.writeGltf(dir / "b"));
    EXPECT_EQ(scene.draws.size(), 2u);
    expectVec(scene.bounds.min, {0, 0, 0});
    expectVec(scene.bounds.max, {6, 1, 0});
    EXPECT_TRUE(hasWarning(scene, "no scene defined"));
    // A scene without nodes is valid and draws nothing: it loads, with one warning saying so.
    b.doc["scenes"] = Json::array({{{"nodes", Json::array()}}});
    scene = assets::loadGltf(b.writeGltf(dir / "c"));
    EXPECT_TRUE(scene.draws.empty());
    EXPECT_EQ(scene.report.warnings, std::vector<std::string>{"nothing to draw: scene 0 has no nodes"});
}

TEST(GltfFeatures, UnindexedPrimitiveAndNonFiniteNormalRepaired) {
    test::TempDir dir;
    GltfBuilder b;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1}, "VEC3", 3);
    const int nrm = b.addFloats({0, 0, 2, 0, 0, 1, nan, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}, {"NORMAL", nrm}})}})});
    const scene::Scene scene = loadGltf(b.writeGltf(dir.path()));
    EXPECT_EQ(scene.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    expectVec(scene.vertices[0].normal, {0, 0, 1});  // normalized
    expectVec(scene.vertices[2].normal, {0, 0, 1});  // NaN replaced
    EXPECT_TRUE(hasWarning(scene, "NORMAL: 1 non-finite value replaced by the default"));
}

}  // namespace
}  // namespace candela::assets::test::gltf_features_test
