// Textures in other formats render as their originals do: a copy of a shared model whose PNG images
// are re-encoded as lossless WebP (EXT_texture_webp, required, no fallback) draws exactly the same
// frame, byte for byte, as the model itself — the same texels reach the same mips and samplers; and
// a KTX2 texture (KHR_texture_basisu, ETC1S and UASTC) draws the frame its reference decoder's PNG
// draws.
#include "gpu_test.h"
#include "test_paths.h"

#include "assets/gltf_loader.h"
#include "gltf_test_util.h"
#include "render/renderer.h"
#include "temp_dir.h"
#include "webp_test_writer.h"

#include <nlohmann/json.hpp>
#include <stb_image.h>

#include <filesystem>
#include <fstream>

namespace candela::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// The RGBA8 texels the loader makes of a PNG: 8-bit as stored, 16-bit rounded to nearest.
std::vector<uint8_t> pngTexels(const fs::path& path, uint32_t& width, uint32_t& height) {
    const std::string file = path.string();
    int w = 0, h = 0, channels = 0;
    std::vector<uint8_t> out;
    if (stbi_is_16_bit(file.c_str())) {
        stbi_us* pixels = stbi_load_16(file.c_str(), &w, &h, &channels, 4);
        if (!pixels) throw std::runtime_error("cannot read " + file);
        out.resize(size_t(w) * size_t(h) * 4);
        for (size_t i = 0; i < out.size(); ++i) out[i] = uint8_t((uint32_t(pixels[i]) * 255u + 32767u) / 65535u);
        stbi_image_free(pixels);
    } else {
        stbi_uc* pixels = stbi_load(file.c_str(), &w, &h, &channels, 4);
        if (!pixels) throw std::runtime_error("cannot read " + file);
        out.assign(pixels, pixels + size_t(w) * size_t(h) * 4);
        stbi_image_free(pixels);
    }
    width = uint32_t(w);
    height = uint32_t(h);
    return out;
}

// Copies the model's glTF folder into `dir` and rewrites its .gltf so that every texture takes a
// lossless WebP copy of its PNG through EXT_texture_webp (required; the core source removed).
// Returns the new .gltf's path.
fs::path webpCopy(const fs::path& gltf, const fs::path& dir) {
    fs::copy(gltf.parent_path(), dir, fs::copy_options::recursive);
    std::ifstream in(gltf);
    Json doc = Json::parse(in);
    size_t converted = 0;
    for (Json& image : doc["images"]) {
        const std::string uri = image["uri"];
        if (uri.size() < 4 || uri.substr(uri.size() - 4) != ".png") continue;
        uint32_t width = 0, height = 0;
        const std::vector<uint8_t> texels = pngTexels(gltf.parent_path() / uri, width, height);
        const std::vector<uint8_t> webp = encodeWebp(width, height, texels, /*lossless=*/true);
        const std::string webpUri = uri.substr(0, uri.size() - 4) + ".webp";
        std::ofstream(dir / webpUri, std::ios::binary).write(reinterpret_cast<const char*>(webp.data()), std::streamsize(webp.size()));
        image["uri"] = webpUri;
        image.erase("mimeType");
        ++converted;
    }
    EXPECT_GT(converted, 0u) << gltf;
    for (Json& texture : doc["textures"]) {
        texture["extensions"]["EXT_texture_webp"]["source"] = texture["source"];
        texture.erase("source");
    }
    for (const char* list : {"extensionsUsed", "extensionsRequired"}) doc[list].push_back("EXT_texture_webp");
    const fs::path out = dir / gltf.filename();
    std::ofstream(out) << doc.dump();
    return out;
}

std::vector<uint8_t> render(vk::Context& context, const scene::Scene& scene) {
    Renderer renderer(context);
    return renderer.capture({.width = 320, .height = 240, .scene = &scene}).rgba8;
}

class LosslessWebpCopy : public GpuTest, public testing::WithParamInterface<const char*> {};

