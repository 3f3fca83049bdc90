// EXT_meshopt_compression: compressed views (every mode and filter) load exactly like their
// plain twins, in .glb and .gltf, with placeholder buffers that have no URI; malformed extension
// objects and streams fail with one line naming the bufferView.
#include "compressed_test_util.h"
#include "meshopt_test_util.h"


namespace candela::assets::test::gltf_meshopt_test {
namespace {

TEST(GltfMeshopt, QuadLoadsExactlyLikeItsPlainTwin) {
    test::TempDir dir;
    const scene::Scene plain = loadGltf(meshoptQuad(false).writeGlb(dir.path(), "plain"));
    const scene::Scene glb = loadGltf(meshoptQuad(true).writeGlb(dir.path(), "meshopt"));
    const scene::Scene gltf = loadGltf(meshoptQuad(true).writeGltf(dir.path(), "meshopt"));
    EXPECT_TRUE(glb.report.warnings.empty()) << glb.report.warnings.front();
    EXPECT_TRUE(gltf.report.warnings.empty()) << gltf.report.warnings.front();
    ASSERT_EQ(plain.indices.size(), 6u);
    EXPECT_NEAR(plain.vertices[1].normal.x, 0.6f, 0.02f);  // the octahedral filter decoded
    expectSameGeometry(plain, glb);
    expectSameGeometry(plain, gltf);
}

TEST(GltfMeshopt, IndexSequenceForAStrip) {
    test::TempDir dir;
    auto make = [](bool compress) {
        GltfBuilder b;
        const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
        const int pos = b.addAccessor(addMeshoptView(b, meshoptAttributes(positions, 3), compress), kFloat, 4, "VEC3");
        const int idx = b.addAccessor(addMeshoptView(b, meshoptIndices({0, 1, 2, 3}, "INDICES"), compress, false),
                                      kUnsignedShort, 4, "SCALAR");
        b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}}, idx, -1, kStrip)}})});
        return b;
    };
    const scene::Scene plain = loadGltf(make(false).writeGlb(dir.path(), "plain"));
    const scene::Scene compressed = loadGltf(make(true).writeGlb(dir.path(), "meshopt"));
    EXPECT_EQ(plain.indices.size(), 6u);
    expectSameGeometry(plain, compressed);
}

// Animation keys: times plain codec, rotations through the QUATERNION filter (normalized shorts),
// translations through the EXPONENTIAL filter: the pose is the same at every time.
TEST(GltfMeshopt, AnimationKeysDecodeToThePlainPose) {
    test::TempDir dir;
    auto make = [](bool compress) {
        GltfBuilder b;
        b.addTriangle();
        const std::vector<float> times = {0, 0.5f, 1.0f};
        const std::vector<float> rotations = {0, 0, 0, 1, 0, 0.3826834f, 0, 0.9238795f, 0, 0.7071068f, 0, 0.7071068f};
        const std::vector<float> moves = {0, 0, 0, 1.5f, -2.25f, 0.125f, 3, 1, -1};
        const int t = b.addAccessor(addMeshoptView(b, meshoptAttributes(times, 1), compress, false), kFloat, 3, "SCALAR");
        b.doc["accessors"][t]["min"] = {0};
        b.doc["accessors"][t]["max"] = {1};
        const int r = b.addAccessor(addMeshoptView(b, meshoptQuaternion(rotations), compress, false), kShort, 3, "VEC4", true);
        const int m = b.addAccessor(addMeshoptView(b, meshoptExponential(moves, 3), compress, false), kFloat, 3, "VEC3");
        b.doc["animations"] = Json::array({{{"samplers", {{{"input", t}, {"output", r}}, {{"input", t}, {"output", m}}}},
                                            {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}},
                                                          {{"sampler", 1}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}});
        b.doc["extensionsUsed"] = compress ? Json{"EXT_meshopt_compression", "KHR_mesh_quantization"} : Json{"KHR_mesh_quantization"};
        return b;
    };
    const scene::Scene plain = loadGltf(make(false).writeGlb(dir.path(), "plain"));
    const scene::Scene compressed = loadGltf(make(true).writeGlb(dir.path(), "meshopt"));
    ASSERT_EQ(compressed.animations.size(), 1u);
    pose::ScenePose a(plain, pose::selectAnimations(plain, {}));
    pose::ScenePose b(compressed, pose::selectAnimations(compressed, {}));
    for (double time : {0.0, 0.3, 0.5, 0.8, 1.0}) {
        a.evaluate(time);
        b.evaluate(time);
        EXPECT_EQ(a.bounds().min, b.bounds().min) << "t " << time;
        EXPECT_EQ(a.bounds().max, b.bounds().max) << "t " << time;
    }
    b.evaluate(0.999);  // (1.0 wraps to 0: animations loop)
    EXPECT_NEAR(b.bounds().min.x, 2.997f, 2e-3f);  // the exponential filter kept the translation
    EXPECT_NEAR(b.bounds().min.z, -1.998f, 5e-3f);  // translation z -0.998 and the quarter turn: corner x 1 → z -1
}

