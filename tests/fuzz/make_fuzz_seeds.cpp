// make_fuzz_seeds OUT: writes the fuzzers' seed corpora to OUT/gltf, OUT/hdr, OUT/exr, OUT/ktx2 and OUT/webp.
//  - glTF: the project's own small models built with the unit tests' GltfBuilder (every accessor
//    type, sparse, strips and fans, quantized attributes, node transforms, cameras, lights,
//    textures by bufferView, data URI and file URI, KHR_texture_transform) as .gltf and .glb, and
//    every .glb and self-contained .gltf of at most 64 KiB under ../shared/assets/models.
//  - HDR: the environment tests' Radiance writer (flat, new-style RLE, old-style RLE, flipped axes,
//    EXPOSURE and comment headers) and crops of ../shared/assets/environments re-encoded with the
//    header lines of the original files.
//  - EXR: files written with OpenEXR's C++ library (the tests' writer): half and float scanlines
//    under every compression, tiled files (one level, mipmaps, ripmaps), RGBA, Y, extra and UINT
//    channels, data window ≠ display window, multi-part files and a deep part.
// Seeds are generated rather than committed so that they follow the writers the tests use.
#include "environment_test_util.h"
#include "draco_test_util.h"
#include "gltf_test_util.h"
#include "meshopt_test_util.h"
#include "webp_test_writer.h"
#include "fuzz_targets.h"

#include "assets/environment.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

using namespace candela::assets;
using namespace candela::assets::test;

namespace {

constexpr uintmax_t kMaxSharedSeedBytes = 64 * 1024;

GltfBuilder texturedQuad(const std::string& imageUri, const Bytes& png) {
    GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    const int nrm = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    const int tan = b.addFloats({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1}, "VEC4", 4);
    const int uv = b.addFloats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2", 2);
    const int col = b.addFloats({1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1}, "VEC4", 4);
    Json tex = {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 0.5}, {"scale", {2, 3}}}}}}};
    b.doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", tex}, {"metallicRoughnessTexture", {{"index", 0}}}, {"baseColorFactor", {1, 0.5, 0.5, 1}}}},
                                       {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
                                       {"occlusionTexture", {{"index", 0}, {"strength", 0.5}}},
                                       {"emissiveTexture", {{"index", 0}, {"texCoord", 0}}},
                                       {"emissiveFactor", {1, 1, 1}},
                                       {"alphaMode", "MASK"},
                                       {"doubleSided", true},
                                       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}}});
    b.doc["samplers"] = Json::array({{{"magFilter", 9728}, {"minFilter", 9987}, {"wrapS", 33071}, {"wrapT", 33648}}});
    b.doc["textures"] = Json::array({{{"source", 0}, {"sampler", 0}}});
    if (!imageUri.empty()) b.doc["images"] = Json::array({{{"uri", imageUri}}});
    else b.doc["images"] = Json::array({{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}}});
    b.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_emissive_strength"};
    const int mesh = b.addMesh({{"POSITION", pos}, {"NORMAL", nrm}, {"TANGENT", tan}, {"TEXCOORD_0", uv}, {"COLOR_0", col}},
                               b.addIndices({0, 1, 2, 0, 2, 3}), 0);
    b.setScene({b.addNode({{"mesh", mesh}})});
    return b;
}

