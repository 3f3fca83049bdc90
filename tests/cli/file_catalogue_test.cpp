// The bad-input catalogue: every class of malformed scene or environment file we know of, each
// row fed to the real `candela render` and held to its stated outcome —
//   Error:   exit code 2 and exactly one stderr line "candela: error: FILE: problem" naming the
//            file and containing the row's fragment (no crash, hang or partial output);
//   Warning: exit code 0, the image written at its size, and a "candela: warning:" line naming
//            the file and containing the fragment; `visible` says whether the scene still shows
//            something (pixels unlike the background) or draws nothing;
//   Note:    as Warning, but nothing on stderr unless --verbose, which prints the line.
// Rows marked `fixedIn6` needed a change to the loaders when the catalogue was written (the count
// is in docs/robustness.md). Under the asan preset the same rows run against the sanitized
// executable, so each is also free of out-of-bounds reads and undefined behaviour.
#include "run_candela.h"

#include "environment_test_util.h"
#include "draco_test_util.h"
#include "gltf_test_util.h"
#include "meshopt_test_util.h"
#include "webp_test_writer.h"

#include <stb_image.h>
#include <zlib.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>

namespace candela::assets::test {
namespace {

// Loads: renders quietly (valid, if unusual). Note: renders quietly too, and with --verbose says
// what it left out (facts the glTF-Validator reports as information, such as degenerate triangles).
enum class Outcome { Error, Warning, Note, Loads };

struct Row {
    std::string kind;   // the class of malformed input
    std::string name;
    std::function<fs::path(const fs::path& dir)> make;  // writes the input; returns the file to open
    Outcome outcome;
    std::string fragment;  // the error or warning line contains this
    bool visible = true;   // Warning rows: the image shows the scene (false: nothing is drawn)
    bool fixedIn6 = false;
};

void PrintTo(const Row& row, std::ostream* os) { *os << row.kind << " / " << row.name; }

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// ---- inputs ----------------------------------------------------------------------------------------

GltfBuilder triangle() {
    GltfBuilder b;
    b.addTriangle();
    return b;
}

// The triangle with `positions` (3 vertices) and `normals`.
GltfBuilder triangleWith(const std::vector<float>& positions, const std::vector<float>& normals) {
    GltfBuilder b;
    const int pos = b.addFloats(positions, "VEC3", 3);
    const int nrm = b.addFloats(normals, "VEC3", 3);
    b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}, {"NORMAL", nrm}}, b.addIndices({0, 1, 2}))}})});
    return b;
}

using Make = std::function<fs::path(const fs::path&)>;

// The triangle's .gltf (+ .bin) after `edit` changed its JSON.
Make gltfEdited(std::function<void(Json&)> edit, std::function<GltfBuilder()> base = triangle) {
    return [edit, base](const fs::path& dir) {
        const GltfBuilder b = base();
        Json json = b.withBuffer("model.bin");
        edit(json);
        writeFile(dir / "model.bin", b.bin);
        writeFile(dir / "model.gltf", json.dump());
        return dir / "model.gltf";
    };
}

// A model's .glb with its bytes changed by `edit`.
Make glbEdited(std::function<void(Bytes&)> edit, std::function<GltfBuilder()> base = triangle) {
    return [edit, base](const fs::path& dir) {
        Bytes glb = base().glbBytes();
        edit(glb);
        writeFile(dir / "model.glb", glb);
        return dir / "model.glb";
    };
}

// A model written as .gltf + .bin (+ whatever `extra` writes beside it).
Make gltfOf(std::function<GltfBuilder()> make, std::function<void(const fs::path&)> extra = {}) {
    return [make, extra](const fs::path& dir) {
        if (extra) extra(dir);
        return make().writeGltf(dir);
    };
}

// A triangle skinned to one joint (node 1, which stays put): JOINTS_0 of UNSIGNED_BYTE `joints`,
// WEIGHTS_0 of FLOAT `weights` (4 per vertex), an identity inverse bind matrix; `edit` may change
// the JSON after.
Make skinnedTriangle(std::vector<uint8_t> joints, std::vector<float> weights, std::function<void(GltfBuilder&)> edit = {}) {
    return gltfOf([=] {
        GltfBuilder b;
        const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
        const int j = b.addAccessor(b.addView(joints), kUnsignedByte, joints.size() / 4, "VEC4");
        const int w = b.addFloats(weights, "VEC4", 4);
        const int ibm = b.addFloats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, "MAT4", 16);
        const int mesh = b.addMesh({{"POSITION", pos}, {"JOINTS_0", j}, {"WEIGHTS_0", w}}, b.addIndices({0, 1, 2}));
        const int joint = b.addNode({{"translation", {0, 0, 0}}});
        b.doc["skins"] = Json::array({{{"joints", {joint}}, {"inverseBindMatrices", ibm}}});
        b.setScene({b.addNode({{"mesh", mesh}, {"skin", 0}}), joint});
        if (edit) edit(b);
        return b;
    });
}

// The triangle with one morph target whose POSITION deltas are `deltas` (VEC3 floats).
Make morphedTriangle(std::vector<float> deltas, std::function<void(GltfBuilder&)> edit = {}) {
    return gltfOf([=] {
        GltfBuilder b;
        const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
        const int delta = b.addFloats(deltas, "VEC3", 3);
        b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 2}))}})});
        b.doc["meshes"][0]["primitives"][0]["targets"] = Json::array({{{"POSITION", delta}}});
        b.doc["meshes"][0]["weights"] = {0.5};
        if (edit) edit(b);
        return b;
    });
}

// The triangle animated by one channel: sampler input `times`, output `values` (of accessor type
// `type`), then `edit` may change the JSON (a channel's target, the interpolation, ...).
Make animatedTriangle(std::vector<float> times, std::vector<float> values, std::string type, int components,
                      std::function<void(Json&)> edit = {}) {
    return gltfOf([=] {
        GltfBuilder b;
        b.addTriangle();
        const int input = b.addFloats(times, "SCALAR", 1);
        const int output = b.addFloats(values, type, components);
        b.doc["animations"] = Json::array({{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
                                            {"samplers", {{{"input", input}, {"output", output}}}}}});
        if (edit) edit(b.doc);
        return b;
    });
}

uint32_t u32(const Bytes& bytes, size_t at) {
    return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 | uint32_t(bytes[at + 3]) << 24;
}

// A zlib-compressed (really compressed, unlike makePng's stored blocks) 8-bit grey PNG of zeros:
// a few hundred KiB that decode to width × height × 4 bytes of RGBA8.
Bytes bombPng(uint32_t width, uint32_t height) {
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    Bytes ihdr;
    putU32BigEndian(ihdr, width);
    putU32BigEndian(ihdr, height);
    ihdr.insert(ihdr.end(), {8, 0, 0, 0, 0});
    pngChunk(png, "IHDR", ihdr);
    z_stream z{};
    deflateInit(&z, 9);
    const std::vector<uint8_t> row(width + 1, 0);  // filter byte + pixels
    Bytes idat(1 << 16), out;
    for (uint32_t y = 0; y < height; ++y) {
        z.next_in = const_cast<uint8_t*>(row.data());
        z.avail_in = uInt(row.size());
        const int flush = y + 1 == height ? Z_FINISH : Z_NO_FLUSH;
        do {
            z.next_out = idat.data();
            z.avail_out = uInt(idat.size());
            deflate(&z, flush);
            out.insert(out.end(), idat.data(), idat.data() + (idat.size() - z.avail_out));
        } while (z.avail_out == 0);
    }
    deflateEnd(&z);
    pngChunk(png, "IDAT", out);
    pngChunk(png, "IEND", {});
    return png;
}

// A small valid Radiance file (RLE scanlines), as the environment tests write it.
Bytes goodHdr() { return HdrWriter{}.write(testTexels(64, 32), 64, 32); }

// A small valid OpenEXR file (half RGB, ZIP).
Bytes goodExr(float special = 1.0f) {
    auto plane = [&](float base) {
        ExrChannel c{"", ExrType::Half, std::vector<float>(64 * 32, base)};
        c.values[5] = special;  // texel 5 of every channel
        return c;
    };
    ExrChannel r = plane(0.5f), g = plane(0.4f), b = plane(0.3f);
    r.name = "R", g.name = "G", b.name = "B";
    return makeExr(64, 32, {r, g, b});
}

Make bytesAs(const std::string& name, std::function<Bytes()> bytes) {
    return [name, bytes](const fs::path& dir) {
        writeFile(dir / name, bytes());
        return dir / name;
    };
}

Make truncated(const std::string& name, std::function<Bytes()> bytes, size_t keep) {
    return bytesAs(name, [bytes, keep] {
        Bytes b = bytes();
        b.resize(std::min(keep, b.size()));
        return b;
    });
}

// Offset of the first byte after the line that starts with `prefix` in a Radiance header.
size_t afterLine(const Bytes& hdr, const std::string& prefix) {
    const std::string text(hdr.begin(), hdr.end());
    return text.find('\n', text.find(prefix)) + 1;
}

// The offset of `attribute`'s value in an EXR header (after its name, type name and size).
size_t exrAttribute(const Bytes& exr, const std::string& attribute) {
    const std::string text(exr.begin(), exr.end());
    const size_t at = text.find(attribute + '\0');
    const size_t typeEnd = text.find('\0', at + attribute.size() + 1);
    return typeEnd + 1 + 4;
}

