#pragma once
// Helpers for the glTF loader tests: a temporary folder, a tiny glTF writer (.gltf + .bin, data-URI
// embedded, or .glb) and a minimal PNG encoder (stored deflate blocks), so every test builds its
// input files itself.

#include "assets/gltf_loader.h"
#include "test_paths.h"
#include "core/errors.h"

#include "temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>
#include <unistd.h>

namespace candela::assets::test {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Bytes = std::vector<uint8_t>;

// glTF enum values, spelled out so tests do not need tiny_gltf.h.
enum : int {
    kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126
};
enum : int { kPoints = 0, kLines = 1, kLineLoop = 2, kLineStrip = 3, kTriangles = 4, kStrip = 5, kFan = 6 };

// The sample models in ../shared/assets, or "" when that folder is absent.
inline fs::path sharedModels() {
#ifdef CANDELA_SHARED_ASSETS
    const fs::path models = ::candela::test::sharedAssets() / "models";
    if (fs::is_directory(models)) return models;
#endif
    return {};
}

// Skips the test when ../shared/assets is absent.
#define REQUIRE_MODELS()                                                            \
    do {                                                                            \
        if (assets::test::sharedModels().empty()) GTEST_SKIP() << "../shared/assets not present"; \
    } while (false)

using candela::test::TempDir;

inline void writeFile(const fs::path& path, const void* data, size_t size) {
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), std::streamsize(size));
}
inline void writeFile(const fs::path& path, const Bytes& bytes) { writeFile(path, bytes.data(), bytes.size()); }
inline void writeFile(const fs::path& path, const std::string& text) { writeFile(path, text.data(), text.size()); }

inline Bytes readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::string base64(const Bytes& data) {
    static const char* kChars = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
        const uint32_t n = uint32_t(data[i]) << 16 | (i + 1 < data.size() ? uint32_t(data[i + 1]) << 8 : 0) |
                           (i + 2 < data.size() ? uint32_t(data[i + 2]) : 0);
        out += kChars[(n >> 18) & 63];
        out += kChars[(n >> 12) & 63];
        out += i + 1 < data.size() ? kChars[(n >> 6) & 63] : '=';
        out += i + 2 < data.size() ? kChars[n & 63] : '=';
    }
    return out;
}

inline void putU32(Bytes& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}
inline void putU32BigEndian(Bytes& out, uint32_t v) {
    for (int i = 3; i >= 0; --i) out.push_back(uint8_t(v >> (8 * i)));
}

