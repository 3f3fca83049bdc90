// KHR_draco_mesh_compression: a Draco quad loads exactly like its plain twin; the Khronos Draco
// samples load like their uncompressed versions; malformed streams and extension objects fail with
// one line naming the primitive.
#include "compressed_test_util.h"
#include "draco_test_util.h"

#include <cmath>

namespace candela::assets::test::gltf_draco_test {
namespace {

TEST(GltfDraco, QuadLoadsExactlyLikeItsPlainTwin) {
    test::TempDir dir;
    const DracoQuad quad;
    const scene::Scene plain = loadGltf(quad.plain().writeGlb(dir.path(), "plain"));
    const scene::Scene glb = loadGltf(quad.compressed().writeGlb(dir.path(), "draco"));
    const scene::Scene gltf = loadGltf(quad.compressed().writeGltf(dir.path(), "draco"));
    EXPECT_TRUE(glb.report.warnings.empty()) << glb.report.warnings.front();
    EXPECT_EQ(plain.indices.size(), 6u);
    expectSameGeometry(plain, glb);
    expectSameGeometry(plain, gltf);
}

TEST(GltfDraco, AttributesOutsideTheStreamStayPlainAndIntegerAccessorsKeepTheirType) {
    test::TempDir dir;
    DracoQuad quad;
    quad.uvs = {0, 1, 0.5f, 1, 0.5f, 0, 0, 0};
    // COLOR_0 is not in the Draco stream: read from its own accessor as usual.
    GltfBuilder b = quad.compressed();
    const int color = b.addFloats({1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, "VEC3", 3);
    b.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = color;
    // TEXCOORD_0 as normalized unsigned shorts (KHR_mesh_quantization): the decoder converts.
    b.doc["accessors"][2]["componentType"] = kUnsignedShort;
    b.doc["accessors"][2]["normalized"] = true;
    b.doc["extensionsUsed"].push_back("KHR_mesh_quantization");
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.vertices.size(), 4u);
    EXPECT_EQ(scene.vertices[1].color, glm::vec4(0, 1, 0, 1));
    EXPECT_NEAR(scene.vertices[1].uv0.x, 0.5f, 1.0f / 65535.0f);
    EXPECT_EQ(scene.vertices[1].uv0.y, 1.0f);
}

TEST(GltfDraco, StripPrimitiveIsDecodedAsTriangles) {
    test::TempDir dir;
    const DracoQuad quad;
    GltfBuilder b = quad.compressed();
    b.doc["meshes"][0]["primitives"][0]["mode"] = kStrip;
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    EXPECT_EQ(scene.indices.size(), 6u);
}

// ---- the Khronos samples: compressed and plain versions agree -------------------------------------

fs::path model(const std::string& name, const std::string& variant, const std::string& file) {
    return sharedModels() / name / variant / file;
}

// Same draws (index counts, materials), bounds within `tolerance` of the extent (quantization).
void expectSameShape(const scene::Scene& draco, const scene::Scene& plain, float tolerance) {
    ASSERT_EQ(draco.draws.size(), plain.draws.size());
    EXPECT_EQ(draco.indices.size(), plain.indices.size());
    expectBoundsNear(draco.bounds, plain.bounds, tolerance);
    for (size_t d = 0; d < plain.draws.size(); ++d) {
        EXPECT_EQ(draco.draws[d].indexCount, plain.draws[d].indexCount) << "draw " << d;
        EXPECT_EQ(draco.draws[d].material, plain.draws[d].material) << "draw " << d;
    }
}

// Khronos sample `name` from glTF-Draco/`dracoFile` and glTF-Binary/NAME.glb: the Draco one loads
// quietly, with the plain one's draws and bounds within 0.1% (its quantization).
struct Pair {
    scene::Scene draco, plain;
};
Pair loadPair(const std::string& name, const std::string& dracoFile) {
    // The levels of detail left out: the simplifier's choices follow the vertex order, which Draco
    // changes (CesiumMilkTruck's chains differ by 4 triangles); the full detail must match exactly.
    const LoadOptions fullDetail{.deferLevelsOfDetail = true};
    Pair pair{assets::loadGltf(model(name, "glTF-Draco", dracoFile), fullDetail),
              loadGltf(model(name, "glTF-Binary", name + ".glb"), fullDetail)};
    EXPECT_TRUE(pair.draco.report.warnings.empty()) << pair.draco.report.warnings.front();
    expectSameShape(pair.draco, pair.plain, 1e-3f);
    return pair;
}

TEST(GltfDraco, CesiumMilkTruckMatchesThePlainFile) {
    REQUIRE_MODELS();
    loadPair("CesiumMilkTruck", "CesiumMilkTruck.gltf");
}

TEST(GltfDraco, CesiumManSkinAndAnimationMatchThePlainFile) {
    REQUIRE_MODELS();
    const auto [draco, plain] = loadPair("CesiumMan", "CesiumMan.gltf");
    ASSERT_EQ(draco.skins.size(), plain.skins.size());
    ASSERT_EQ(draco.deformations.size(), plain.deformations.size());
    // Posed, the skinned bounds agree too: joints and weights came through.
    expectSamePosedBounds(draco, plain, {}, 1e-2f, {1.1});
}

TEST(GltfDraco, MorphPrimitivesTestKeepsItsTargets) {
    REQUIRE_MODELS();
    const auto [draco, plain] = loadPair("MorphPrimitivesTest", "MorphPrimitivesTest.gltf");
    ASSERT_EQ(draco.deformations.size(), plain.deformations.size());
    for (size_t i = 0; i < plain.deformations.size(); ++i)
        EXPECT_EQ(draco.deformations[i].targetCount, plain.deformations[i].targetCount);
}

// ---- malformed ------------------------------------------------------------------------------------

struct DracoCase {
    std::string name;
    std::function<void(GltfBuilder&)> json;        // edits the document
    std::function<void(Bytes&)> stream = nullptr;   // edits the Draco stream
    std::function<void(DracoQuad&)> quad = nullptr; // edits the quad before encoding
    std::string fragment;
};

void PrintTo(const DracoCase& c, std::ostream* os) { *os << c.name; }

class DracoBadInput : public testing::TestWithParam<DracoCase> {};

TEST_P(DracoBadInput, IsOneLineErrorNamingThePrimitive) {
    const DracoCase& row = GetParam();
    test::TempDir dir;
    DracoQuad quad;
    if (row.quad) row.quad(quad);
    Bytes stream = quad.encode();
    if (row.stream) row.stream(stream);
    GltfBuilder b = quad.compressed(stream);
    if (row.json) row.json(b);
    expectLoadFails(b.writeGlb(dir.path()), row.fragment);
}

assets::test::Json& primitiveOf(GltfBuilder& b) { return b.doc["meshes"][0]["primitives"][0]; }
assets::test::Json& dracoOf(GltfBuilder& b) { return primitiveOf(b)["extensions"]["KHR_draco_mesh_compression"]; }

// Accessors of DracoQuad::compressed(): 0 POSITION, 1 NORMAL, 2 TEXCOORD_0, 3 indices.
std::vector<DracoCase> dracoCases() {
    return {
        {"TruncatedStream", nullptr, [](Bytes& s) { s.resize(s.size() / 2); }, nullptr, "Draco decoding failed"},
        {"NotADracoStream", nullptr, [](Bytes& s) { std::fill(s.begin(), s.end(), uint8_t('x')); }, nullptr,
         "not a Draco stream"},
        {"BufferViewMissing", [](GltfBuilder& b) { dracoOf(b).erase("bufferView"); }, nullptr, nullptr,
         "KHR_draco_mesh_compression.bufferView: expected an index"},
        {"BufferViewOutOfRange", [](GltfBuilder& b) { dracoOf(b)["bufferView"] = 7; }, nullptr, nullptr,
         "KHR_draco_mesh_compression: bufferView 7 does not exist"},
        {"AttributesNotAnObject", [](GltfBuilder& b) { dracoOf(b)["attributes"] = 3; }, nullptr, nullptr,
         "KHR_draco_mesh_compression.attributes: expected an object"},
        {"AttributeIdNotInStream", [](GltfBuilder& b) { dracoOf(b)["attributes"]["NORMAL"] = 9; }, nullptr, nullptr,
         "attribute NORMAL: the Draco mesh has no attribute 9"},
        {"AttributeNotInPrimitive", [](GltfBuilder& b) { dracoOf(b)["attributes"]["TEXCOORD_1"] = 2; }, nullptr, nullptr,
         "attribute TEXCOORD_1: not among the primitive's attributes"},
        {"AccessorCountDiffers", [](GltfBuilder& b) { b.doc["accessors"][0]["count"] = 5; }, nullptr, nullptr,
         "attribute POSITION: the accessor counts 5, the Draco mesh has 4 vertices"},
        {"IndexCountDiffers", [](GltfBuilder& b) { b.doc["accessors"][3]["count"] = 3; }, nullptr, nullptr,
         "the indices accessor counts 3, the Draco mesh has 6"},
        {"ComponentCountDiffers", [](GltfBuilder& b) { b.doc["accessors"][2]["type"] = "VEC3"; }, nullptr, nullptr,
         "attribute TEXCOORD_0: the Draco attribute has 2 components, the accessor 3"},
        {"ValuesBeyondTheNormalizedType",
         [](GltfBuilder& b) {
             b.doc["accessors"][1]["componentType"] = kUnsignedByte;  // -1 has no unsigned normalized byte
             b.doc["accessors"][1]["normalized"] = true;
         },
         nullptr, [](DracoQuad& q) { q.normals = {0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1}; },
         "attribute NORMAL: decoded values do not fit the accessor's component type"},
        {"LinesMode", [](GltfBuilder& b) { primitiveOf(b)["mode"] = kLines; }, nullptr, nullptr,
         "mode 1 (Draco meshes are triangles or strips)"},
    };
}

INSTANTIATE_TEST_SUITE_P(Rows, DracoBadInput, testing::ValuesIn(dracoCases()),
                         [](const testing::TestParamInfo<DracoCase>& row) { return row.param.name; });

}  // namespace
}  // namespace candela::assets::test::gltf_draco_test