// ---- the catalogue ---------------------------------------------------------------------------------

std::vector<Row> catalogue() {
    std::vector<Row> rows;
    auto error = [&](std::string kind, std::string name, Make make, std::string fragment, bool fixed = false) {
        rows.push_back({std::move(kind), std::move(name), std::move(make), Outcome::Error, std::move(fragment), true, fixed});
    };
    auto warning = [&](std::string kind, std::string name, Make make, std::string fragment, bool visible,
                       bool fixed = false) {
        rows.push_back({std::move(kind), std::move(name), std::move(make), Outcome::Warning, std::move(fragment), visible, fixed});
    };
    auto note = [&](std::string kind, std::string name, Make make, std::string fragment, bool visible, bool fixed = false) {
        rows.push_back({std::move(kind), std::move(name), std::move(make), Outcome::Note, std::move(fragment), visible, fixed});
    };
    auto loads = [&](std::string kind, std::string name, Make make) {
        rows.push_back({std::move(kind), std::move(name), std::move(make), Outcome::Loads, "", true, false});
    };

    // -- Truncation at many offsets.
    const size_t glbSize = triangle().glbBytes().size();
    const size_t glbJson = 20 + u32(triangle().glbBytes(), 12);  // first byte after the JSON chunk
    for (size_t keep : {size_t(0), size_t(3)})
        error("truncated", "Glb" + std::to_string(keep), truncated("m.glb", [] { return triangle().glbBytes(); }, keep),
              keep == 0 ? "empty file" : "invalid glTF");
    for (size_t keep : {size_t(4), size_t(11)})
        error("truncated", "Glb" + std::to_string(keep), truncated("m.glb", [] { return triangle().glbBytes(); }, keep),
              "truncated GLB: " + std::to_string(keep) + " bytes, the header needs 12");
    for (size_t keep : {size_t(12), size_t(19), size_t(20), size_t(60), glbJson, glbJson + 4, glbJson + 8, glbSize - 1})
        error("truncated", "Glb" + std::to_string(keep), truncated("m.glb", [] { return triangle().glbBytes(); }, keep),
              "truncated GLB: header says " + std::to_string(glbSize) + " bytes, file has " + std::to_string(keep));
    const size_t jsonSize = triangle().withBuffer("model.bin").dump().size();
    for (size_t keep : {size_t(1), size_t(17), jsonSize / 2, jsonSize - 1})
        error("truncated", "Gltf" + std::to_string(keep), [keep](const fs::path& dir) {
            const GltfBuilder b = triangle();
            writeFile(dir / "model.bin", b.bin);
            writeFile(dir / "model.gltf", b.withBuffer("model.bin").dump().substr(0, keep));
            return dir / "model.gltf";
        }, "parse error");
    for (size_t keep : {size_t(0), size_t(40), size_t(77)})
        error("truncated", "Bin" + std::to_string(keep), [keep](const fs::path& dir) {
            const fs::path path = triangle().writeGltf(dir);
            fs::resize_file(dir / "model.bin", keep);
            return path;
        }, keep == 0 ? "cannot read 'model.bin': empty file" : "File size mismatch : model.bin");
    for (size_t keep : {size_t(8), size_t(20), size_t(45), smallPng().size() - 20})
        error("truncated", "Png" + std::to_string(keep), [keep](const fs::path& dir) {
            Bytes png = smallPng();
            png.resize(keep);
            return texturedTriangle("", png).writeGlb(dir);
        }, keep < 45 ? std::string("image 0: cannot decode image")  // cut before the IDAT chunk's header ends
                     : "image 0: chunk IDAT at byte 33 declares 29 bytes, past the end of the file (" + std::to_string(keep) + " bytes)");
    const size_t hdrHeader = afterLine(goodHdr(), "-Y");
    auto hdrCut = [](size_t keep) -> std::string {
        if (keep < 2) return "not a Radiance HDR file";
        if (keep < 11) return "truncated header (no end of the first line)";
        if (keep < 35) return "truncated header (no blank line ending it)";
        return "";
    };
    for (size_t keep : {size_t(1), size_t(5), size_t(20)})
        error("truncated", "Hdr" + std::to_string(keep), truncated("env.hdr", goodHdr, keep), hdrCut(keep));
    error("truncated", "HdrInResolutionLine", truncated("env.hdr", goodHdr, hdrHeader - 4), "no resolution line after the header");
    for (size_t keep : {hdrHeader, hdrHeader + 3, hdrHeader + 100, goodHdr().size() - 1})
        error("truncated", "Hdr" + std::to_string(keep), truncated("env.hdr", goodHdr, keep),
              "truncated: the file ends (" + std::to_string(keep) + " bytes) inside scanline");
    const size_t exrSize = goodExr().size();
    for (const auto& [keep, fragment] : std::vector<std::pair<size_t, std::string>>{
             {3, "not an OpenEXR file (bad magic number)"}, {8, "invalid EXR header: End of file attempting to read header"},
             {40, "invalid EXR header"}, {200, "invalid EXR header"}, {exrSize / 2, "invalid EXR header"},
             {exrSize - 1, "cannot decode EXR pixels"}})
        error("truncated", "Exr" + std::to_string(keep), truncated("env.exr", [] { return goodExr(); }, keep), fragment);

    // -- Wrong magic.
    error("wrong magic", "Glb", glbEdited([](Bytes& g) { g[3] = 'X'; }), "invalid glTF");
    error("wrong magic", "Hdr", bytesAs("env.hdr", [] { Bytes b = goodHdr(); b[1] = '!'; return b; }), "not a Radiance");
    error("wrong magic", "Exr", bytesAs("env.exr", [] { Bytes b = goodExr(); b[0] = 0x77; return b; }), "not an OpenEXR");
    error("wrong magic", "Png", [](const fs::path& dir) {
        Bytes png = smallPng();
        png[1] = 'Q';
        return texturedTriangle("", png).writeGlb(dir);
    }, "image 0: cannot decode image");
    error("wrong magic", "NeitherEnvironment", bytesAs("env.png", [] { return smallPng(); }), "unknown environment format");

    // -- Wrong chunk and section lengths.
    error("chunk length", "GlbJsonTooLong", glbEdited([](Bytes& g) { setU32(g, 12, 0x7FFFFFF0); }), "chunk 0 claims 2147483632 bytes");
    error("chunk length", "GlbBinTooLong", glbEdited([](Bytes& g) { setU32(g, 20 + u32(g, 12), 0xFFFFFFFF); }), "chunk 1 claims 4294967295 bytes");
    error("chunk length", "GlbBinShort", glbEdited([](Bytes& g) { setU32(g, 20 + u32(g, 12), 8); }), "corrupt GLB: chunk");
    error("chunk length", "GlbTotalShort", glbEdited([](Bytes& g) { setU32(g, 8, 16); }), "truncated GLB: chunk header");
    error("chunk length", "GlbTotalLong", glbEdited([](Bytes& g) { setU32(g, 8, u32(g, 8) + 64); }), "truncated GLB: header says");
    warning("chunk length", "GlbJsonUnpadded", glbEdited([](Bytes& g) {
        // JSON chunk length not a multiple of 4 (the trailing padding space left out of it).
        const uint32_t json = u32(g, 12);
        ASSERT_EQ(g[20 + json - 1], ' ');
        setU32(g, 12, json - 1);
        g.erase(g.begin() + 20 + json - 1);
        setU32(g, 8, uint32_t(g.size()));
    }), "not a multiple of 4", true, true);
    error("chunk length", "PngIhdrLength", [](const fs::path& dir) {
        Bytes png = smallPng();
        png[11] = 200;  // IHDR length 13 → 200
        return texturedTriangle("", png).writeGlb(dir);
    }, "image 0: cannot decode image");
    error("chunk length", "HdrRleRunPastRow", bytesAs("env.hdr", [] {
        Bytes b = goodHdr();
        b[afterLine(b, "-Y") + 4] = 128 + 127;  // first run of row 0 longer than the 64 texels left
        return b;
    }), "RLE run of 127 at x = 0 overflows scanline 0 (width 64)");
    error("chunk length", "HdrRleWidthMismatch", bytesAs("env.hdr", [] {
        Bytes b = goodHdr();
        b[afterLine(b, "-Y") + 3] = 65;  // the scanline marker says 65 texels, the header 64
        return b;
    }), "scanline 0: RLE length 65 does not match the width 64");
    error("chunk length", "ExrChannelListSize", bytesAs("env.exr", [] {
        Bytes b = goodExr();
        setU32(b, exrAttribute(b, "channels") - 4, 100000);
        return b;
    }), "invalid EXR header");
    error("chunk length", "ExrOffsetTablePastEnd", bytesAs("env.exr", [] {
        Bytes b = goodExr();
        const std::string text(b.begin(), b.end());
        // The offset table follows the header's terminating NUL; point its first entry past the end.
        size_t headerEnd = 8;
        while (b[headerEnd] != 0) {  // attributes: name\0 type\0 size value
            headerEnd = text.find('\0', headerEnd) + 1;
            headerEnd = text.find('\0', headerEnd) + 1;
            headerEnd += 4 + u32(b, headerEnd);
        }
        setU32(b, headerEnd + 1, 0x7FFFFFF0);
        return b;
    }), "cannot decode EXR pixels: seek past the end of the file");

    // -- JSON type errors.
    error("JSON type", "VersionNumber", gltfEdited([](Json& j) { j["asset"]["version"] = 2; }), "version");
    error("JSON type", "CountString", gltfEdited([](Json& j) { j["accessors"][0]["count"] = "3"; }), "count");
    error("JSON type", "ComponentTypeString", gltfEdited([](Json& j) { j["accessors"][0]["componentType"] = "FLOAT"; }), "componentType");
    error("JSON type", "AccessorsNotArray", gltfEdited([](Json& j) { j["accessors"] = {{"a", 1}}; }), "accessors");
    error("JSON type", "AttributesNotObject", gltfEdited([](Json& j) { j["meshes"][0]["primitives"][0]["attributes"] = 5; }), "attributes", true);
    error("JSON type", "ChildrenStrings", gltfEdited([](Json& j) {
        j["nodes"].push_back({{"children", {"0"}}});
    }), "children", true);
    error("JSON type", "TranslationTwoNumbers", gltfEdited([](Json& j) { j["nodes"][0]["translation"] = {1, 2}; }), "translation");
    error("JSON type", "ScaleStrings", gltfEdited([](Json& j) { j["nodes"][0]["scale"] = {"1", "1", "1"}; }), "scale", true);
    error("JSON type", "RotationFiveNumbers", gltfEdited([](Json& j) { j["nodes"][0]["rotation"] = {0, 0, 0, 1, 0}; }), "rotation");
    error("JSON type", "BaseColorFactorThree", gltfEdited([](Json& j) {
        j["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1}}}}}});
        j["meshes"][0]["primitives"][0]["material"] = 0;
    }), "baseColorFactor", true);
    error("JSON type", "SceneString", gltfEdited([](Json& j) { j["scene"] = "0"; }), "scene", true);
    error("JSON type", "RootArray", bytesAs("m.gltf", [] { return toBytes("[1, 2, 3]"); }), "the document: expected a JSON object");

    // -- Out-of-range indices and byte ranges.
    error("out of range", "AccessorIndex", gltfEdited([](Json& j) { j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 99; }), "accessor 99 does not exist");
    error("out of range", "AccessorNegative", gltfEdited([](Json& j) { j["meshes"][0]["primitives"][0]["indices"] = -4; }), "-4", true);
    error("out of range", "BufferViewIndex", gltfEdited([](Json& j) { j["accessors"][0]["bufferView"] = 17; }), "bufferView 17 does not exist");
    error("out of range", "BufferIndex", gltfEdited([](Json& j) { j["bufferViews"][0]["buffer"] = 5; }), "buffer 5, which does not exist");
    error("out of range", "AccessorPastView", gltfEdited([](Json& j) { j["accessors"][0]["byteOffset"] = 4; }), "run past the end of bufferView 0");
    error("out of range", "AccessorCountHuge", gltfEdited([](Json& j) { j["accessors"][0]["count"] = 1000000000000000ull; }), "run past the end of bufferView");
    error("out of range", "ViewPastBuffer", gltfEdited([](Json& j) { j["bufferViews"][0]["byteLength"] = 10000; }), "lies outside buffer 0");
    error("out of range", "ViewOffsetOverflow", gltfEdited([](Json& j) { j["bufferViews"][0]["byteOffset"] = std::numeric_limits<uint64_t>::max() - 8; }), "lies outside buffer 0");
    error("out of range", "VertexIndex", gltfOf([] {
        GltfBuilder b;
        const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
        b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 7}))}})});
        return b;
    }), "index 7 (element 2) >= vertex count 3");
    error("out of range", "SparseIndex", gltfOf([] {
        GltfBuilder b = triangle();
        const int idx = b.addView(std::vector<uint16_t>{5, 0});
        const int val = b.addView(std::vector<float>{1, 2, 3});
        b.doc["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", idx}, {"componentType", kUnsignedShort}}}, {"values", {{"bufferView", val}}}};
        return b;
    }), "sparse: index 5 >= count 3");
    error("out of range", "MaterialIndex", gltfEdited([](Json& j) { j["meshes"][0]["primitives"][0]["material"] = 3; }), "material 3 does not exist");
    error("out of range", "TextureIndex", gltfEdited([](Json& j) {
        j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 5;
    }, [] { return texturedTriangle("", smallPng()); }), "texture 5 does not exist");
    error("out of range", "ImageIndex", gltfEdited([](Json& j) { j["textures"][0]["source"] = 3; }, [] { return texturedTriangle("", smallPng()); }), "names image 3, which does not exist");
    error("out of range", "SamplerIndex", gltfEdited([](Json& j) { j["textures"][0]["sampler"] = 7; }, [] { return texturedTriangle("", smallPng()); }), "sampler 7");
    error("out of range", "ImageViewPastBuffer", gltfEdited([](Json& j) {
        j["bufferViews"][j["images"][0]["bufferView"].get<int>()]["byteLength"] = 1 << 20;
    }, [] { return texturedTriangle("", smallPng()); }), "lies outside buffer 0");
    error("out of range", "ChildIndex", gltfEdited([](Json& j) { j["nodes"][0]["children"] = {9}; }), "node 9 does not exist");
    error("out of range", "SceneIndex", gltfEdited([](Json& j) { j["scene"] = 3; }), "scene 3 does not exist");
    // A default scene named in a file without scenes: it rendered an empty image with "nothing to
    // draw: the file has no scene and no nodes" (#43; the glTF-Validator: UNRESOLVED_REFERENCE).
    error("out of range", "SceneIndexWithoutScenes", gltfEdited([](Json& j) {
        j.erase("scenes");
        j.erase("nodes");
        j["scene"] = 7;
    }), "scene 7 (the default scene) does not exist (the file has no scenes)", true);
    error("out of range", "MeshIndex", gltfEdited([](Json& j) { j["nodes"][0]["mesh"] = 4; }), "mesh 4 does not exist");
    error("out of range", "CameraIndex", gltfEdited([](Json& j) { j["nodes"][0]["camera"] = 4; }), "camera 4 does not exist");
    error("out of range", "LightIndex", gltfEdited([](Json& j) { j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 2}}}}; }), "KHR_lights_punctual light index");

    // -- Cyclic or shared node hierarchies.
    error("node graph", "Cycle", gltfEdited([](Json& j) {
        j["nodes"][0]["children"] = {1};
        j["nodes"].push_back({{"children", {0}}});
    }), "cycle in the node hierarchy");
    error("node graph", "SelfCycle", gltfEdited([](Json& j) { j["nodes"][0]["children"] = {0}; }), "node 0: cycle in the node hierarchy");
    error("node graph", "SharedChild", gltfEdited([](Json& j) {
        j["nodes"].push_back({{"children", {0}}});
        j["nodes"].push_back({{"children", {0}}});
        j["scenes"][0]["nodes"] = {1, 2};
    }), "node 0: reached twice");
    error("node graph", "RootListedTwice", gltfEdited([](Json& j) { j["scenes"][0]["nodes"] = {0, 0}; }), "node 0: reached twice");
    error("node graph", "RootAlsoChild", gltfEdited([](Json& j) {
        j["nodes"].push_back({{"children", {0}}});
        j["scenes"][0]["nodes"] = {0, 1};
    }), "node 0: reached twice");

    // -- Absurd image dimensions.
    error("absurd size", "PngHuge", [](const fs::path& dir) {
        writeFile(dir / "huge.png", makePng(100000, 100000, 8, 6, {}, true));
        return texturedTriangle("huge.png").writeGltf(dir);
    }, "image 0: image size 100000x100000 exceeds the limit of 16384 pixels per side");
    error("absurd size", "PngZero", [](const fs::path& dir) {
        return texturedTriangle("", makePng(0, 0, 8, 6, {}, true)).writeGlb(dir);
    }, "image 0: cannot decode image");
    error("absurd size", "HdrHuge", bytesAs("env.hdr", [] { return toBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 200000\n"); }),
          "image size 200000x100000 exceeds the limit 16384x8192");
    error("absurd size", "HdrZero", bytesAs("env.hdr", [] { return toBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 64\n"); }),
          "zero image size 64x0");
    error("absurd size", "ExrHuge", bytesAs("env.exr", [] {
        Bytes b = goodExr();
        for (const char* window : {"dataWindow", "displayWindow"}) setU32(b, exrAttribute(b, window) + 8, 999999);  // xMax
        return b;
    }), "invalid EXR header: Invalid width (1000000) too large (max 16384)");
    error("absurd size", "ExrInvertedWindow", bytesAs("env.exr", [] {
        Bytes b = goodExr();
        setU32(b, exrAttribute(b, "dataWindow"), 100);  // xMin > xMax
        return b;
    }), "invalid EXR header: Invalid data window (100, 0 - 63, 31)");

    // -- Decompression bombs: small files that would decode to far more memory.
    error("decompression bomb", "Png16kSquare", [](const fs::path& dir) {
        // ≈ 260 KiB of PNG that decodes to 16384 × 16384 RGBA8 = 1 GiB.
        writeFile(dir / "bomb.png", bombPng(16384, 16384));
        return texturedTriangle("bomb.png").writeGltf(dir);
    }, "decodes to 1.0 GiB", true);
    error("decompression bomb", "PngManyImagesOverBudget", [](const fs::path& dir) {
        // Nine 8192² images of 64 KiB each: 9 × 256 MiB decoded, over the scene's 2 GiB.
        writeFile(dir / "bomb.png", bombPng(8192, 8192));
        GltfBuilder b = texturedTriangle("bomb.png");
        for (int i = 1; i < 9; ++i) {
            b.doc["images"].push_back({{"uri", "bomb.png"}});
            b.doc["textures"].push_back({{"source", i}});
            b.doc["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
        }
        return b.writeGltf(dir);
    }, "decoded images would take", true);
    error("decompression bomb", "ExrZipHuge", bytesAs("env.exr", [] {
        // A 64 × 32 ZIP file that declares 65536 × 32768 texels (24 GiB of float RGB).
        Bytes b = goodExr();
        for (const char* window : {"dataWindow", "displayWindow"}) {
            setU32(b, exrAttribute(b, window) + 8, 65535);
            setU32(b, exrAttribute(b, window) + 12, 32767);
        }
        return b;
    }), "invalid EXR header: Invalid width (65536) too large (max 16384)");

    // -- URIs escaping the model's folder.
    auto escaping = [&](std::string name, std::string uri, std::string fragment) {
        error("URI escapes", std::move(name), [uri](const fs::path& dir) {
            const GltfBuilder b = triangle();
            writeFile(dir / "outside.bin", b.bin);  // exists: only the folder rule can refuse it
            writeFile(dir / "in" / "m.gltf", b.withBuffer(uri).dump());
            return dir / "in" / "m.gltf";
        }, std::move(fragment));
    };
    escaping("DotDot", "../outside.bin", "URI '../outside.bin' escapes the model's folder");
    escaping("PercentDotDot", "%2e%2e/outside.bin", "escapes the model's folder");
    escaping("NestedDotDot", "sub/../../outside.bin", "escapes the model's folder");
    escaping("FileScheme", "file:///etc/passwd", "uses an unsupported URI scheme");
    escaping("HttpScheme", "http://example.com/outside.bin", "uses an unsupported URI scheme");
    escaping("PercentNul", "outside.bin%00.png", "contains a NUL character");
    error("URI escapes", "Absolute", [](const fs::path& dir) {
        const GltfBuilder b = triangle();
        writeFile(dir / "abs.bin", b.bin);
        writeFile(dir / "m.gltf", b.withBuffer(fs::absolute(dir / "abs.bin").string()).dump());
        return dir / "m.gltf";
    }, "is an absolute path");
    error("URI escapes", "ImageDotDot", [](const fs::path& dir) {
        writeFile(dir / "x.png", smallPng());
        return texturedTriangle("sub/../../x.png").writeGltf(dir / "in");
    }, "escapes the model's folder");

    // -- NaN and Inf.
    error("NaN/Inf", "PositionNan", gltfOf([] { return triangleWith({0, 0, 0, 1, kNan, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}); }),
          "POSITION: vertex 1 is not finite");
    error("NaN/Inf", "PositionInf", gltfOf([] { return triangleWith({0, 0, 0, 1, 0, 0, kInf, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}); }),
          "POSITION: vertex 2 is not finite");
    warning("NaN/Inf", "NormalNan", gltfOf([] { return triangleWith({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, kNan, 0, 1, 0, 0, 1}); }),
            "NORMAL: 1 non-finite value replaced by the default", true);
    warning("NaN/Inf", "NormalInfAndZero", gltfOf([] { return triangleWith({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, kInf, 0, 0, 0, 0, 0, 1}); }),
            "NORMAL: 1 non-finite value replaced by the default", true);
    warning("NaN/Inf", "TexcoordNan", gltfOf([] {
        GltfBuilder b;
        const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
        const int uv = b.addFloats({0, 0, kNan, 0, 0, 1}, "VEC2", 2);
        b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, b.addIndices({0, 1, 2}))}})});
        return b;
    }), "TEXCOORD_0: 1 non-finite value replaced by the default", true);
    // JSON has no NaN or Inf: a literal too large for a double is a parse error, and one too large
    // for a float (the precision Candela renders in) fails where it is converted.
    auto withNode = [](std::string node) {
        return [node](const fs::path& dir) {
            const fs::path path = triangle().writeGltf(dir);
            std::string json = triangle().withBuffer("model.bin").dump();
            json.replace(json.find("{\"mesh\":0}"), 10, node);
            writeFile(path, json);
            return path;
        };
    };
    error("NaN/Inf", "TranslationBeyondDouble", withNode("{\"mesh\":0,\"translation\":[1e999,0,0]}"), "number overflow parsing '1e999'");
    error("NaN/Inf", "TranslationBeyondFloat", withNode("{\"mesh\":0,\"translation\":[1e300,0,0]}"),
          "node 0: world transform is beyond single precision", true);
    error("NaN/Inf", "MatrixBeyondFloat", withNode("{\"mesh\":0,\"matrix\":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,-1e300,1]}"),
          "node 0: world transform is beyond single precision", true);
    error("NaN/Inf", "ScaleProductBeyondFloat", gltfEdited([](Json& j) {
        // Each scale fits a float; the child's world scale 1e40 does not.
        j["nodes"][0]["scale"] = {1e20, 1e20, 1e20};
        j["nodes"].push_back({{"children", {0}}, {"scale", {1e20, 1e20, 1e20}}});
        j["scenes"][0]["nodes"] = {1};
    }), "node 0: world transform is beyond single precision", true);
    error("NaN/Inf", "MeshCornerBeyondFloat", gltfEdited([](Json& j) {
        // The world matrix (scale 1e38, translation 3e38) fits a float; the corner x = 1 lands at 4e38.
        j["nodes"][0]["scale"] = {1e38, 1e38, 1e38};
        j["nodes"][0]["translation"] = {3e38, 0, 0};
    }), "node 0: a corner of its mesh in world space is beyond single precision", true);
    error("NaN/Inf", "LightIntensityBeyondFloat", gltfEdited([](Json& j) {
        j["extensionsUsed"] = {"KHR_lights_punctual"};
        j["extensions"]["KHR_lights_punctual"]["lights"] = Json::array({{{"type", "point"}, {"intensity", 1e300}}});
        j["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        j["scenes"][0]["nodes"] = {0, 1};
    }), "light 0 intensity is beyond single precision", true);
    warning("NaN/Inf", "CameraBeyondFloat", gltfEdited([](Json& j) {
        j["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 1e300}}}}});
        j["nodes"].push_back({{"camera", 0}, {"translation", {0, 0, 3}}});
        j["scenes"][0]["nodes"] = {0, 1};
    }), "camera 0: parameters beyond single precision, camera skipped", true, true);
    warning("NaN/Inf", "ExrTexelsNanInf", bytesAs("env.exr", [] { return goodExr(kNan); }), "replaced", true);
    warning("NaN/Inf", "ExrTexelInf", bytesAs("env.exr", [] { return goodExr(kInf); }), "replaced", true);
    warning("NaN/Inf", "ExrTexelNegative", bytesAs("env.exr", [] { return goodExr(-4.0f); }), "replaced", true);

    // -- EXR structure: deep data and luminance/chroma are refused; a multi-part file and a data
    //    window smaller than the display window render with a note.
    auto rgbPart = [](const std::string& name, ExrLayout layout = {}) {
        std::vector<ExrChannel> channels;
        for (const char* c : {"R", "G", "B"}) channels.push_back({c, ExrType::Half, std::vector<float>(64 * 32, 0.5f)});
        return ExrPart{name, 64, 32, channels, layout, false};
    };
    error("EXR structure", "ExrDeep", bytesAs("env.exr", [&] {
        ExrPart deep = rgbPart("deep", {Imf::ZIPS_COMPRESSION});
        deep.deep = true;
        return makeExrParts({deep});
    }), "deep EXR is not supported");
    error("EXR structure", "ExrLuminanceChroma", bytesAs("env.exr", [] {
        return makeExr(64, 32, {{"Y", ExrType::Half, std::vector<float>(64 * 32, 0.5f)},
                                {"RY", ExrType::Half, std::vector<float>(32 * 16, 0.0f), 2},
                                {"BY", ExrType::Half, std::vector<float>(32 * 16, 0.0f), 2}});
    }), "luminance/chroma EXR (Y, RY, BY) is not supported");
    note("EXR structure", "ExrMultiPart", bytesAs("env.exr", [&] {
        ExrPart depth{"depth", 64, 32, {{"Z", ExrType::Float, std::vector<float>(64 * 32, 1.0f)}}, {}, false};
        return makeExrParts({depth, rgbPart("beauty")});
    }), "2-part EXR: part 1 'beauty' used", true);
    note("EXR structure", "ExrDataWindowInsideDisplay", bytesAs("env.exr", [&] {
        ExrLayout layout;
        layout.display = Imath::Box2i({-8, -4}, {71, 35});
        return makeExrParts({rgbPart("", layout)});
    }), "does not cover the display window", true);

    // -- Degenerate geometry.
    note("degenerate", "ZeroAreaTriangle", gltfOf([] {
        GltfBuilder b;  // one real triangle and one with all three corners on a line
        const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 3, 0, 0}, "VEC3", 3);
        b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 2, 1, 3, 4}))}})});
        return b;
    }), "zero-area", true, true);
    note("degenerate", "AllTrianglesZeroArea", gltfOf([] {
        GltfBuilder b;
        const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3", 3);
        b.setScene({b.addNode({{"mesh", b.addMesh({{"POSITION", pos}}, b.addIndices({0, 1, 2}))}})});
        return b;
    }), "zero-area", false, true);
    note("degenerate", "ZeroScale", gltfEdited([](Json& j) { j["nodes"][0]["scale"] = {0, 0, 0}; }), "zero scale, not drawn", false, true);
    note("degenerate", "ZeroScaleOneAxis", gltfEdited([](Json& j) { j["nodes"][0]["scale"] = {1, 0, 1}; }), "zero scale, not drawn", false, true);
    note("degenerate", "ZeroScaleParent", gltfEdited([](Json& j) {
        j["nodes"].push_back({{"children", {0}}, {"scale", {0, 0, 0}}});
        j["scenes"][0]["nodes"] = {1};
    }), "zero scale, not drawn", false, true);

    // -- Nothing to draw. Valid files (glTF 2.0 §3.5.1: an asset may have no scene, "a library of
    // individual entities") that rendered an empty image without a word (#31): one warning.
    const auto withoutScenes = [](Json& j) {
        j.erase("scenes");
        j.erase("scene");
    };
    warning("nothing to draw", "NoSceneNoNodes", gltfEdited([=](Json& j) {
        withoutScenes(j);
        j.erase("nodes");
    }), "nothing to draw: the file has no scene and no nodes", false, true);
    warning("nothing to draw", "NoSceneNoMeshNode", gltfEdited([=](Json& j) {
        withoutScenes(j);
        j["nodes"][0].erase("mesh");
    }), "nothing to draw: the file has no scene, and none of its root nodes holds a mesh", false, true);
    warning("nothing to draw", "EmptyScene", gltfEdited([](Json& j) { j["scenes"][0]["nodes"] = Json::array(); }),
            "nothing to draw: scene 0 has no nodes", false, true);
    warning("nothing to draw", "SceneWithoutMeshNode", gltfEdited([](Json& j) { j["nodes"][0].erase("mesh"); }),
            "nothing to draw: no node of scene 0 holds a mesh", false, true);

    // -- Animations (the loader validates them so that playback needs no checks).
    const std::vector<float> move = {0, 0, 0, 1, 0, 0};
    error("animation", "InputDecreasing", animatedTriangle({1, 0}, move, "VEC3", 3),
          "animation 0 sampler 0: key times decrease at key 1");
    loads("animation", "InputEqualTimes", animatedTriangle({0, 0, 1}, {0, 0, 0, 1, 0, 0, 1, 0, 0}, "VEC3", 3));
    loads("animation", "LastsTenToTheThirtySeconds", animatedTriangle({0, 1e30f}, move, "VEC3", 3));
    error("animation", "InputNotFloat", gltfOf([] {
        GltfBuilder b;
        b.addTriangle();
        const int input = b.addAccessor(b.addView(std::vector<uint16_t>{0, 1}), kUnsignedShort, 2, "SCALAR");
        const int output = b.addFloats({0, 0, 0, 1, 0, 0}, "VEC3", 3);
        b.doc["animations"] = Json::array({{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
                                            {"samplers", {{{"input", input}, {"output", output}}}}}});
        return b;
    }), "animation 0 sampler 0 input: accessor 3 must be SCALAR of FLOAT");
    error("animation", "InputNotScalar", animatedTriangle({0, 1}, move, "VEC3", 3, [](Json& j) {
        j["animations"][0]["samplers"][0]["input"] = 4;  // the VEC3 output as input
    }), "input: accessor 4 must be SCALAR of FLOAT, not VEC3");
    error("animation", "OutputWrongType", animatedTriangle({0, 1}, {0, 0, 0, 1, 1, 0, 0, 1}, "VEC4", 4),
          "animation 0 sampler 0 output: accessor 4 must be VEC3 of FLOAT");
    error("animation", "OutputCountNotInputCount", animatedTriangle({0, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3", 3),
          "9 output values for 2 keys (expected 6");
    error("animation", "CubicOutputWithoutTangents", animatedTriangle({0, 1}, move, "VEC3", 3, [](Json& j) {
        j["animations"][0]["samplers"][0]["interpolation"] = "CUBICSPLINE";
    }), "6 output values for 2 keys (expected 18");
    error("animation", "UnknownInterpolation", animatedTriangle({0, 1}, move, "VEC3", 3, [](Json& j) {
        j["animations"][0]["samplers"][0]["interpolation"] = "BEZIER";
    }), "unknown interpolation 'BEZIER'");
    error("animation", "ChannelMissingNode", animatedTriangle({0, 1}, move, "VEC3", 3, [](Json& j) {
        j["animations"][0]["channels"][0]["target"]["node"] = 7;
    }), "animation 0 channel 0: node 7 does not exist");
    error("animation", "ChannelMissingSampler", animatedTriangle({0, 1}, move, "VEC3", 3, [](Json& j) {
        j["animations"][0]["channels"][0]["sampler"] = 4;
    }), "animation 0 channel 0: sampler 4 does not exist");
    error("animation", "WeightsWithoutMorphTargets", animatedTriangle({0, 1}, {0, 1}, "SCALAR", 1, [](Json& j) {
        j["animations"][0]["channels"][0]["target"]["path"] = "weights";
    }), "animates the weights of node 0, whose mesh has no morph targets");
    error("animation", "AnimatedMatrixNode", animatedTriangle({0, 1}, move, "VEC3", 3, [](Json& j) {
        j["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    }), "node 0 has a matrix, and only TRS nodes may be animated");
    error("animation", "ChannelWithoutTarget", animatedTriangle({0, 1}, move, "VEC3", 3, [](Json& j) {
        j["animations"][0]["channels"][0].erase("target");
    }), "channels[0].target: expected an object");
    // -- Skins and morph targets.
    const std::vector<uint8_t> joint0(12, 0);
    const std::vector<float> full = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    loads("skin", "OneJoint", skinnedTriangle(joint0, full));
    error("skin", "JointIndexBeyondSkin", skinnedTriangle({0, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0}, full),
          "skin 0: a vertex names joint 3, but the skin has 1 joints");
    error("skin", "JointsOfFloat", skinnedTriangle(joint0, full, [](GltfBuilder& b) {
        b.doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = 2;  // the FLOAT weights
    }), "JOINTS_0: accessor 2 must be VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT");
    error("skin", "WeightsOfBytesNotNormalized", skinnedTriangle(joint0, full, [](GltfBuilder& b) {
        b.doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = 1;  // the UNSIGNED_BYTE joints
    }), "WEIGHTS_0: accessor 1 must be VEC4 of FLOAT or normalized (UNSIGNED_)BYTE/SHORT");
    error("skin", "WeightNan", skinnedTriangle(joint0, {1, 0, 0, 0, kNan, 0, 0, 0, 1, 0, 0, 0}),
          "WEIGHTS_0: vertex 1 has weight nan (weights must be finite and >= 0)");
    error("skin", "WeightNegative", skinnedTriangle(joint0, {1, 0, 0, 0, 1.5f, -0.5f, 0, 0, 1, 0, 0, 0}),
          "WEIGHTS_0: vertex 1 has weight -0.500000");
    error("skin", "WeightsAllZero", skinnedTriangle(joint0, {1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}),
          "vertex 1 has no joint weight (all are 0)");
    warning("skin", "WeightsNotSummingToOne", skinnedTriangle(joint0, {1, 0, 0, 0, 0.5f, 0, 0, 0, 1, 0, 0, 0}),
            "1 vertices have skin weights that do not sum to 1 (renormalized)", true);
    error("skin", "InverseBindMatrixCountMismatch", skinnedTriangle(joint0, full, [](GltfBuilder& b) {
        b.doc["skins"][0]["joints"] = {1, 1};
    }), "skin 0: inverseBindMatrices has 1 matrices for 2 joints");
    error("skin", "HundredThousandJoints", skinnedTriangle(joint0, full, [](GltfBuilder& b) {
        b.doc["skins"][0]["joints"] = Json(std::vector<int>(100000, 1));
    }), "skin 0: 100000 joints, more than the 65536 a vertex can name");
    error("skin", "JointNodeMissing", skinnedTriangle(joint0, full, [](GltfBuilder& b) { b.doc["skins"][0]["joints"] = {9}; }),
          "skin 0: joint node 9 does not exist");
    error("skin", "SkinMissing", skinnedTriangle(joint0, full, [](GltfBuilder& b) { b.doc["nodes"][1]["skin"] = 4; }),
          "skin 4 does not exist");
    error("morph", "TargetCountDiffersFromMesh", morphedTriangle({0, 0, 1, 0, 0, 1}),
          "morph target 0 POSITION: 2 elements, POSITION has 3");
    error("morph", "TargetDeltaNan", morphedTriangle({0, 0, 1, 0, kNan, 1, 0, 0, 1}), "morph target 0 POSITION: element 1 is not finite");
    error("morph", "WeightsCountDiffersFromTargets", morphedTriangle({0, 0, 1, 0, 0, 1, 0, 0, 1}, [](GltfBuilder& b) {
        b.doc["meshes"][0]["weights"] = {0.5, 0.5};
    }), "mesh 0: 2 weights for 1 morph targets");
    error("morph", "PrimitivesWithDifferentTargetCounts", morphedTriangle({0, 0, 1, 0, 0, 1, 0, 0, 1}, [](GltfBuilder& b) {
        Json second = b.doc["meshes"][0]["primitives"][0];
        second.erase("targets");
        b.doc["meshes"][0]["primitives"].push_back(second);
    }), "mesh 0 primitive 1: 0 morph targets, primitive 0 has 1");
    loads("morph", "SparseTargetWithoutBufferView", morphedTriangle({0, 0, 1, 0, 0, 1, 0, 0, 1}, [](GltfBuilder& b) {
        // All zero but one vertex: a sparse accessor over nothing.
        const int values = b.addFloats({0, 0, 2}, "VEC3", 3);
        const int view = b.doc["accessors"][values]["bufferView"];
        const int indices = b.addView(std::vector<uint16_t>{2, 0});
        const Json sparse = {{"count", 1},
                             {"indices", {{"bufferView", indices}, {"componentType", kUnsignedShort}}},
                             {"values", {{"bufferView", view}}}};
        b.doc["accessors"].push_back({{"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}, {"sparse", sparse}});
        b.doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = int(b.doc["accessors"].size()) - 1;
    }));
    // -- EXT_mesh_gpu_instancing.
    auto instanced = [](std::function<void(GltfBuilder&)> edit) {
        return gltfOf([edit] {
            GltfBuilder b;
            b.addTriangle();
            const int t = b.addFloats({0, 0, 0, 2, 0, 0}, "VEC3", 3);
            b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"TRANSLATION", t}};
            b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
            edit(b);
            return b;
        });
    };
    loads("instancing", "TwoInstances", instanced([](GltfBuilder&) {}));
    error("instancing", "AttributeCountsDiffer", instanced([](GltfBuilder& b) {
        b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] = b.addFloats({1, 1, 1}, "VEC3", 3);
    }), "EXT_mesh_gpu_instancing: SCALE has 1 instances, another attribute 2");
    error("instancing", "TranslationOfShorts", instanced([](GltfBuilder& b) {
        b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["TRANSLATION"] = 2;  // the index accessor
    }), "EXT_mesh_gpu_instancing TRANSLATION: accessor 2 must be VEC3 of FLOAT");
    error("instancing", "MissingAccessor", instanced([](GltfBuilder& b) {
        b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"] = 40;
    }), "EXT_mesh_gpu_instancing ROTATION: accessor 40 does not exist");
    // -- KHR_draco_mesh_compression (a quad encoded by Draco's encoder; tests/unit/draco_test_util.h).
    auto draco = [](std::function<void(Bytes&)> stream, std::function<void(GltfBuilder&)> edit = {}) {
        return gltfOf([stream, edit] {
            const DracoQuad quad;
            Bytes bytes = quad.encode();
            if (stream) stream(bytes);
            GltfBuilder b = quad.compressed(bytes);
            if (edit) edit(b);
            return b;
        });
    };
    loads("draco", "Quad", draco({}));
    error("draco", "TruncatedStream", draco([](Bytes& s) { s.resize(s.size() / 2); }),
          "KHR_draco_mesh_compression: Draco decoding failed");
    error("draco", "NotADracoStream", draco([](Bytes& s) { std::fill(s.begin(), s.end(), uint8_t('x')); }),
          "KHR_draco_mesh_compression: not a Draco stream");
    error("draco", "AttributeIdNotInStream", draco({}, [](GltfBuilder& b) {
        b.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 9;
    }), "attribute NORMAL: the Draco mesh has no attribute 9");
    error("draco", "AccessorCountDiffers", draco({}, [](GltfBuilder& b) { b.doc["accessors"][0]["count"] = 5; }),
          "attribute POSITION: the accessor counts 5, the Draco mesh has 4 vertices");
    error("draco", "BufferViewOutsideTheBuffer", draco({}, [](GltfBuilder& b) {
        b.doc["bufferViews"][0]["byteLength"] = 1 << 20;
    }), "KHR_draco_mesh_compression: bufferView 0 [0, +1048576) lies outside buffer 0");
    // -- EXT_meshopt_compression (a quad whose views are compressed by meshoptimizer's encoders;
    // tests/unit/meshopt_test_util.h). Views: 0 POSITION, 1 NORMAL (octahedral), 2 TEXCOORD_0, 3 indices.
    auto meshopt = [](std::function<void(Json&)> edit) {
        return gltfOf([edit] {
            GltfBuilder b = meshoptQuad(true);
            if (edit) edit(b.doc["bufferViews"]);
            return b;
        });
    };
    auto codec = [](int view) { return [view](Json& views) -> Json& { return views[view]["extensions"]["EXT_meshopt_compression"]; }; };
    loads("meshopt", "Quad", meshopt({}));
    error("meshopt", "StreamTruncated", meshopt([=](Json& v) { codec(0)(v)["byteLength"] = 8; }),
          "bufferView 0 EXT_meshopt_compression: the ATTRIBUTES data does not decode");
    error("meshopt", "IndicesTruncated", meshopt([=](Json& v) { codec(3)(v)["byteLength"] = 1; }),
          "bufferView 3 EXT_meshopt_compression: the TRIANGLES data does not decode");
    error("meshopt", "UnknownMode", meshopt([=](Json& v) { codec(0)(v)["mode"] = "VERTICES"; }), "unknown mode 'VERTICES'");
    error("meshopt", "QuaternionOfStride4", meshopt([=](Json& v) { codec(1)(v)["filter"] = "QUATERNION"; }),
          "QUATERNION needs a byteStride of 8, not 4");
    error("meshopt", "ClaimsMoreThanTheCodecProduces", meshopt([=](Json& v) {
        codec(0)(v)["count"] = 100000000;
        v[0]["byteLength"] = 1200000000;
    }), "compressed bytes cannot hold the 1200000000 bytes it claims");
    error("meshopt", "SourceOutsideTheBuffer", meshopt([=](Json& v) { codec(2)(v)["byteOffset"] = 1 << 20; }),
          "lies outside buffer 0");
    warning("animation", "PointerPath", animatedTriangle({0, 1}, move, "VEC3", 3, [](Json& j) {
        j["animations"][0]["channels"][0]["target"]["path"] = "pointer";
    }), "animation 0 channel 0: target path 'pointer' is not supported (ignored)", true);
    // -- Material layers: KHR_materials_ior and KHR_materials_specular.
    const auto layered = [](Json extensions) {
        return gltfEdited([extensions](Json& j) {
            j["materials"] = Json::array({{{"extensions", extensions}}});
            j["meshes"][0]["primitives"][0]["material"] = 0;
        });
    };
    loads("material layers", "SpecularGlossinessConversion",
          layered({{"KHR_materials_ior", {{"ior", 0}}}, {"KHR_materials_specular", {{"specularColorFactor", {0.9, 0.6, 0.3}}}}}));
    error("material layers", "SpecularFactorString", layered({{"KHR_materials_specular", {{"specularFactor", "1"}}}}),
          "KHR_materials_specular.specularFactor: expected a number, got the string \"1\"");
    error("material layers", "IorArray", layered({{"KHR_materials_ior", {{"ior", {1.5}}}}}),
          "KHR_materials_ior.ior: expected a number, got an array");
    error("material layers", "SpecularColorTextureMissing",
          layered({{"KHR_materials_specular", {{"specularColorTexture", {{"index", 3}}}}}}),
          "specularColorTexture: texture 3 does not exist");
    warning("material layers", "IorBelowOne", layered({{"KHR_materials_ior", {{"ior", 0.5}}}}),
            "ior 0.5 is outside [1, inf] (using 1)", true);
    warning("material layers", "NegativeSpecularColor", layered({{"KHR_materials_specular", {{"specularColorFactor", {-1, 1, 1}}}}}),
            "specularColorFactor -1 is outside [0, inf] (using 0)", true);
    // KHR_materials_clearcoat.
    loads("material layers", "ClearcoatFactorsOnly",
          layered({{"KHR_materials_clearcoat", {{"clearcoatFactor", 1}, {"clearcoatRoughnessFactor", 0.2}}}}));
    error("material layers", "ClearcoatFactorString", layered({{"KHR_materials_clearcoat", {{"clearcoatFactor", "1"}}}}),
          "KHR_materials_clearcoat.clearcoatFactor: expected a number, got the string \"1\"");
    error("material layers", "ClearcoatNormalTextureMissing",
          layered({{"KHR_materials_clearcoat", {{"clearcoatFactor", 1}, {"clearcoatNormalTexture", {{"index", 2}}}}}}),
          "clearcoatNormalTexture: texture 2 does not exist");
    error("material layers", "ClearcoatNormalScaleString",
          layered({{"KHR_materials_clearcoat", {{"clearcoatNormalTexture", {{"index", 0}, {"scale", "x"}}}}}}),
          "clearcoatNormalTexture.scale: expected a number");
    warning("material layers", "ClearcoatFactorAboveOne", layered({{"KHR_materials_clearcoat", {{"clearcoatFactor", 2}}}}),
            "clearcoatFactor 2 is outside [0, 1] (using 1)", true);
    // KHR_materials_sheen.
    loads("material layers", "SheenFactorsOnly",
          layered({{"KHR_materials_sheen", {{"sheenColorFactor", {0.9, 0.5, 0.2}}, {"sheenRoughnessFactor", 0.4}}}}));
    error("material layers", "SheenColorTwoComponents", layered({{"KHR_materials_sheen", {{"sheenColorFactor", {1, 1}}}}}),
          "KHR_materials_sheen.sheenColorFactor: expected an array of 3 numbers");
    error("material layers", "SheenRoughnessTextureMissing",
          layered({{"KHR_materials_sheen", {{"sheenColorFactor", {1, 1, 1}}, {"sheenRoughnessTexture", {{"index", 6}}}}}}),
          "sheenRoughnessTexture: texture 6 does not exist");
    warning("material layers", "SheenColorAboveOne", layered({{"KHR_materials_sheen", {{"sheenColorFactor", {2, 1, 1}}}}}),
            "sheenColorFactor 2 is outside [0, 1] (using 1)", true);
    // KHR_materials_anisotropy.
    // The direction lives in a tangent frame, which this triangle's missing UVs leave arbitrary.
    warning("material layers", "AnisotropyWithoutUvs",
            layered({{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.7}, {"anisotropyRotation", 1.2}}}}),
            "its tangent frame (normal map or anisotropy) follows TEXCOORD_0, which the primitive lacks; tangents are arbitrary",
            true);
    error("material layers", "AnisotropyRotationString", layered({{"KHR_materials_anisotropy", {{"anisotropyRotation", "1"}}}}),
          "KHR_materials_anisotropy.anisotropyRotation: expected a number, got the string \"1\"");
    warning("material layers", "AnisotropyStrengthNegative", layered({{"KHR_materials_anisotropy", {{"anisotropyStrength", -1}}}}),
            "anisotropyStrength -1 is outside [0, 1] (using 0)", true);
    // KHR_materials_transmission and KHR_materials_volume.
    loads("material layers", "TransmissionVolumeFactorsOnly",
          layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                   {"KHR_materials_volume", {{"thicknessFactor", 0.5}, {"attenuationDistance", 2}, {"attenuationColor", {1, 0.5, 0.2}}}}}));
    error("material layers", "TransmissionFactorString", layered({{"KHR_materials_transmission", {{"transmissionFactor", "1"}}}}),
          "KHR_materials_transmission.transmissionFactor: expected a number, got the string \"1\"");
    error("material layers", "TransmissionTextureMissing",
          layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}, {"transmissionTexture", {{"index", 5}}}}}}),
          "transmissionTexture: texture 5 does not exist");
    error("material layers", "AttenuationColorTwoComponents",
          layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                   {"KHR_materials_volume", {{"attenuationColor", {1, 1}}}}}),
          "KHR_materials_volume.attenuationColor: expected an array of 3 numbers");
    error("material layers", "ThicknessTextureMissing",
          layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                   {"KHR_materials_volume", {{"thicknessFactor", 1}, {"thicknessTexture", {{"index", 4}}}}}}),
          "thicknessTexture: texture 4 does not exist");
    warning("material layers", "TransmissionAboveOne", layered({{"KHR_materials_transmission", {{"transmissionFactor", 2}}}}),
            "transmissionFactor 2 is outside [0, 1] (using 1)", true);
    warning("material layers", "ThicknessNegative",
            layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}}}, {"KHR_materials_volume", {{"thicknessFactor", -2}}}}),
            "thicknessFactor -2 is outside [0, inf] (using 0)", true);
    warning("material layers", "AttenuationDistanceZero",
            layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                     {"KHR_materials_volume", {{"thicknessFactor", 1}, {"attenuationDistance", 0}}}}),
            "attenuationDistance 0 is not > 0: no absorption", true);
    // KHR_materials_iridescence.
    loads("material layers", "IridescenceFactorsOnly",
          layered({{"KHR_materials_iridescence", {{"iridescenceFactor", 1}, {"iridescenceIor", 1.6}, {"iridescenceThicknessMaximum", 500}}}}));
    error("material layers", "IridescenceIorString", layered({{"KHR_materials_iridescence", {{"iridescenceIor", "1.3"}}}}),
          "KHR_materials_iridescence.iridescenceIor: expected a number, got the string \"1.3\"");
    error("material layers", "IridescenceThicknessTextureMissing",
          layered({{"KHR_materials_iridescence", {{"iridescenceFactor", 1}, {"iridescenceThicknessTexture", {{"index", 7}}}}}}),
          "iridescenceThicknessTexture: texture 7 does not exist");
    warning("material layers", "IridescenceFactorAboveOne", layered({{"KHR_materials_iridescence", {{"iridescenceFactor", 1.5}}}}),
            "iridescenceFactor 1.5 is outside [0, 1] (using 1)", true);
    warning("material layers", "IridescenceThicknessNegative",
            layered({{"KHR_materials_iridescence", {{"iridescenceFactor", 1}, {"iridescenceThicknessMaximum", -100}}}}),
            "iridescenceThicknessMaximum -100 is outside [0, inf] (using 0)", true);
    // KHR_materials_diffuse_transmission and KHR_materials_dispersion.
    loads("material layers", "DiffuseTransmissionFactorsOnly",
          layered({{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 0.5}, {"diffuseTransmissionColorFactor", {1, 0.8, 0.5}}}},
                   {"KHR_materials_volume", {{"thicknessFactor", 0.2}}}}));
    error("material layers", "DiffuseTransmissionColorTwoComponents",
          layered({{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionColorFactor", {1, 1}}}}}),
          "KHR_materials_diffuse_transmission.diffuseTransmissionColorFactor: expected an array of 3 numbers");
    error("material layers", "DiffuseTransmissionTextureMissing",
          layered({{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 1}, {"diffuseTransmissionTexture", {{"index", 5}}}}}}),
          "diffuseTransmissionTexture: texture 5 does not exist");
    warning("material layers", "DiffuseTransmissionAboveOne", layered({{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 1.5}}}}),
            "diffuseTransmissionFactor 1.5 is outside [0, 1] (using 1)", true);
    loads("material layers", "DispersionWithVolume",
          layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}}}, {"KHR_materials_volume", {{"thicknessFactor", 1}}},
                   {"KHR_materials_dispersion", {{"dispersion", 0.33}}}}));
    error("material layers", "DispersionString", layered({{"KHR_materials_dispersion", {{"dispersion", "0.3"}}}}),
          "KHR_materials_dispersion.dispersion: expected a number, got the string \"0.3\"");
    note("material layers", "DispersionWithoutVolume",
         layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}}}, {"KHR_materials_dispersion", {{"dispersion", 1}}}}),
         "dispersion 1 has no effect without KHR_materials_transmission and a KHR_materials_volume thickness (thin-walled)", true);
    warning("material layers", "DispersionNegative",
            layered({{"KHR_materials_transmission", {{"transmissionFactor", 1}}}, {"KHR_materials_volume", {{"thicknessFactor", 1}}},
                     {"KHR_materials_dispersion", {{"dispersion", -1}}}}),
            "dispersion -1 is outside [0, inf] (using 0)", true);
    // KHR_materials_pbrSpecularGlossiness and KHR_materials_variants.
    loads("material layers", "SpecularGlossinessFactorsOnly",
          layered({{"KHR_materials_pbrSpecularGlossiness", {{"diffuseFactor", {0.8, 0.2, 0.2, 1}}, {"glossinessFactor", 0.6}}}}));
    warning("material layers", "GlossinessAboveOne", layered({{"KHR_materials_pbrSpecularGlossiness", {{"glossinessFactor", 3}}}}),
            "glossinessFactor 3 is outside [0, 1] (using 1)", true);
    error("material layers", "VariantMaterialMissing", gltfEdited([](Json& j) {
              j["extensions"] = {{"KHR_materials_variants", {{"variants", Json::array({Json{{"name", "a"}}})}}}};
              j["meshes"][0]["primitives"][0]["extensions"] = {
                  {"KHR_materials_variants", {{"mappings", Json::array({Json{{"material", 4}, {"variants", {0}}}})}}}};
          }), "KHR_materials_variants mapping 0: material 4 does not exist");
    warning("material layers", "ClearcoatRoughnessNegative",
            layered({{"KHR_materials_clearcoat", {{"clearcoatFactor", 1}, {"clearcoatRoughnessFactor", -0.5}}}}),
            "clearcoatRoughnessFactor -0.5 is outside [0, 1] (using 0)", true);

    // -- Texture formats: KTX2 with Basis Universal (KHR_texture_basisu) and WebP (EXT_texture_webp).
    // A 64×64 ETC1S file with 7 levels, stored smallest first, so level 0 ends the file.
    const auto ktx2 = [](std::function<void(Bytes&)> edit) -> Make {
        return [edit](const fs::path& dir) {
            Bytes k = testKtx2("etc1s_mips.ktx2");
            edit(k);
            return ktx2Triangle(k).writeGlb(dir);
        };
    };
    const auto setU64 = [](Bytes& b, size_t at, uint64_t v) {
        for (int i = 0; i < 8; ++i) b[at + size_t(i)] = uint8_t(v >> (8 * i));
    };
    loads("texture format", "Ktx2Etc1sWithMips", ktx2([](Bytes&) {}));
    error("truncated", "Ktx2Header", ktx2([](Bytes& k) { k.resize(40); }), "image 0: KTX2: truncated: 40 bytes, the header needs 80");
    error("truncated", "Ktx2Level0", ktx2([](Bytes& k) { k.resize(k.size() - 9); }), "image 0: KTX2: level 0 (");
    error("chunk length", "Ktx2LevelLengthLies", ktx2([setU64](Bytes& k) { setU64(k, 88, uint64_t(1) << 40); }),
          "image 0: KTX2: level 0 (1099511627776 bytes at");
    error("chunk length", "Ktx2GlobalDataLies", ktx2([setU64](Bytes& k) { setU64(k, 72, 0xFFFFFFFFull); }),
          "image 0: KTX2: supercompression global data (4294967295 bytes at");
    error("absurd size", "Ktx2Huge", ktx2([](Bytes& k) { setU32(k, 20, 1u << 20); setU32(k, 24, 1u << 20); }),
          "image 0: KTX2: image size 1048576x1048576 exceeds the limit of 16384 pixels per side");
    error("absurd size", "Ktx2TooManyLevels", ktx2([](Bytes& k) { setU32(k, 40, 20); }),
          "image 0: KTX2: 20 mip levels, a 64x64 image has at most 7");
    error("unknown value", "Ktx2UnknownSupercompression", ktx2([](Bytes& k) { setU32(k, 44, 9); }),
          "image 0: KTX2: unknown supercompression scheme 9");
    error("unknown value", "Ktx2Etc1sWithZstandard", ktx2([](Bytes& k) { setU32(k, 44, 2); }),
          "image 0: KTX2: ETC1S payload with supercompression scheme 2 (BasisLZ, 1, is required)");
    error("unknown value", "Ktx2NotBasis", ktx2([](Bytes& k) { setU32(k, 12, 37); }),
          "image 0: KTX2: vkFormat 37 is not a Basis Universal payload");
    warning("texture format", "Ktx2LinearFileAsColour", [](const fs::path& dir) {
        return ktx2Triangle(testKtx2("etc1s_noise_linear.ktx2")).writeGlb(dir);
    }, "the KTX2 file's transfer function is linear but a material reads it as colour (sRGB)", true);
    const auto webp = [](bool lossless) {
        Bytes pixels(16 * 16 * 4);
        for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint8_t(i % 4 == 3 ? 255 : i * 7);
        return candela::test::encodeWebp(16, 16, pixels, lossless);
    };
    loads("texture format", "WebpLossless", [webp](const fs::path& dir) { return webpTriangle(webp(true)).writeGlb(dir); });
    loads("texture format", "WebpLossy", [webp](const fs::path& dir) { return webpTriangle(webp(false)).writeGlb(dir); });
    error("truncated", "Webp", [webp](const fs::path& dir) {
        Bytes w = webp(true);
        w.resize(w.size() / 2);
        return webpTriangle(w).writeGlb(dir);
    }, "image 0: WebP: cannot decode the image");
    return rows;
}