std::vector<std::pair<std::string, GltfBuilder>> ownModels(const Bytes& png) {
    std::vector<std::pair<std::string, GltfBuilder>> out;
    GltfBuilder tri;
    tri.addTriangle();
    out.emplace_back("triangle", tri);
    out.emplace_back("textured_bufferview", texturedQuad("", png));
    out.emplace_back("textured_uri", texturedQuad("image.png", {}));
    out.emplace_back("textured_data_uri", texturedQuad("data:image/png;base64," + base64(png), {}));

    GltfBuilder strips;  // strip, fan, points, lines; no indices
    const int pos = strips.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 0, 0}, "VEC3", 3);
    for (int mode : {0, 1, 2, 3, 5, 6}) strips.addMesh({{"POSITION", pos}}, -1, -1, mode);
    std::vector<int> nodes;
    for (int i = 0; i < 6; ++i) nodes.push_back(strips.addNode({{"mesh", i}, {"translation", {i, 0, 0}}}));
    strips.setScene(nodes);
    out.emplace_back("modes", strips);

    GltfBuilder quantized;  // SHORT normalized positions, BYTE normals, UNSIGNED_BYTE indices, sparse
    const std::vector<int16_t> p16 = {0, 0, 0, 0, 32767, 0, 0, 0, 0, 32767, 0, 0};
    const int qp = quantized.addAccessor(quantized.addView(p16, 8), kShort, 3, "VEC3", true);
    const std::vector<int8_t> n8 = {0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0};
    const int qn = quantized.addAccessor(quantized.addView(n8, 4), kByte, 3, "VEC3", true);
    const std::vector<uint8_t> i8 = {0, 1, 2, 0};
    const int qi = quantized.addAccessor(quantized.addView(i8), kUnsignedByte, 3, "SCALAR");
    const int sIdx = quantized.addView(std::vector<uint16_t>{1, 0});
    const int sVal = quantized.addView(std::vector<int16_t>{16000, 16000, 0, 0});
    quantized.doc["accessors"][qp]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", sIdx}, {"componentType", kUnsignedShort}}}, {"values", {{"bufferView", sVal}}}};
    quantized.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    quantized.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    const int qm = quantized.addMesh({{"POSITION", qp}, {"NORMAL", qn}}, qi);
    quantized.setScene({quantized.addNode({{"mesh", qm}, {"scale", {0.001, 0.001, 0.001}}})});
    out.emplace_back("quantized_sparse", quantized);

    GltfBuilder graph;  // hierarchy with TRS and matrix, cameras, lights, mirrored node
    graph.addTriangle();
    graph.doc["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100}, {"aspectRatio", 1.5}}}},
                                        {{"type", "orthographic"}, {"orthographic", {{"xmag", 2}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}});
    const Json lights = Json::array({{{"type", "point"}, {"intensity", 10}, {"range", 5}},
                                     {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
                                     {{"type", "directional"}, {"color", {1, 0.5, 0.2}}}});
    graph.doc["extensions"]["KHR_lights_punctual"]["lights"] = lights;
    graph.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    const int lit = graph.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}, {"rotation", {0, 0.7071, 0, 0.7071}}});
    const int cam = graph.addNode({{"camera", 0}, {"translation", {0, 0, 5}}});
    const int ortho = graph.addNode({{"camera", 1}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 3, 1}}});
    const int mirror = graph.addNode({{"mesh", 0}, {"scale", {-1, 1, 1}}, {"children", {lit}}});
    graph.setScene({0, graph.addNode({{"children", {cam, ortho, mirror}}, {"translation", {1, 2, 3}}})});
    out.emplace_back("graph", graph);

    // Animated, skinned (two JOINTS/WEIGHTS sets, short joints, normalized byte weights) and
    // morphed (two targets, one sparse), with STEP, LINEAR and CUBICSPLINE samplers on every path.
    GltfBuilder animated;
    const int ap = animated.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int j0 = animated.addAccessor(animated.addView(std::vector<uint16_t>{0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0}), kUnsignedShort, 3, "VEC4");
    const int w0 = animated.addAccessor(animated.addView(std::vector<uint8_t>{128, 127, 0, 0, 255, 0, 0, 0, 200, 55, 0, 0}), kUnsignedByte, 3, "VEC4", true);
    const int j1 = animated.addAccessor(animated.addView(std::vector<uint8_t>(12, 1)), kUnsignedByte, 3, "VEC4");
    const int w1 = animated.addFloats(std::vector<float>(12, 0.0f), "VEC4", 4);
    const int d0 = animated.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    const int d1 = animated.addFloats({0.1f, 0, 0, 0, 0.1f, 0, 0, 0, 0}, "VEC3", 3);
    const int ibm = animated.addFloats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1}, "MAT4", 16);
    const int am = animated.addMesh({{"POSITION", ap}, {"JOINTS_0", j0}, {"WEIGHTS_0", w0}, {"JOINTS_1", j1}, {"WEIGHTS_1", w1}},
                                    animated.addIndices({0, 1, 2}));
    animated.doc["meshes"][am]["primitives"][0]["targets"] = Json::array({{{"POSITION", d0}}, {{"POSITION", d1}, {"NORMAL", d0}}});
    animated.doc["meshes"][am]["weights"] = {0.25, 0};
    const int bone1 = animated.addNode({{"translation", {1, 0, 0}}});
    const int bone0 = animated.addNode({{"children", {bone1}}});
    animated.doc["skins"] = Json::array({{{"joints", {bone0, bone1}}, {"inverseBindMatrices", ibm}}});
    const int skinned = animated.addNode({{"mesh", am}, {"skin", 0}});
    const int morphOnly = animated.addNode({{"mesh", am}, {"weights", {0.5, 0.5}}, {"translation", {2, 0, 0}}});
    animated.setScene({skinned, bone0, morphOnly});
    const int t2 = animated.addFloats({0, 1}, "SCALAR", 1);
    const int v3 = animated.addFloats({0, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int c3 = animated.addFloats({0, 0, 0, 1, 1, 1, 0, 1, 0, 0, 0, 0, 1, 2, 1, 0, 0, 0}, "VEC3", 3);
    const int q4 = animated.addFloats({0, 0, 0, 1, 0, 0.7071f, 0, 0.7071f}, "VEC4", 4);
    const int w2 = animated.addFloats({0, 0, 1, 0.5f}, "SCALAR", 1);
    animated.doc["animations"] = Json::array(
        {{{"name", "all paths"},
          {"samplers", {{{"input", t2}, {"output", v3}, {"interpolation", "STEP"}},
                        {{"input", t2}, {"output", q4}},
                        {{"input", t2}, {"output", c3}, {"interpolation", "CUBICSPLINE"}},
                        {{"input", t2}, {"output", w2}}}},
          {"channels", {{{"sampler", 0}, {"target", {{"node", bone1}, {"path", "translation"}}}},
                        {{"sampler", 1}, {"target", {{"node", bone0}, {"path", "rotation"}}}},
                        {{"sampler", 2}, {"target", {{"node", morphOnly}, {"path", "scale"}}}},
                        {{"sampler", 3}, {"target", {{"node", morphOnly}, {"path", "weights"}}}}}}}});
    out.emplace_back("animated_skinned_morphed", animated);
    out.emplace_back("draco_quad", DracoQuad().compressed());  // KHR_draco_mesh_compression
    out.emplace_back("meshopt_quad", meshoptQuad(true));      // EXT_meshopt_compression
    return out;
}

void write(const fs::path& path, const Bytes& bytes) { writeFile(path, bytes); }

// True when every buffer and image of a .gltf is a data: URI or a bufferView.
bool selfContained(const Bytes& gltf) {
    const Json doc = Json::parse(gltf.begin(), gltf.end(), nullptr, false);
    if (doc.is_discarded()) return false;
    for (const char* array : {"buffers", "images"})
        for (const Json& item : doc.value(array, Json::array()))
            if (item.contains("uri") && item["uri"].get<std::string>().rfind("data:", 0) != 0) return false;
    return true;
}

void makeGltfSeeds(const fs::path& dir, const Bytes& png) {
    int copied = 0;
    for (const auto& [name, model] : ownModels(png)) {
        write(dir / (name + ".glb"), model.glbBytes());
        writeFile(dir / (name + ".gltf"), model.withBuffer("data:application/octet-stream;base64," + base64(model.bin)).dump());
    }
    // One model whose buffer is a file in the fuzzers' URI folder (tests/fuzz/uri-folder/buffer.bin
    // holds this triangle's buffer).
    GltfBuilder tri;
    tri.addTriangle();
    writeFile(dir / "triangle_external.gltf", tri.withBuffer("buffer.bin").dump());
    const fs::path shared = sharedModels();
    if (!shared.empty()) {
        for (const auto& entry : fs::recursive_directory_iterator(shared)) {
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || entry.file_size() > kMaxSharedSeedBytes) continue;
            if (ext != ".glb" && ext != ".gltf") continue;
            const Bytes bytes = readBytes(entry.path());
            if (ext == ".gltf" && !selfContained(bytes)) continue;  // would fail on its first URI
            {
                write(dir / ("shared_" + entry.path().filename().string()), bytes);
                ++copied;
            }
        }
    }
    std::printf("gltf seeds: %zu own, %d from ../shared/assets\n", ownModels(png).size() * 2 + 1, copied);
}