inline uint32_t crc32(const uint8_t* data, size_t size) {
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

inline void pngChunk(Bytes& png, const char type[4], const Bytes& data) {
    putU32BigEndian(png, uint32_t(data.size()));
    const size_t start = png.size();
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    putU32BigEndian(png, crc32(png.data() + start, png.size() - start));
}

// A PNG of the given size. colorType 6 = RGBA, 2 = RGB; bitDepth 8 or 16. `pixels` holds the rows
// top first, samples big-endian for 16 bits. With `header only`, IDAT and IEND are left out.
inline Bytes makePng(uint32_t width, uint32_t height, int bitDepth, int colorType, const Bytes& pixels,
                     bool headerOnly = false) {
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    Bytes ihdr;
    putU32BigEndian(ihdr, width);
    putU32BigEndian(ihdr, height);
    ihdr.insert(ihdr.end(), {uint8_t(bitDepth), uint8_t(colorType), 0, 0, 0});
    pngChunk(png, "IHDR", ihdr);
    if (headerOnly) return png;
    const size_t rowBytes = pixels.size() / height;
    Bytes raw;
    for (uint32_t y = 0; y < height; ++y) {
        raw.push_back(0);  // filter: none
        raw.insert(raw.end(), pixels.begin() + std::ptrdiff_t(y * rowBytes), pixels.begin() + std::ptrdiff_t((y + 1) * rowBytes));
    }
    Bytes z = {0x78, 0x01};
    size_t at = 0;
    do {
        const size_t n = std::min<size_t>(65535, raw.size() - at);
        z.push_back(at + n == raw.size() ? 1 : 0);  // BFINAL on the last stored block
        z.insert(z.end(), {uint8_t(n), uint8_t(n >> 8), uint8_t(~n), uint8_t(~n >> 8)});
        z.insert(z.end(), raw.begin() + std::ptrdiff_t(at), raw.begin() + std::ptrdiff_t(at + n));
        at += n;
    } while (at < raw.size());
    uint32_t a = 1, b = 0;
    for (uint8_t c : raw) a = (a + c) % 65521, b = (b + a) % 65521;
    putU32BigEndian(z, b << 16 | a);
    pngChunk(png, "IDAT", z);
    pngChunk(png, "IEND", {});
    return png;
}

// A 2×2 RGBA8 PNG with the given first pixel (the rest opaque white).
inline Bytes smallPng(std::array<uint8_t, 4> first = {255, 0, 0, 255}) {
    Bytes pixels = {first[0], first[1], first[2], first[3]};
    for (int i = 0; i < 3; ++i) pixels.insert(pixels.end(), {255, 255, 255, 255});
    return makePng(2, 2, 8, 6, pixels);
}

// Builds a glTF document and its single binary buffer.
struct GltfBuilder {
    Json doc = Json{{"asset", {{"version", "2.0"}}}};
    Bytes bin;
    std::vector<Json> moreBuffers;  // buffers 1, 2, ... as written (bin is buffer 0)

    // Appends `size` bytes (4-byte aligned) as a new bufferView; returns its index.
    int addView(const void* data, size_t size, int stride = 0) {
        while (bin.size() % 4) bin.push_back(0);
        const size_t offset = bin.size();
        bin.insert(bin.end(), static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + size);
        Json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
        if (stride) view["byteStride"] = stride;
        doc["bufferViews"].push_back(view);
        return int(doc["bufferViews"].size() - 1);
    }
    template <typename T>
    int addView(const std::vector<T>& values, int stride = 0) {
        return addView(values.data(), values.size() * sizeof(T), stride);
    }
    int addAccessor(int view, int componentType, size_t count, const std::string& type, bool normalized = false,
                    size_t byteOffset = 0) {
        Json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
        if (view >= 0) a["bufferView"] = view;
        if (normalized) a["normalized"] = true;
        if (byteOffset) a["byteOffset"] = byteOffset;
        doc["accessors"].push_back(a);
        return int(doc["accessors"].size() - 1);
    }
    // With min and max per component over the finite values (the glTF-Validator requires them for
    // POSITION and animation inputs; tools/validator/oracle.py runs it over the files these build).
    int addFloats(const std::vector<float>& values, const std::string& type, int components) {
        const int accessor = addAccessor(addView(values), kFloat, values.size() / size_t(components), type);
        Json low = Json::array(), high = Json::array();
        for (int c = 0; c < components; ++c) {
            float lo = std::numeric_limits<float>::infinity(), hi = -lo;
            for (size_t i = size_t(c); i < values.size(); i += size_t(components))
                if (std::isfinite(values[i])) lo = std::min(lo, values[i]), hi = std::max(hi, values[i]);
            if (!(lo <= hi)) return accessor;  // no finite value: no bounds
            low.push_back(lo);
            high.push_back(hi);
        }
        doc["accessors"][size_t(accessor)]["min"] = low;
        doc["accessors"][size_t(accessor)]["max"] = high;
        return accessor;
    }
    int addIndices(const std::vector<uint16_t>& indices) {
        return addAccessor(addView(indices), kUnsignedShort, indices.size(), "SCALAR");
    }
    // A mesh with one primitive; returns the mesh index.
    int addMesh(const Json& attributes, int indices = -1, int material = -1, int mode = -1) {
        Json primitive = {{"attributes", attributes}};
        if (indices >= 0) primitive["indices"] = indices;
        if (material >= 0) primitive["material"] = material;
        if (mode >= 0) primitive["mode"] = mode;
        doc["meshes"].push_back({{"primitives", Json::array({primitive})}});
        return int(doc["meshes"].size() - 1);
    }
    int addNode(Json node) {
        doc["nodes"].push_back(std::move(node));
        return int(doc["nodes"].size() - 1);
    }
    void setScene(const std::vector<int>& roots) {
        doc["scenes"] = Json::array({{{"nodes", roots}}});
        doc["scene"] = 0;
    }
    // The canonical test triangle in the XY plane (counter-clockwise seen from +Z), with a node.
    void addTriangle(bool withNormals = true) {
        const int pos = addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
        Json attributes = {{"POSITION", pos}};
        if (withNormals) attributes["NORMAL"] = addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
        const int mesh = addMesh(attributes, addIndices({0, 1, 2}));
        setScene({addNode({{"mesh", mesh}})});
    }

    Json withBuffer(const std::string& uri) const {
        Json d = doc;
        Json buffer = {{"byteLength", bin.size()}};
        if (!uri.empty()) buffer["uri"] = uri;
        if (!bin.empty() || !moreBuffers.empty()) d["buffers"] = Json::array({buffer});
        for (const Json& more : moreBuffers) d["buffers"].push_back(more);
        return d;
    }
    // NAME.gltf + NAME.bin in `dir`.
    fs::path writeGltf(const fs::path& dir, const std::string& name = "model") const {
        writeFile(dir / (name + ".bin"), bin);
        writeFile(dir / (name + ".gltf"), withBuffer(name + ".bin").dump());
        return dir / (name + ".gltf");
    }
    // One .gltf with the buffer as a data: URI.
    fs::path writeEmbedded(const fs::path& dir, const std::string& name = "model") const {
        writeFile(dir / (name + ".gltf"), withBuffer("data:application/octet-stream;base64," + base64(bin)).dump());
        return dir / (name + ".gltf");
    }
    Bytes glbBytes() const { return makeGlb(withBuffer("").dump(), bin); }
    fs::path writeGlb(const fs::path& dir, const std::string& name = "model") const {
        writeFile(dir / (name + ".glb"), glbBytes());
        return dir / (name + ".glb");
    }

    static Bytes makeGlb(std::string json, Bytes binChunk) {
        while (json.size() % 4) json += ' ';
        while (binChunk.size() % 4) binChunk.push_back(0);
        Bytes out;
        putU32(out, 0x46546C67);
        putU32(out, 2);
        putU32(out, uint32_t(12 + 8 + json.size() + (binChunk.empty() ? 0 : 8 + binChunk.size())));
        putU32(out, uint32_t(json.size()));
        putU32(out, 0x4E4F534A);
        out.insert(out.end(), json.begin(), json.end());
        if (!binChunk.empty()) {
            putU32(out, uint32_t(binChunk.size()));
            putU32(out, 0x004E4942);
            out.insert(out.end(), binChunk.begin(), binChunk.end());
        }
        return out;
    }
};

// Writes `v` little-endian over bytes[at, at + 4).
inline void setU32(Bytes& bytes, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + size_t(i)] = uint8_t(v >> (8 * i));
}