// ---- files from the reference encoder -------------------------------------------------------------

// `model` (under ../shared/assets/models) through gltfpack -cc, in `dir`.
fs::path gltfpacked(const TempDir& dir, const std::string& model) {
    const fs::path out = dir.path() / "packed.glb";
    gltfpack(sharedModels() / model, out);
    return out;
}

TEST(GltfMeshopt, GltfpackedFoxAnimatesLikeTheOriginal) {
    REQUIRE_MODELS();
    test::TempDir dir;
    const scene::Scene original = loadGltf(sharedModels() / "Fox/glTF-Binary/Fox.glb");
    const scene::Scene packed = loadGltf(gltfpacked(dir, "Fox/glTF-Binary/Fox.glb"));
    EXPECT_TRUE(packed.report.warnings.empty()) << packed.report.warnings.front();
    ASSERT_EQ(packed.animations.size(), original.animations.size());
    for (size_t i = 0; i < original.animations.size(); ++i) EXPECT_EQ(packed.animations[i].name, original.animations[i].name);
    EXPECT_EQ(packed.skins.size(), original.skins.size());
    EXPECT_EQ(packed.indices.size(), original.indices.size());
    // gltfpack resamples the animations at 30 Hz and quantizes rotations to 12 bits: the poses move
    // by up to 0.4% of the fox's size (measured). A decoding error (a wrong filter, stride or key
    // order) moves them by its whole size; the bound is 1%.
    for (const char* animation : {"Survey", "Walk", "Run"})
        expectSamePosedBounds(original, packed, {animation}, 1e-2f, {0.0, 0.4, 1.1});
}

TEST(GltfMeshopt, GltfpackedDamagedHelmetMatchesTheOriginal) {
    REQUIRE_MODELS();
    test::TempDir dir;
    const scene::Scene original = loadGltf(sharedModels() / "DamagedHelmet/glTF-Binary/DamagedHelmet.glb");
    const scene::Scene packed = loadGltf(gltfpacked(dir, "DamagedHelmet/glTF-Binary/DamagedHelmet.glb"));
    EXPECT_TRUE(packed.report.warnings.empty()) << packed.report.warnings.front();
    // Full detail (the levels of detail of the two differ with the quantized positions).
    EXPECT_EQ(packed.report.geometry.indexBytes, original.report.geometry.indexBytes);
    expectBoundsNear(packed.bounds, original.bounds, 2e-3f);
}

// ---- malformed ------------------------------------------------------------------------------------

struct MeshoptCase {
    std::string name;
    std::function<void(GltfBuilder&)> edit;  // on meshoptQuad(true); views 0 POSITION .. 3 indices
    std::string fragment;
};

void PrintTo(const MeshoptCase& c, std::ostream* os) { *os << c.name; }

class MeshoptBadInput : public testing::TestWithParam<MeshoptCase> {};

TEST_P(MeshoptBadInput, IsOneLineErrorNamingTheView) {
    test::TempDir dir;
    GltfBuilder b = meshoptQuad(true);
    GetParam().edit(b);
    expectLoadFails(b.writeGlb(dir.path()), GetParam().fragment);
}