// The header lines of a shared Radiance file (between the magic line and the blank line).
std::string headerLinesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string line, lines;
    std::getline(in, line);  // magic
    while (std::getline(in, line) && !line.empty()) lines += line + "\n";
    return lines;
}

void makeHdrSeeds(const fs::path& dir) {
    int count = 0;
    const uint32_t w = 40, h = 5;
    const std::vector<Rgbe> texels = testTexels(w, h);
    auto add = [&](const std::string& name, const HdrWriter& writer, const std::vector<Rgbe>& t, uint32_t width,
                   uint32_t height) {
        write(dir / (name + ".hdr"), writer.write(t, width, height));
        ++count;
    };
    HdrWriter writer;
    add("rle", writer, texels, w, h);
    writer.scanlines = Scanlines::Flat;
    add("flat", writer, texels, w, h);
    writer.scanlines = Scanlines::OldRle;
    add("old_rle", writer, texels, w, h);
    writer = HdrWriter{};
    writer.resolution = "+Y 5 -X 40";
    writer.flipY = writer.flipX = true;
    add("flipped", writer, texels, w, h);
    writer = HdrWriter{};
    writer.magic = "#?RGBE\n";
    writer.headerLines = "# made by make_fuzz_seeds\nGAMMA=1.0\nEXPOSURE=2.0\nFORMAT=32-bit_rle_rgbe\nPRIMARIES=0.640 0.330 0.290 0.600 0.150 0.060 0.333 0.333\n";
    add("headers", writer, texels, w, h);
    const std::vector<Rgbe> wide = testTexels(160, 2);  // long enough rows for multi-byte RLE runs
    add("wide_rle", HdrWriter{}, wide, 160, 2);

    // Crops of the shared environments: their own header lines, 64 × 8 texels of their top rows.
    if (const fs::path shared = sharedEnvironments(); !shared.empty()) {
        for (const auto& entry : fs::directory_iterator(shared)) {
            if (entry.path().extension() != ".hdr") continue;
            const Environment env = loadEnvironment(entry.path());
            const uint32_t cw = 64, ch = 8, step = env.width / cw;
            std::vector<Rgbe> crop(size_t(cw) * ch);
            for (uint32_t y = 0; y < ch; ++y)
                for (uint32_t x = 0; x < cw; ++x) {
                    const float* t = env.texel(x * step, y * (env.height / 2 / ch));
                    crop[size_t(y) * cw + x] = encodeRgbe(t[0], t[1], t[2]);
                }
            HdrWriter original;
            original.headerLines = headerLinesOf(entry.path());
            add("shared_" + entry.path().stem().string(), original, crop, cw, ch);
        }
    }
    std::printf("hdr seeds: %d\n", count);
}