// A textured triangle whose base colour image is `uri` (a URI) or a bufferView holding `png`.
inline GltfBuilder texturedTriangle(const std::string& uri, const Bytes& png = {}) {
    GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int uv = b.addFloats({0, 0, 1, 0, 0, 1}, "VEC2", 2);
    b.doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    b.doc["textures"] = Json::array({{{"source", 0}}});
    if (!uri.empty()) b.doc["images"] = Json::array({{{"uri", uri}}});
    else b.doc["images"] = Json::array({{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}}});
    const int mesh = b.addMesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, b.addIndices({0, 1, 2}), 0);
    b.setScene({b.addNode({{"mesh", mesh}})});
    return b;
}

// texturedTriangle whose base colour texture takes its image only from texture extension
// `extension` (EXT_texture_webp, KHR_texture_basisu: required, no core source), the image being
// `bytes` in a bufferView with `mimeType`.
inline GltfBuilder extensionImageTriangle(const std::string& extension, const Bytes& bytes, const std::string& mimeType) {
    GltfBuilder b = texturedTriangle("", bytes);
    b.doc["images"][0]["mimeType"] = mimeType;
    b.doc["textures"] = Json::array({{{"extensions", {{extension, {{"source", 0}}}}}}});
    b.doc["extensionsUsed"] = {extension};
    b.doc["extensionsRequired"] = {extension};
    return b;
}
inline GltfBuilder webpTriangle(const Bytes& webp) { return extensionImageTriangle("EXT_texture_webp", webp, "image/webp"); }
inline GltfBuilder ktx2Triangle(const Bytes& ktx2) { return extensionImageTriangle("KHR_texture_basisu", ktx2, "image/ktx2"); }

#ifdef CANDELA_TEST_DATA
// A committed KTX2 test file (tests/data/ktx2, made by tools/ktx2-test-data).
inline Bytes testKtx2(const std::string& name) { return readBytes(::candela::test::testData() / "ktx2" / name); }
#endif

// Loads and returns the UserError's message, or "" if the load succeeded. Any other exception
// comes back as "UNEXPECTED ...", which no expectation matches.
inline std::string loadError(const fs::path& path, const assets::LoadOptions& options = {}) {
    try {
        (void)assets::loadGltf(path, options);
    } catch (const UserError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("UNEXPECTED exception: ") + e.what();
    }
    return {};
}

}  // namespace candela::assets::test
