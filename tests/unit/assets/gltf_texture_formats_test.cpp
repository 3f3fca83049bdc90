// Textures beyond PNG and JPEG: EXT_texture_webp (WebP through libwebp) and KHR_texture_basisu (KTX2
// with Basis Universal payloads, candela_textures), read through the glTF loader on tiny files the
// tests write themselves (WebP) or commit (KTX2, tests/data/ktx2, made by the reference encoder).
#include "gltf_test_util.h"
#include "webp_test_writer.h"
#include "assets/gltf_context.h"

#include <random>

namespace candela::assets::test {
namespace {

using candela::test::encodeAnimatedWebp;
using candela::test::encodeWebp;

// width × height RGBA8 texels from a fixed seed, with fully transparent texels whose RGB is not 0
// (a lossless encoder without `exact` would drop it).
assets::test::Bytes noise(uint32_t width, uint32_t height, uint32_t seed) {
    std::mt19937 rng(seed);
    Bytes pixels(size_t(width) * height * 4);
    for (uint8_t& v : pixels) v = uint8_t(rng());
    for (size_t i = 3; i < pixels.size(); i += 16) pixels[i] = 0;
    return pixels;
}

assets::test::Bytes solid(uint32_t width, uint32_t height, std::array<uint8_t, 4> rgba) {
    Bytes pixels;
    for (size_t i = 0; i < size_t(width) * height; ++i) pixels.insert(pixels.end(), rgba.begin(), rgba.end());
    return pixels;
}

bool hasLine(const std::vector<std::string>& lines, const std::string& fragment) {
    for (const std::string& line : lines)
        if (line.find(fragment) != std::string::npos) return true;
    return false;
}

TEST(GltfTextureFormatsTest, LosslessWebpDecodesToTheSameBytes) {
    test::TempDir dir;
    const Bytes pixels = noise(13, 7, 1);
    const scene::Scene scene = loadGltf(webpTriangle(encodeWebp(13, 7, pixels, true)).writeGlb(dir.path()));
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].width, 13u);
    EXPECT_EQ(scene.images[0].height, 7u);
    EXPECT_EQ(scene.images[0].rgba8, pixels);
    EXPECT_TRUE(scene.images[0].mips.empty());
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
}

TEST(GltfTextureFormatsTest, LossyWebpKeepsItsAlphaAndComesCloseInColour) {
    test::TempDir dir;
    // A smooth gradient (lossy coding's good case) under a hard-edged alpha.
    const uint32_t w = 32, h = 16;
    Bytes pixels;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) pixels.insert(pixels.end(), {uint8_t(x * 8), uint8_t(y * 16), 128, uint8_t(x < 16 ? 255 : 64)});
    const scene::Scene scene = loadGltf(webpTriangle(encodeWebp(w, h, pixels, false, 95.0f)).writeGlb(dir.path()));
    ASSERT_EQ(scene.images.size(), 1u);
    const Bytes& got = scene.images[0].rgba8;
    ASSERT_EQ(got.size(), pixels.size());
    double colourError = 0.0;
    for (size_t i = 0; i < got.size(); i += 4) {
        EXPECT_EQ(got[i + 3], pixels[i + 3]) << "alpha of texel " << i / 4;
        for (size_t c = 0; c < 3; ++c) colourError += std::abs(int(got[i + c]) - int(pixels[i + c]));
    }
    EXPECT_LT(colourError / double(w * h * 3), 3.0);  // mean absolute error in 8-bit levels
}

TEST(GltfTextureFormatsTest, WebpIsPreferredOverTheFallbackSource) {
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng({255, 0, 0, 255}));  // image 0: the PNG fallback
    const Bytes green = solid(2, 2, {0, 255, 0, 255});
    const Bytes webp = encodeWebp(2, 2, green, true);
    b.doc["images"].push_back({{"bufferView", b.addView(webp.data(), webp.size())}, {"mimeType", "image/webp"}});
    b.doc["textures"][0]["extensions"] = {{"EXT_texture_webp", {{"source", 1}}}};
    b.doc["extensionsUsed"] = {"EXT_texture_webp"};
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    ASSERT_EQ(scene.images.size(), 1u);  // the fallback is never decoded
    EXPECT_EQ(scene.images[0].rgba8, green);
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
}