void makeExrSeeds(const fs::path& dir) {
    const uint32_t w = 16, h = 8;
    auto channel = [&](const std::string& name, ExrType type, float scale) {
        ExrChannel c{name, type, std::vector<float>(size_t(w) * h)};
        for (size_t i = 0; i < c.values.size(); ++i) c.values[i] = scale * float((i * 37) % 101) / 7.0f;
        return c;
    };
    auto rgb = [&](ExrType type) { return std::vector<ExrChannel>{channel("R", type, 1), channel("G", type, 2), channel("B", type, 3)}; };
    int count = 0;
    auto save = [&](const std::string& name, const Bytes& bytes) {
        write(dir / name, bytes);
        ++count;
    };
    for (Imf::Compression compression : candela::test::kExrCompressions)
        for (ExrType type : {ExrType::Half, ExrType::Float})
            save("rgb_" + candela::test::compressionName(compression) + (type == ExrType::Half ? "_half" : "_float") + ".exr",
                 makeExr(w, h, rgb(type), {compression}));
    for (Imf::LevelMode levels : {Imf::ONE_LEVEL, Imf::MIPMAP_LEVELS, Imf::RIPMAP_LEVELS})
        for (Imf::Compression compression : {Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION, Imf::DWAA_COMPRESSION})
            save("tiled_" + std::to_string(int(levels)) + "_" + candela::test::compressionName(compression) + ".exr",
                 makeExr(w, h, rgb(ExrType::Half), {compression, true, 8, levels}));
    std::vector<ExrChannel> rgba = rgb(ExrType::Half);
    rgba.push_back(channel("A", ExrType::Half, 1));
    save("rgba_half.exr", makeExr(w, h, rgba));
    save("y_float.exr", makeExr(w, h, {channel("Y", ExrType::Float, 5)}, {Imf::PIZ_COMPRESSION}));
    std::vector<ExrChannel> extra = rgb(ExrType::Float);
    extra.push_back(channel("Z", ExrType::Float, 1));
    extra.push_back(channel("id", ExrType::Uint, 1));
    save("extra_channels.exr", makeExr(w, h, extra, {Imf::RLE_COMPRESSION}));
    ExrLayout windows;
    windows.dataX = -3;
    windows.dataY = 2;
    windows.display = Imath::Box2i({0, 0}, {15, 7});
    save("windows.exr", makeExr(w, h, rgb(ExrType::Half), windows));
    const ExrPart z{"depth", w, h, {channel("Z", ExrType::Float, 1)}, {}, false};
    const ExrPart deep{"deep", w, h, rgb(ExrType::Float), {Imf::ZIPS_COMPRESSION}, true};
    const ExrPart colour{"beauty", w, h, rgb(ExrType::Half), {Imf::PIZ_COMPRESSION, true, 8}, false};
    save("multipart.exr", makeExrParts({z, deep, colour}));
    save("deep.exr", makeExrParts({deep}));
    std::printf("exr seeds: %d\n", count);
}

}  // namespace