// ---- the test --------------------------------------------------------------------------------------

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    for (size_t at = 0; at < text.size();) {
        const size_t end = text.find('\n', at);
        out.push_back(text.substr(at, end == std::string::npos ? std::string::npos : end - at));
        at = end == std::string::npos ? text.size() : end + 1;
    }
    return out;
}

class Catalogue : public testing::TestWithParam<Row> {};

TEST_P(Catalogue, StatedOutcomeAndExitCode) {
    const Row& row = GetParam();
    candela::test::TempDir dir("candela_catalogue");
    const fs::path file = row.make(dir.path());
    ASSERT_FALSE(HasFatalFailure());
    const std::string ext = file.extension().string();
    const bool environment = ext == ".hdr" || ext == ".exr" || ext == ".png";
    const fs::path out = dir / "out.png";
    const std::string args =
        "render --width 48 --height 32 --out '" + out.string() + "' " +
        (environment ? "--ibl-cube-size 16 --ibl-sh-size 16 --env '" + file.string() + "'"
                     : "--env none --camera-orbit 0,90,0 --scene '" + file.string() + "'");
    const candela::test::Result r = candela::test::run(args);
    RecordProperty("stderr", r.stderrText);
    ASSERT_NE(r.exitCode, -1) << "crashed: candela " << args;
    const std::vector<std::string> stderrLines = lines(r.stderrText);

    if (row.outcome == Outcome::Error) {
        EXPECT_EQ(r.exitCode, 2) << r.stderrText;
        ASSERT_EQ(stderrLines.size(), 1u) << "expected one line:\n" << r.stderrText;
        EXPECT_EQ(stderrLines[0].rfind("candela: error: " + file.string() + ": ", 0), 0u) << stderrLines[0];
        EXPECT_NE(stderrLines[0].find(row.fragment), std::string::npos) << stderrLines[0] << "\nexpected: " << row.fragment;
        EXPECT_FALSE(fs::exists(out)) << "an image was written";
        return;
    }
    EXPECT_EQ(r.exitCode, 0) << r.stderrText;
    if (row.outcome == Outcome::Loads || row.outcome == Outcome::Note) {
        EXPECT_EQ(r.stderrText, "") << "a valid file renders quietly";
    }
    if (row.outcome == Outcome::Note) {
        const candela::test::Result verbose = candela::test::run(args + " --verbose");
        bool said = false;
        for (const std::string& line : lines(verbose.stderrText))
            said = said || (line.rfind("candela: ", 0) == 0 && line.find(file.string()) != std::string::npos &&
                            line.find(row.fragment) != std::string::npos);
        EXPECT_TRUE(said) << "--verbose does not say '" << row.fragment << "' of the file:\n" << verbose.stderrText;
    }
    bool named = row.outcome == Outcome::Loads || row.outcome == Outcome::Note;
    for (const std::string& line : stderrLines) {
        EXPECT_EQ(line.rfind("candela: warning: ", 0), 0u) << line;
        named = named || (line.find(file.string()) != std::string::npos && line.find(row.fragment) != std::string::npos);
    }
    EXPECT_TRUE(named) << "no warning naming the file and '" << row.fragment << "':\n" << r.stderrText;
    int width = 0, height = 0, channels = 0;
    uint8_t* pixels = stbi_load(out.c_str(), &width, &height, &channels, 4);
    ASSERT_NE(pixels, nullptr) << "no image written";
    EXPECT_EQ(width, 48);
    EXPECT_EQ(height, 32);
    int unlikeBackground = 0;
    for (int i = 0; i < width * height; ++i)
        if (std::memcmp(pixels + 4 * i, pixels, 4) != 0) ++unlikeBackground;
    stbi_image_free(pixels);
    if (row.visible) EXPECT_GT(unlikeBackground, 0) << "the scene does not show";
    else EXPECT_EQ(unlikeBackground, 0) << "expected nothing drawn";
}