TEST(GltfTextureFormatsTest, AnimatedWebpGivesItsFirstFrameWithANote) {
    test::TempDir dir;
    const Bytes first = noise(8, 4, 2), second = solid(8, 4, {10, 20, 30, 255});
    const scene::Scene scene = loadGltf(webpTriangle(encodeAnimatedWebp(8, 4, {first, second})).writeGlb(dir.path()));
    ASSERT_EQ(scene.images.size(), 1u);
    // The animation decoder composites onto a canvas: transparent texels keep the frame's bytes only
    // where alpha is not 0, so compare alpha everywhere and colour where the texel is visible.
    const Bytes& got = scene.images[0].rgba8;
    ASSERT_EQ(got.size(), first.size());
    for (size_t i = 0; i < got.size(); i += 4) {
        EXPECT_EQ(got[i + 3], first[i + 3]);
        if (first[i + 3] == 0) continue;
        for (size_t c = 0; c < 3; ++c) EXPECT_EQ(got[i + c], first[i + c]) << "texel " << i / 4;
    }
    EXPECT_TRUE(hasLine(scene.report.notes, "image 0: animated WebP: drawn from its first frame")) << testing::PrintToString(scene.report.notes);
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
}

TEST(GltfTextureFormatsTest, BadWebpIsOneLineNamingTheImage) {
    test::TempDir dir;
    Bytes webp = encodeWebp(16, 16, noise(16, 16, 3), true);
    webp.resize(webp.size() / 2);  // truncated bitstream
    const std::string error = loadError(webpTriangle(webp).writeGlb(dir.path()));
    EXPECT_NE(error.find("image 0: WebP: "), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;

    Bytes header = encodeWebp(16, 16, noise(16, 16, 3), true);
    header.resize(14);  // RIFF....WEBP and two bytes of the first chunk
    const std::string headerError = loadError(webpTriangle(header).writeGlb(dir.path()));
    EXPECT_NE(headerError.find("image 0: WebP: cannot read the header"), std::string::npos) << headerError;
}

TEST(GltfTextureFormatsTest, WebpAboveTheSizeLimitFailsBeforeDecoding) {
    test::TempDir dir;
    LoadOptions options;
    options.maxImageDimension = 8;
    const std::string error = loadError(webpTriangle(encodeWebp(16, 4, noise(16, 4, 4), true)).writeGlb(dir.path()), options);
    EXPECT_NE(error.find("image 0: WebP: image size 16x4 exceeds the limit of 8 pixels per side"), std::string::npos) << error;
}

// The images decode beside the rest of the load (ImageTable::decodeAll); the result is as if they
// had decoded first. A broken image is the load's error even when a later step fails meanwhile.
TEST(GltfTextureFormatsTest, ABrokenImageIsTheErrorBeforeOneFoundWhileItDecoded) {
    test::TempDir dir;
    Bytes webp = encodeWebp(16, 16, noise(16, 16, 3), true);
    webp.resize(webp.size() / 2);  // truncated bitstream
    GltfBuilder b = webpTriangle(webp);
    b.doc["nodes"][0]["mesh"] = 7;  // loadNodes fails on it
    const std::string error = loadError(b.writeGlb(dir.path()));
    EXPECT_NE(error.find("image 0: WebP: "), std::string::npos) << error;
    // The same file with a good image fails on the node.
    GltfBuilder good = webpTriangle(encodeWebp(16, 16, noise(16, 16, 3), true));
    good.doc["nodes"][0]["mesh"] = 7;
    const std::string nodeError = loadError(good.writeGlb(dir.path()));
    EXPECT_EQ(nodeError.find("image 0"), std::string::npos) << nodeError;
    EXPECT_NE(nodeError.find("node 0"), std::string::npos) << nodeError;
}

// ... and the decoders' notes come before the lines the materials recorded while they ran.
TEST(GltfTextureFormatsTest, DecodeNotesComeBeforeTheMaterialsNotes) {
    test::TempDir dir;
    GltfBuilder b = webpTriangle(encodeAnimatedWebp(8, 4, {noise(8, 4, 2), solid(8, 4, {10, 20, 30, 255})}));
    b.doc["materials"][0]["extensions"]["KHR_materials_dispersion"] = {{"dispersion", 1.0}};
    b.doc["extensionsUsed"].push_back("KHR_materials_dispersion");
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    const std::vector<std::string>& notes = scene.report.notes;
    const auto at = [&](const std::string& fragment) {
        for (size_t i = 0; i < notes.size(); ++i)
            if (notes[i].find(fragment) != std::string::npos) return i;
        return notes.size();
    };
    ASSERT_LT(at("animated WebP: drawn from its first frame"), notes.size()) << testing::PrintToString(notes);
    ASSERT_LT(at("dispersion 1 has no effect"), notes.size()) << testing::PrintToString(notes);
    EXPECT_LT(at("animated WebP: drawn from its first frame"), at("dispersion 1 has no effect")) << testing::PrintToString(notes);
    // As the decode before the rest of the load gives them (the floor bench's way).
    const scene::Scene first = loadGltf(b.writeGlb(dir.path()), {.decodeBesideTheLoad = false});
    EXPECT_EQ(first.report.notes, notes);
    EXPECT_EQ(first.report.warnings, scene.report.warnings);
    ASSERT_EQ(scene.images.size(), 1u);
    ASSERT_EQ(first.images.size(), 1u);
    EXPECT_EQ(scene.images[0].width, 8u);
    EXPECT_EQ(scene.images[0].rgba8, first.images[0].rgba8);
}

// How the decode's lines go before those recorded while it ran: each line once, where it was first
// recorded in that order, within the cap (64 lines, then "further warnings suppressed").
TEST(GltfLoadContext, LinesTakenOutAreRecordedAgainAfterThoseThatGoBeforeThem) {
    std::vector<std::string> warnings, notes;
    const gltf::LoadContext ctx{"f.gltf", &warnings, &notes};
    ctx.warn("a");
    ctx.note("n");
    ctx.warn("b");  // recorded while the decode ran...
    ctx.warn("d");
    const gltf::LoadContext::Lines later = ctx.takeSince(1, 1);
    EXPECT_EQ(warnings, std::vector<std::string>{"a"});
    EXPECT_EQ(notes, std::vector<std::string>{"n"});
    ctx.warn("d");  // ... the decode's own lines ...
    ctx.warn("c");
    ctx.restore(later);  // ... then the rest, without a second "d"
    EXPECT_EQ(warnings, (std::vector<std::string>{"a", "d", "c", "b"}));
    // At the cap: what no longer fits gives way to the suppression line, once.
    std::vector<std::string> full;
    const gltf::LoadContext capped{"f.gltf", &full, nullptr};
    for (int i = 0; i < 70; ++i) capped.warn("late " + std::to_string(i));
    const gltf::LoadContext::Lines taken = capped.takeSince(0, 0);
    ASSERT_EQ(taken.warnings.size(), 65u);
    EXPECT_EQ(taken.warnings.back(), "further warnings suppressed");
    capped.warn("decoded");
    capped.restore(taken);
    ASSERT_EQ(full.size(), 65u);
    EXPECT_EQ(full.front(), "decoded");
    EXPECT_EQ(full[63], "late 62");
    EXPECT_EQ(full.back(), "further warnings suppressed");
}

TEST(GltfTextureFormatsTest, AnUnusedBrokenWebpIsNeverRead) {
    test::TempDir dir;
    GltfBuilder b = texturedTriangle("", smallPng());
    const Bytes broken = {'R', 'I', 'F', 'F', 4, 0, 0, 0, 'W', 'E', 'B', 'P'};
    b.doc["images"].push_back({{"bufferView", b.addView(broken.data(), broken.size())}, {"mimeType", "image/webp"}});
    const scene::Scene scene = loadGltf(b.writeGlb(dir.path()));
    EXPECT_EQ(scene.images.size(), 1u);
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
}

}  // namespace
}  // namespace candela::assets::test