// The committed KTX2 test files (tests/data/ktx2: ETC1S and UASTC, with and without Zstandard,
// with mips and alpha, made by the reference encoder).
void makeKtx2Seeds(const fs::path& dir) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(CANDELA_TEST_DATA) / "ktx2"))
        if (entry.path().extension() == ".ktx2") {
            fs::copy_file(entry.path(), dir / entry.path().filename(), fs::copy_options::overwrite_existing);
            ++count;
        }
    std::printf("ktx2 seeds: %d\n", count);
}

// Lists of scenes (`candela render @list.txt`): comments, blank lines, CRLF, spaces, folders.
void makeSceneListSeeds(const fs::path& dir) {
    const auto write = [&](const char* name, const std::string& text) { std::ofstream(dir / name, std::ios::binary) << text; };
    write("plain.txt", "models/Box.glb\nmodels/Duck.gltf\n");
    write("comments.txt", "# thumbnails\n\n  models/a b.glb  \n#models/skip.glb\nlibrary/\n");
    write("crlf.txt", "a.glb\r\nb.gltf\r\n\r\n");
    write("nested.txt", "a.glb\n@other.txt\n");
}

// The images `candela diff` compares: a byte choosing the format (0 PNG, 1 EXR), then the file —
// the small PNG of the glTF seeds and every EXR seed.
void makeComparedImageSeeds(const fs::path& out, const fs::path& dir) {
    const auto prefixed = [](uint8_t format, const Bytes& file) {
        Bytes bytes{format};
        bytes.insert(bytes.end(), file.begin(), file.end());
        return bytes;
    };
    write(dir / "small.png.seed", prefixed(0, smallPng()));
    for (const auto& entry : fs::directory_iterator(out / "exr")) {
        std::ifstream in(entry.path(), std::ios::binary);
        const Bytes file{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        write(dir / (entry.path().filename().string() + ".seed"), prefixed(1, file));
    }
}

// Lossless, lossy, with alpha and animated WebP files written with libwebp's encoder.
void makeWebpSeeds(const fs::path& dir) {
    std::vector<uint8_t> pixels(24 * 10 * 4);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint8_t(i * 37 + (i >> 5));
    std::vector<uint8_t> opaque = pixels;
    for (size_t i = 3; i < opaque.size(); i += 4) opaque[i] = 255;
    const auto write = [&](const char* name, const std::vector<uint8_t>& bytes) {
        std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    };
    write("lossless_alpha.webp", candela::test::encodeWebp(24, 10, pixels, true));
    write("lossy_alpha.webp", candela::test::encodeWebp(24, 10, pixels, false));
    write("lossy.webp", candela::test::encodeWebp(24, 10, opaque, false));
    write("animated.webp", candela::test::encodeAnimatedWebp(24, 10, {pixels, opaque}));
    std::printf("webp seeds: 4\n");
}

// Levels-of-detail cache files for the fuzz target's key and meshes: chains for both meshes (one
// that does not simplify), and a frame count alone.
void makeLodCacheSeeds(const fs::path& dir) {
    using namespace candela;
    geometry::LodCacheRecord chains{.framesDrawn = 2, .chains = std::vector<std::vector<geometry::SimplifiedLevel>>(2)};
    std::vector<uint32_t> coarse, coarsest = {0, 9, 63};
    for (uint32_t t = 0; t < 16; ++t) coarse.insert(coarse.end(), {t, t + 1, t + 32});
    (*chains.chains)[0] = {{coarse, 0.125f}, {coarsest, 0.5f}};
    const auto write = [&](const char* name, const geometry::LodCacheRecord& record) {
        const std::vector<std::byte> bytes = geometry::encodeLodCache(fuzz::kFuzzLodCacheKey, record);
        std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    };
    write("chains.clod", chains);
    write("frames.clod", {.framesDrawn = 5, .chains = std::nullopt});
    std::printf("lod_cache seeds: 2\n");
}

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_fuzz_seeds OUT_DIR\n");
        return 2;
    }
    const fs::path out = argv[1];
    for (const char* sub : {"gltf", "hdr", "exr", "ktx2", "webp", "lod_cache", "scene_list", "compared_image"}) fs::create_directories(out / sub);
    makeGltfSeeds(out / "gltf", smallPng());
    makeHdrSeeds(out / "hdr");
    makeExrSeeds(out / "exr");
    makeKtx2Seeds(out / "ktx2");
    makeWebpSeeds(out / "webp");
    makeLodCacheSeeds(out / "lod_cache");
    makeSceneListSeeds(out / "scene_list");
    makeComparedImageSeeds(out, out / "compared_image");
    return 0;
}