assets::test::Json& meshoptOf(GltfBuilder& b, int view) { return b.doc["bufferViews"][view]["extensions"]["EXT_meshopt_compression"]; }

std::vector<MeshoptCase> meshoptCases() {
    return {
        {"UnknownMode", [](GltfBuilder& b) { meshoptOf(b, 0)["mode"] = "VERTICES"; }, "bufferView 0 EXT_meshopt_compression: unknown mode 'VERTICES'"},
        {"UnknownFilter", [](GltfBuilder& b) { meshoptOf(b, 1)["filter"] = "POLAR"; }, "bufferView 1 EXT_meshopt_compression: unknown filter 'POLAR'"},
        {"StrideDiffersFromTheView", [](GltfBuilder& b) { b.doc["bufferViews"][0]["byteStride"] = 16; },
         "byteStride 12 differs from the bufferView's 16"},
        {"LengthNotCountTimesStride", [](GltfBuilder& b) { meshoptOf(b, 0)["count"] = 5; },
         "the bufferView's byteLength 48 is not count 5 × byteStride 12"},
        {"AttributeStrideNotMultipleOf4", [](GltfBuilder& b) {
             meshoptOf(b, 0)["byteStride"] = 6;
             meshoptOf(b, 0)["count"] = 8;
             b.doc["bufferViews"][0].erase("byteStride");
         }, "ATTRIBUTES need a byteStride divisible by 4 and at most 256, not 6"},
        {"TrianglesWithAFilter", [](GltfBuilder& b) { meshoptOf(b, 3)["filter"] = "OCTAHEDRAL"; }, "TRIANGLES take no filter ('OCTAHEDRAL')"},
        {"TrianglesNotMultipleOf3", [](GltfBuilder& b) {
             meshoptOf(b, 3)["count"] = 4;
             meshoptOf(b, 3)["byteStride"] = 3;
             meshoptOf(b, 3)["mode"] = "INDICES";
         }, "INDICES need a byteStride of 2 or 4, not 3"},
        {"QuaternionOfStride4", [](GltfBuilder& b) { meshoptOf(b, 1)["filter"] = "QUATERNION"; }, "QUATERNION needs a byteStride of 8, not 4"},
        {"SourceOutsideTheBuffer", [](GltfBuilder& b) { meshoptOf(b, 0)["byteOffset"] = 100000; }, "lies outside buffer 0"},
        {"SourceBufferMissing", [](GltfBuilder& b) { meshoptOf(b, 0)["buffer"] = 7; }, "buffer 7 does not exist"},
        {"StreamDoesNotDecode", [](GltfBuilder& b) { meshoptOf(b, 0)["byteLength"] = 8; }, "the ATTRIBUTES data does not decode"},
        {"IndicesDoNotDecode", [](GltfBuilder& b) { meshoptOf(b, 3)["byteLength"] = 1; }, "the TRIANGLES data does not decode"},
        {"ClaimsMoreThanTheCodecProduces", [](GltfBuilder& b) {
             meshoptOf(b, 0)["count"] = 100000000;
             b.doc["bufferViews"][0]["byteLength"] = 1200000000;
         }, "compressed bytes cannot hold the 1200000000 bytes it claims"},
        {"ByteLengthMissing", [](GltfBuilder& b) { meshoptOf(b, 0).erase("byteLength"); }, "byteLength is missing"},
        {"ModeNotAString", [](GltfBuilder& b) { meshoptOf(b, 0)["mode"] = 0; },
         "bufferViews[0].extensions.EXT_meshopt_compression.mode: expected a string"},
        {"PlainViewOnTheFallbackBuffer", [](GltfBuilder& b) { b.doc["bufferViews"][0].erase("extensions"); },
         "bufferView 0 [0, +48) lies outside buffer 1 (3 bytes)"},
    };
}

INSTANTIATE_TEST_SUITE_P(Rows, MeshoptBadInput, testing::ValuesIn(meshoptCases()),
                         [](const testing::TestParamInfo<MeshoptCase>& row) { return row.param.name; });

}  // namespace
}  // namespace candela::assets::test::gltf_meshopt_test