TEST_P(LosslessWebpCopy, RendersExactlyLikeThePngOriginal) {
    const fs::path gltf = ::candela::test::sharedAssets() / "models" / GetParam() / "glTF" / (std::string(GetParam()) + ".gltf");
    if (!fs::exists(gltf)) GTEST_SKIP() << gltf << " not present";
    TempDir dir;
    const scene::Scene original = assets::loadGltf(gltf);
    const scene::Scene copy = assets::loadGltf(webpCopy(gltf, dir.path() / "model"));
    EXPECT_TRUE(copy.report.warnings.empty()) << copy.report.warnings.front();
    ASSERT_EQ(copy.images.size(), original.images.size());
    for (size_t i = 0; i < copy.images.size(); ++i) EXPECT_EQ(copy.images[i].rgba8, original.images[i].rgba8) << "image " << i;
    const std::vector<uint8_t> expected = render(context(), original);
    const std::vector<uint8_t> actual = render(context(), copy);
    ASSERT_EQ(actual.size(), expected.size());
    size_t differing = 0;
    for (size_t i = 0; i < actual.size(); ++i) differing += actual[i] != expected[i];
    EXPECT_EQ(differing, 0u) << "bytes differing between the WebP copy's frame and the original's";
}

// A triangle textured with `image` (a KHR_texture_basisu KTX2 file, or a PNG) sampled from level 0
// only (LINEAR filters, no mips), so that the frame shows the decoded texels and nothing generated.
std::vector<uint8_t> renderTexturedTriangle(vk::Context& context, const std::vector<uint8_t>& image, bool ktx2) {
    assets::test::GltfBuilder b = ktx2 ? assets::test::ktx2Triangle(image) : assets::test::texturedTriangle("", image);
    b.doc["samplers"] = Json::array({{{"magFilter", 9729}, {"minFilter", 9729}}});
    b.doc["textures"][0]["sampler"] = 0;
    TempDir dir;
    const scene::Scene scene = assets::loadGltf(b.writeGlb(dir.path()));
    EXPECT_TRUE(scene.report.warnings.empty()) << scene.report.warnings.front();
    Renderer renderer(context);
    RenderSettings settings{.width = 160, .height = 120, .scene = &scene};
    return renderer.capture(settings).rgba8;
}

TEST_F(GpuTest, Ktx2TexturesDrawTheReferenceDecodersTexels) {
    const fs::path data = ::candela::test::testData() / "ktx2";
    // ETC1S (BasisLZ) and UASTC, both sRGB as base colours are; their level 0 as the reference decoded it.
    for (const auto& [ktx2, png] : {std::pair{"etc1s_mips.ktx2", "etc1s_mips_level0_ref.png"},
                                    std::pair{"uastc_mips_l0.ktx2", "uastc_mips_l0_level0_srgb.png"}}) {
        SCOPED_TRACE(ktx2);
        const std::vector<uint8_t> fromKtx2 = renderTexturedTriangle(context(), assets::test::readBytes(data / ktx2), true);
        const std::vector<uint8_t> fromPng = renderTexturedTriangle(context(), assets::test::readBytes(data / png), false);
        ASSERT_EQ(fromKtx2.size(), fromPng.size());
        size_t differing = 0, covered = 0;
        for (size_t i = 0; i < fromKtx2.size(); i += 4) {
            differing += !std::equal(fromKtx2.begin() + ptrdiff_t(i), fromKtx2.begin() + ptrdiff_t(i + 4), fromPng.begin() + ptrdiff_t(i));
            covered += fromPng[i + 3] == 255;
        }
        EXPECT_EQ(differing, 0u) << "pixels differing between the KTX2 texture's frame and its reference decode's";
        EXPECT_GT(covered, fromPng.size() / 4 / 10) << "the triangle covers the frame";
    }
}

// A base colour texture; sampler settings and textures of odd sizes; normal maps (their own mip chain).
INSTANTIATE_TEST_SUITE_P(SharedModels, LosslessWebpCopy,
                         testing::Values("BoxTextured", "TextureSettingsTest", "NormalTangentMirrorTest"));

}  // namespace
}  // namespace candela::test