INSTANTIATE_TEST_SUITE_P(Files, Catalogue, testing::ValuesIn(catalogue()), [](const testing::TestParamInfo<Row>& param) {
    std::string kind;
    for (char c : param.param.kind)
        if (std::isalnum(static_cast<unsigned char>(c))) kind += c;
    return kind + "_" + param.param.name;
});

// Not a test: writes every row's files under $CANDELA_CATALOGUE_DUMP/KIND_NAME/ with a manifest
// (manifest.tsv: folder, file to open, outcome, the row's text) for tools/validator/oracle.py, which
// runs the glTF-Validator over them. Run with --gtest_also_run_disabled_tests
// --gtest_filter=CatalogueFiles.DISABLED_WriteEveryRowsFiles.
TEST(CatalogueFiles, DISABLED_WriteEveryRowsFiles) {
    const char* root = std::getenv("CANDELA_CATALOGUE_DUMP");
    ASSERT_NE(root, nullptr) << "set CANDELA_CATALOGUE_DUMP to the folder to write";
    const char* outcomes[] = {"error", "warning", "note", "loads"};
    std::ofstream manifest(fs::path(root) / "manifest.tsv");
    for (const Row& row : catalogue()) {
        std::string kind;
        for (char c : row.kind)
            if (std::isalnum(static_cast<unsigned char>(c))) kind += c;
        const fs::path dir = fs::path(root) / (kind + "_" + row.name);
        fs::create_directories(dir);
        const fs::path file = row.make(dir);
        manifest << dir.filename().string() << '\t' << fs::relative(file, dir).string() << '\t'
                 << outcomes[static_cast<int>(row.outcome)] << '\t' << row.fragment << '\n';
    }
}

// The figures docs/robustness.md quotes: rows per outcome and how many needed a fix.
TEST(CatalogueSummary, CountsRows) {
    const std::vector<Row> rows = catalogue();
    const auto errors = std::count_if(rows.begin(), rows.end(), [](const Row& r) { return r.outcome == Outcome::Error; });
    const auto fixed = std::count_if(rows.begin(), rows.end(), [](const Row& r) { return r.fixedIn6; });
    const auto notes = std::count_if(rows.begin(), rows.end(), [](const Row& r) { return r.outcome == Outcome::Note; });
    std::printf("bad-input catalogue: %zu rows (%td errors, %td notes for --verbose, %td warnings or quiet loads), %td needed a fix\n",
                rows.size(), errors, notes, std::ptrdiff_t(rows.size()) - errors - notes, fixed);
    EXPECT_GE(rows.size(), 100u);
}

}  // namespace
}  // namespace candela::assets::test
