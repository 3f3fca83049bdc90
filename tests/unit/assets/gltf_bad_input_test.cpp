// Malformed glTF input: every row builds its file(s) in a temporary folder and expects loadGltf to
// throw one UserError line "PATH: problem" containing the row's fragment. Under the asan preset
// these also prove there is no out-of-bounds read, crash or hang on any of them.
#include "animation_pointer_util.h"
#include "bad_input_expect.h"
#include "gltf_test_util.h"

#include <cmath>
#include <functional>
#include <limits>

namespace candela::assets::test::gltf_bad_input_test {
namespace {

struct BadCase {
    std::string name;
    std::function<fs::path(const fs::path& dir)> make;  // writes the input, returns the file to load
    std::string fragment;                               // the error message must contain this
    LoadOptions options = {};
};

assets::test::GltfBuilder triangle() {
    GltfBuilder b;
    b.addTriangle();
    return b;
}

// The triangle model with its JSON changed by `edit`, written as .gltf + .bin.
std::function<fs::path(const fs::path&)> edited(std::function<void(GltfBuilder&)> edit) {
    return [edit](const fs::path& dir) {
        GltfBuilder b = triangle();
        edit(b);
        return b.writeGltf(dir);
    };
}

// The triangle model as .glb, with its bytes changed by `edit`.
std::function<fs::path(const fs::path&)> glbEdited(std::function<void(Bytes&)> edit) {
    return [edit](const fs::path& dir) {
        Bytes glb = triangle().glbBytes();
        edit(glb);
        writeFile(dir / "model.glb", glb);
        return dir / "model.glb";
    };
}

std::vector<BadCase> badCases() {
    std::vector<BadCase> cases;
    auto add = [&](std::string name, std::function<fs::path(const fs::path&)> make, std::string fragment,
                   LoadOptions options = {}) { cases.push_back({std::move(name), std::move(make), std::move(fragment), options}); };

    // Files and containers.
    add("NonexistentFile", [](const fs::path& dir) { return dir / "nothing.gltf"; }, "cannot open");
    add("Directory", [](const fs::path& dir) { fs::create_directories(dir / "d.gltf"); return dir / "d.gltf"; }, "is a directory");
    add("EmptyFile", [](const fs::path& dir) { writeFile(dir / "e.glb", std::string()); return dir / "e.glb"; }, "empty file");
    for (size_t cut : {6, 11}) add("GlbTruncatedHeader" + std::to_string(cut), glbEdited([cut](Bytes& g) { g.resize(cut); }), "truncated GLB: " + std::to_string(cut) + " bytes");
    for (size_t cut : {12, 16, 19, 40})
        add("GlbTruncatedAt" + std::to_string(cut), glbEdited([cut](Bytes& g) { g.resize(cut); }), "truncated GLB: header says");
    add("GlbTruncatedInBin", glbEdited([](Bytes& g) { g.resize(g.size() - 10); }), "truncated GLB: header says");
    add("GlbWrongMagic", glbEdited([](Bytes& g) { g[3] = 'X'; }), "invalid glTF: [json.exception.parse_error");
    add("GlbVersion1", glbEdited([](Bytes& g) { setU32(g, 4, 1); }), "unsupported GLB version 1");
    add("GlbJsonChunkTooLong", glbEdited([](Bytes& g) { setU32(g, 12, 0x7FFFFFF0); }), "chunk 0 claims 2147483632 bytes");
    add("GlbBinChunkTooLong", glbEdited([](Bytes& g) {
            const uint32_t jsonLength = uint32_t(g[12] | g[13] << 8 | g[14] << 16 | g[15] << 24);
            setU32(g, 20 + jsonLength, 0xFFFFFFFF);
        }), "chunk 1 claims 4294967295 bytes");
    add("GlbFirstChunkNotJson", glbEdited([](Bytes& g) { setU32(g, 16, 0x004E4942); }), "first chunk is not JSON");
    add("GlbHeaderLengthTooShort", glbEdited([](Bytes& g) { setU32(g, 8, 16); }), "truncated GLB: chunk header");
    add("GlbNoChunks", glbEdited([](Bytes& g) { setU32(g, 8, 12); }), "no JSON chunk");
    add("GlbBufferLongerThanBinChunk", [](const fs::path& dir) {
            GltfBuilder b = triangle();
            Json json = b.withBuffer("");
            json["buffers"][0]["byteLength"] = b.bin.size() + 100;
            writeFile(dir / "m.glb", GltfBuilder::makeGlb(json.dump(), b.bin));
            return dir / "m.glb";
        }, "byteLength");
    add("GlbBinChunkMissing", [](const fs::path& dir) {
            GltfBuilder b = triangle();
            writeFile(dir / "m.glb", GltfBuilder::makeGlb(b.withBuffer("").dump(), {}));
            return dir / "m.glb";
        }, "empty BIN chunk");

    // JSON.
    add("JsonSyntaxError", [](const fs::path& dir) { writeFile(dir / "m.gltf", std::string("{\"asset\": {\"version\": \"2.0\"}")); return dir / "m.gltf"; }, "parse error");
    add("JsonTruncated", [](const fs::path& dir) {
            const std::string json = triangle().withBuffer("model.bin").dump();
            writeFile(dir / "m.gltf", json.substr(0, json.size() / 2));
            return dir / "m.gltf";
        }, "parse error");
    add("JsonDeeplyNestedExtras", [](const fs::path& dir) {
            // tinygltf converts extras recursively; 100000 levels would overflow the stack.
            std::string json = triangle().withBuffer("model.bin").dump();
            json.insert(json.size() - 1, ",\"extras\":" + std::string(100000, '[') + std::string(100000, ']'));
            writeFile(dir / "m.gltf", json);
            return dir / "m.gltf";
        }, "JSON nested deeper than 512 levels");
    add("JsonRootNotObject", [](const fs::path& dir) { writeFile(dir / "m.gltf", std::string("[1, 2, 3]")); return dir / "m.gltf"; }, "expected a JSON object");
    add("JsonMissingAsset", edited([](GltfBuilder& b) { b.doc.erase("asset"); }), "asset");
    add("JsonVersion1", edited([](GltfBuilder& b) { b.doc["asset"]["version"] = "1.0"; }), "unsupported glTF version '1.0'");
    add("JsonComponentTypeString", edited([](GltfBuilder& b) { b.doc["accessors"][0]["componentType"] = "FLOAT"; }), "componentType");
    add("JsonCountNegative", edited([](GltfBuilder& b) { b.doc["accessors"][0]["count"] = -3; }), "count");
    add("JsonAccessorTypeUnknown", edited([](GltfBuilder& b) { b.doc["accessors"][0]["type"] = "VEC7"; }), "VEC7");
    add("JsonBufferViewNotObject", edited([](GltfBuilder& b) { b.doc["bufferViews"][0] = 42; }), "bufferViews");
    add("JsonComponentTypeDouble", edited([](GltfBuilder& b) { b.doc["accessors"][0]["componentType"] = 5130; }), "unsupported componentType 5130");

    // Byte ranges.
    add("AccessorPastBufferView", edited([](GltfBuilder& b) { b.doc["accessors"][0]["byteOffset"] = 4; }), "run past the end of bufferView 0");
    add("AccessorCountHuge", edited([](GltfBuilder& b) { b.doc["accessors"][0]["count"] = 1000000000000000ull; }), "run past the end of bufferView");
    add("AccessorMissing", edited([](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 99; }), "accessor 99 does not exist");
    add("AccessorUnbackedHuge", edited([](GltfBuilder& b) {
            b.doc["accessors"][0].erase("bufferView");
            b.doc["accessors"][0]["count"] = 1000000000000ull;
        }), "without a bufferView");
    add("BufferViewPastBuffer", edited([](GltfBuilder& b) { b.doc["bufferViews"][0]["byteLength"] = 10000; }), "lies outside buffer 0");
    add("BufferViewOffsetOverflow", edited([](GltfBuilder& b) { b.doc["bufferViews"][0]["byteOffset"] = std::numeric_limits<uint64_t>::max() - 8; }), "lies outside buffer 0");
    add("BufferViewBadBuffer", edited([](GltfBuilder& b) { b.doc["bufferViews"][0]["buffer"] = 5; }), "buffer 5, which does not exist");
    add("BufferViewMissing", edited([](GltfBuilder& b) { b.doc["accessors"][0]["bufferView"] = 17; }), "bufferView 17 does not exist");
    add("StrideSmallerThanElement", edited([](GltfBuilder& b) { b.doc["bufferViews"][0]["byteStride"] = 4; }), "byteStride 4 is smaller than its element size 12");
    add("IndexBeyondVertexCount", [](const fs::path& dir) {
            GltfBuilder b;
            const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
            b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 7}))}})});
            return b.writeGltf(dir);
        }, "index 7 (element 2) >= vertex count 3");
    add("IndexAccessorFloat", edited([](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["indices"] = 0; }), "index accessor 0 must be SCALAR");
    add("AttributeCountMismatch", edited([](GltfBuilder& b) { b.doc["accessors"][1]["count"] = 2; }), "NORMAL: 2 elements, POSITION has 3");
    add("PositionWrongType", edited([](GltfBuilder& b) { b.doc["accessors"][0]["type"] = "VEC2"; }), "has type VEC2, expected VEC3");
    add("SparseIndexOutOfRange", edited([](GltfBuilder& b) {
            const int idx = b.addView(std::vector<uint16_t>{5, 0});
            const int val = b.addView(std::vector<float>{1, 2, 3});
            b.doc["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", idx}, {"componentType", kUnsignedShort}}}, {"values", {{"bufferView", val}}}};
        }), "sparse: index 5 >= count 3");
    add("SparseValuesOutOfRange", edited([](GltfBuilder& b) {
            const int idx = b.addView(std::vector<uint16_t>{0, 1});
            const int val = b.addView(std::vector<float>{1, 2, 3});
            b.doc["accessors"][0]["sparse"] = {{"count", 2}, {"indices", {{"bufferView", idx}, {"componentType", kUnsignedShort}}}, {"values", {{"bufferView", val}}}};
        }), "values run past the end");
    add("DataUriWrongLength", [](const fs::path& dir) {
            GltfBuilder b = triangle();
            Json json = b.withBuffer("data:application/octet-stream;base64," + base64(b.bin));
            json["buffers"][0]["byteLength"] = b.bin.size() + 4;
            writeFile(dir / "m.gltf", json.dump());
            return dir / "m.gltf";
        }, "Failed to decode 'uri'");

    // External files and URIs.
    add("MissingBin", [](const fs::path& dir) { const fs::path p = triangle().writeGltf(dir); fs::remove(dir / "model.bin"); return p; }, "cannot read 'model.bin': file not found");
    add("BinTooShort", [](const fs::path& dir) {
            const fs::path p = triangle().writeGltf(dir);
            fs::resize_file(dir / "model.bin", 8);
            return p;
        }, "File size mismatch : model.bin");
    add("MissingImage", [](const fs::path& dir) { return texturedTriangle("missing.png").writeGltf(dir); }, "cannot read 'missing.png': file not found");
    add("BufferUriEscapes", [](const fs::path& dir) {
            GltfBuilder b = triangle();
            writeFile(dir / "outside.bin", b.bin);  // exists, so only the folder rule can refuse it
            writeFile(dir / "in" / "m.gltf", b.withBuffer("../outside.bin").dump());
            return dir / "in" / "m.gltf";
        }, "URI '../outside.bin' escapes the model's folder");
    add("BufferUriPercentEscapes", [](const fs::path& dir) {
            GltfBuilder b = triangle();
            writeFile(dir / "outside.bin", b.bin);
            writeFile(dir / "in" / "m.gltf", b.withBuffer("%2e%2e/outside.bin").dump());
            return dir / "in" / "m.gltf";
        }, "escapes the model's folder");
    add("ImageUriEscapes", [](const fs::path& dir) {
            writeFile(dir / "x.png", smallPng());
            return texturedTriangle("sub/../../x.png").writeGltf(dir / "in");
        }, "URI 'sub/../../x.png' escapes the model's folder");
    add("BufferUriAbsolute", [](const fs::path& dir) {
            GltfBuilder b = triangle();
            writeFile(dir / "abs.bin", b.bin);
            writeFile(dir / "m.gltf", b.withBuffer(fs::absolute(dir / "abs.bin").string()).dump());
            return dir / "m.gltf";
        }, "is an absolute path");
    add("BufferUriScheme", [](const fs::path& dir) {
            GltfBuilder b = triangle();
            writeFile(dir / "m.gltf", b.withBuffer("file:///etc/passwd").dump());
            return dir / "m.gltf";
        }, "uses an unsupported URI scheme");

    // Images.
    add("AbsurdImageSizeUri", [](const fs::path& dir) {
            writeFile(dir / "huge.png", makePng(100000, 100000, 8, 6, {}, true));
            return texturedTriangle("huge.png").writeGltf(dir);
        }, "image 0: image size 100000x100000 exceeds the limit of 16384 pixels per side");
    add("AbsurdImageSizeGlb", [](const fs::path& dir) {
            return texturedTriangle("", makePng(100000, 100000, 8, 6, {}, true)).writeGlb(dir);
        }, "image size 100000x100000 exceeds the limit");
    add("ImageOverOptionLimit", [](const fs::path& dir) { return texturedTriangle("", smallPng()).writeGlb(dir); },
        "image size 2x2 exceeds the limit of 1 pixels per side", LoadOptions{.maxImageDimension = 1});
    add("CorruptImage", [](const fs::path& dir) {
            writeFile(dir / "bad.png", std::string("this is not an image at all"));
            return texturedTriangle("bad.png").writeGltf(dir);
        }, "cannot decode image");
    add("TruncatedPngData", [](const fs::path& dir) {
            Bytes png = smallPng();
            png.resize(png.size() - 20);  // IDAT cut short: found before stb_image reads it
            return texturedTriangle("", png).writeGlb(dir);
        }, "image 0: chunk IDAT at byte 33 declares 29 bytes, past the end of the file (66 bytes)");
    add("ImageBufferViewPastBuffer", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["bufferViews"][b.doc["images"][0]["bufferView"].get<int>()]["byteLength"] = 1 << 20;
            return b.writeGlb(dir);
        }, "image 0: bufferView 2 [");
    add("TextureMissing", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 5;
            return b.writeGlb(dir);
        }, "texture 5 does not exist");
    add("SpecularFactorNotANumber", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_specular", {{"specularFactor", "high"}}}}}}});
        }), "materials[0].extensions.KHR_materials_specular.specularFactor: expected a number, got the string \"high\"");
    add("SpecularColorFactorTwoComponents", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_specular", {{"specularColorFactor", {1, 1}}}}}}}});
        }), "specularColorFactor: expected an array of 3 numbers");
    add("IorNotANumber", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_ior", {{"ior", Json::array()}}}}}}});
        }), "KHR_materials_ior.ior: expected a number, got an array");
    add("SpecularTextureMissing", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["materials"][0]["extensions"] = {{"KHR_materials_specular", {{"specularColorTexture", {{"index", 4}}}}}};
            return b.writeGlb(dir);
        }, "specularColorTexture: texture 4 does not exist");
    add("SpecularTextureWithoutIndex", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["materials"][0]["extensions"] = {{"KHR_materials_specular", {{"specularTexture", {{"texCoord", 0}}}}}};
            return b.writeGlb(dir);
        }, "specularTexture: no texture index");
    add("ClearcoatRoughnessNotANumber", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatRoughnessFactor", true}}}}}}});
        }), "KHR_materials_clearcoat.clearcoatRoughnessFactor: expected a number");
    add("ClearcoatTextureMissing", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["materials"][0]["extensions"] = {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1}, {"clearcoatTexture", {{"index", 7}}}}}};
            return b.writeGlb(dir);
        }, "clearcoatTexture: texture 7 does not exist");
    add("VariantMappingMaterialMissing", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["extensions"] = {{"KHR_materials_variants", {{"variants", {{{"name", "a"}}}}}}};
            b.doc["meshes"][0]["primitives"][0]["extensions"] = {
                {"KHR_materials_variants", {{"mappings", {{{"material", 9}, {"variants", {0}}}}}}}};
            return b.writeGlb(dir);
        }, "mesh 0 primitive 0 KHR_materials_variants mapping 0: material 9 does not exist");
    add("VariantIndexMissing", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["extensions"] = {{"KHR_materials_variants", {{"variants", {{{"name", "a"}}}}}}};
            b.doc["meshes"][0]["primitives"][0]["extensions"] = {
                {"KHR_materials_variants", {{"mappings", {{{"material", 0}, {"variants", {3}}}}}}}};
            return b.writeGlb(dir);
        }, "mapping 0: variant 3 does not exist (the file defines 1)");
    add("VariantMappingWithoutVariants", edited([](GltfBuilder& b) {
            b.doc["meshes"][0]["primitives"][0]["extensions"] = {{"KHR_materials_variants", {{"mappings", {{{"material", 0}}}}}}};
        }), "KHR_materials_variants.mappings[0].variants: expected an array of indices");
    add("VariantWithoutName", edited([](GltfBuilder& b) {
            b.doc["extensions"] = {{"KHR_materials_variants", {{"variants", Json::array({Json::object()})}}}};
        }), "extensions.KHR_materials_variants.variants[0].name: expected a string (a variant's name is required)");
    // KHR_materials_diffuse_transmission and KHR_materials_dispersion.
    add("DiffuseTransmissionColorTwoComponents", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionColorFactor", {1, 1}}}}}}}});
        }), "KHR_materials_diffuse_transmission.diffuseTransmissionColorFactor: expected an array of 3 numbers");
    add("DiffuseTransmissionColorNotAnArray", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionColorFactor", 1}}}}}}});
        }), "diffuseTransmissionColorFactor: expected an array of 3 numbers");
    add("DiffuseTransmissionFactorNotANumber", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", "0.5"}}}}}}});
        }), "KHR_materials_diffuse_transmission.diffuseTransmissionFactor: expected a number, got the string \"0.5\"");
    add("DiffuseTransmissionTextureMissing", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["materials"][0]["extensions"] = {{"KHR_materials_diffuse_transmission",
                                                    {{"diffuseTransmissionFactor", 1}, {"diffuseTransmissionTexture", {{"index", 6}}}}}};
            return b.writeGlb(dir);
        }, "diffuseTransmissionTexture: texture 6 does not exist");
    add("DiffuseTransmissionColorTextureWithoutIndex", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["materials"][0]["extensions"] = {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionColorTexture", {{"texCoord", 0}}}}}};
            return b.writeGlb(dir);
        }, "diffuseTransmissionColorTexture: no texture index");
    add("DispersionNotANumber", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_dispersion", {{"dispersion", Json::array({0.5})}}}}}}});
        }), "KHR_materials_dispersion.dispersion: expected a number, got an array");
    add("DispersionNotAnObject", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_dispersion", 0.5}}}}});
        }), "KHR_materials_dispersion: expected an object");
    add("SpecularGlossinessDiffuseFactorShort", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({{{"extensions", {{"KHR_materials_pbrSpecularGlossiness", {{"diffuseFactor", {1, 1, 1}}}}}}}});
        }), "diffuseFactor: expected an array of 4 numbers");
    add("TextureImageMissing", [](const fs::path& dir) {
            GltfBuilder b = texturedTriangle("", smallPng());
            b.doc["textures"][0]["source"] = 3;
            return b.writeGlb(dir);
        }, "names image 3, which does not exist");

    // Values and the node graph.
    add("NanPosition", [](const fs::path& dir) {
            GltfBuilder b;
            const float nan = std::numeric_limits<float>::quiet_NaN();
            const int pos = b.addFloats({0, 0, 0, 1, nan, 0, 0, 1, 0}, "VEC3", 3);
            b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 2}))}})});
            return b.writeGltf(dir);
        }, "POSITION: vertex 1 is not finite");
    add("InfPositionSparse", edited([](GltfBuilder& b) {
            const int idx = b.addView(std::vector<uint16_t>{2, 0});
            const int val = b.addView(std::vector<float>{0, std::numeric_limits<float>::infinity(), 0});
            b.doc["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", idx}, {"componentType", kUnsignedShort}}}, {"values", {{"bufferView", val}}}};
        }), "POSITION: vertex 2 is not finite");
    add("CyclicNodes", edited([](GltfBuilder& b) {
            b.doc["nodes"][0]["children"] = {1};
            b.addNode({{"children", {0}}});
        }), "cycle in the node hierarchy");
    add("SelfCycle", edited([](GltfBuilder& b) { b.doc["nodes"][0]["children"] = {0}; }), "node 0: cycle in the node hierarchy");
    add("NodeWithTwoParents", edited([](GltfBuilder& b) {
            const int shared = b.addNode({{"mesh", 0}});
            b.addNode({{"children", {shared}}});
            b.addNode({{"children", {shared}}});
            b.doc["scenes"][0]["nodes"] = {2, 3};
        }), "node 1: reached twice");
    add("ChildMissing", edited([](GltfBuilder& b) { b.doc["nodes"][0]["children"] = {9}; }), "node 9 does not exist");
    add("SceneMissing", edited([](GltfBuilder& b) { b.doc["scene"] = 3; }), "scene 3 does not exist");
    add("NameWithNewlineStaysOneLine", edited([](GltfBuilder& b) {
            b.doc["nodes"][0]["name"] = "evil\nname";
            b.doc["nodes"][0]["mesh"] = 4;
        }), "node 0 ('evil?name'): mesh 4 does not exist");
    add("MeshMissing", edited([](GltfBuilder& b) { b.doc["nodes"][0]["mesh"] = 4; }), "mesh 4 does not exist");
    add("MaterialMissing", edited([](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["material"] = 3; }), "material 3 does not exist");
    add("CameraMissing", edited([](GltfBuilder& b) { b.doc["nodes"][0]["camera"] = 4; }), "camera 4 does not exist");
    add("LightMissing", edited([](GltfBuilder& b) { b.doc["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 2}}}}; }), "KHR_lights_punctual light index is missing or out of range");
    add("MatrixWrongLength", edited([](GltfBuilder& b) { b.doc["nodes"][0]["matrix"] = std::vector<double>(15, 1.0); }), "nodes[0].matrix: expected an array of 16 numbers");
    add("InvalidMode", edited([](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["mode"] = 9; }), "invalid mode 9");
    add("RequiredExtensionUnsupported", edited([](GltfBuilder& b) {
            b.doc["extensionsUsed"] = {"EXT_texture_avif"};
            b.doc["extensionsRequired"] = {"EXT_texture_avif"};
        }), "requires unsupported extension EXT_texture_avif");
    // KHR_animation_pointer and KHR_node_visibility.
    add("PointerToMissingMaterial", edited([](GltfBuilder& b) {
            addPointerAnimation(b, {{.pointer = "/materials/3/pbrMetallicRoughness/baseColorFactor", .times = {0, 1},
                                     .values = {0, 0, 0, 1, 1, 1, 1, 1}, .type = "VEC4"}});
        }), "channel 0: pointer '/materials/3/pbrMetallicRoughness/baseColorFactor': material 3 does not exist");
    add("PointerVisibilityLinear", edited([](GltfBuilder& b) {
            addPointerAnimation(b, {{.pointer = "/nodes/0/extensions/KHR_node_visibility/visible", .times = {0, 1}, .values = {0, 1},
                                     .interpolation = "LINEAR", .componentType = kUnsignedByte}});
        }), "a visibility is a bool: sampler 0 must use STEP interpolation, not LINEAR");
    add("PointerWrongAccessorType", edited([](GltfBuilder& b) {
            b.doc["materials"] = Json::array({Json::object()});
            addPointerAnimation(b, {{.pointer = "/materials/0/pbrMetallicRoughness/roughnessFactor", .times = {0, 1},
                                     .values = {0, 0, 0, 1, 1, 1}, .type = "VEC3"}});
        }), "pointer '/materials/0/pbrMetallicRoughness/roughnessFactor': takes SCALAR values, but sampler 0's output accessor 4 is VEC3");
    add("PointerNotAString", edited([](GltfBuilder& b) {
            addPointerAnimation(b, {{.pointer = "/nodes/0/scale", .times = {0, 1}, .values = {1, 1, 1, 2, 2, 2}, .type = "VEC3"}});
            b.doc["animations"][0]["channels"][0]["target"]["extensions"]["KHR_animation_pointer"]["pointer"] = 5;
        }), "animations[0].channels[0].target.extensions.KHR_animation_pointer.pointer: expected a string, got the integer 5");
    add("VisibleNotABool", edited([](GltfBuilder& b) { setVisible(b, 0, true); b.doc["nodes"][0]["extensions"]["KHR_node_visibility"]["visible"] = "false"; }),
        "nodes[0].extensions.KHR_node_visibility.visible: expected true or false, got the string \"false\"");
    return cases;
}

class Row : public testing::TestWithParam<BadCase> {};

TEST_P(Row, IsOneLineUserErrorNamingTheFile) {
    test::TempDir dir;
    const BadCase& c = GetParam();
    const fs::path path = c.make(dir.path());
    const std::string message = loadError(path, c.options);
    RecordProperty("message", message);
    candela::test::expectOneLineErrorNamingFile(path, message, c.fragment);
}

INSTANTIATE_TEST_SUITE_P(GltfBadInput, Row, testing::ValuesIn(badCases()),
                         [](const testing::TestParamInfo<BadCase>& row) { return row.param.name; });

// The unmodified inputs the table starts from do load, so each row fails for its own reason.
TEST(GltfBadInputBaseline, UnmodifiedInputsLoad) {
    test::TempDir dir;
    EXPECT_EQ(loadError(triangle().writeGltf(dir / "a")), "");
    EXPECT_EQ(loadError(triangle().writeGlb(dir / "b")), "");
    EXPECT_EQ(loadError(triangle().writeEmbedded(dir / "c")), "");
    EXPECT_EQ(loadError(texturedTriangle("", smallPng()).writeGlb(dir / "d")), "");
    writeFile(dir / "e" / "ok.png", smallPng());
    EXPECT_EQ(loadError(texturedTriangle("ok.png").writeGltf(dir / "e")), "");
}

}  // namespace
}  // namespace candela::assets::test::gltf_bad_input_test
