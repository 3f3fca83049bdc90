// The KTX2 container (textures/ktx2_file.h) end to end on the committed test files made by the
// reference encoder (tests/data/ktx2): every level of an ETC1S and a UASTC file decodes to the
// reference decoder's output, Zstandard supercompression decodes alike, the orientation and DFD
// are read, and every truncation or single-byte change of a file is refused with a UserError or
// decoded — never a crash (the sanitizer build runs this too). The payload decoders' own tests:
// basis_etc1s_test.cpp, basis_uastc_test.cpp.
#include "ktx2_test_writer.h"
#include "test_paths.h"

#include "core/errors.h"
#include "textures/ktx2_file.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace candela::textures {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;
using test::joinKtx2;
using test::ktx2KeyValues;
using test::splitKtx2;
using test::withZstandard;

constexpr uint32_t kMaxDimension = 16384;

Bytes fileBytes(const std::string& name) {
    std::ifstream in(::candela::test::testData() / "ktx2" / name, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A reference decode (RGBA8 PNG) of the reference encoder's tool.
Bytes reference(const std::string& name, uint32_t width, uint32_t height) {
    const std::string path = (::candela::test::testData() / "ktx2" / name).string();
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!pixels) throw std::runtime_error("cannot read " + path);
    Bytes out(pixels, pixels + size_t(w) * size_t(h) * 4);
    stbi_image_free(pixels);
    EXPECT_EQ(uint32_t(w), width) << name;
    EXPECT_EQ(uint32_t(h), height) << name;
    return out;
}

std::string errorOf(const Bytes& file) {
    try {
        (void)decodeKtx2(file, kMaxDimension);
    } catch (const UserError& e) {
        return e.what();
    }
    return {};
}

TEST(Ktx2FileTest, Etc1sHeaderAndDfdAreRead) {
    const Ktx2Info info = readKtx2Info(fileBytes("etc1s_mips.ktx2"), kMaxDimension);
    EXPECT_EQ(info.width, 64u);
    EXPECT_EQ(info.height, 64u);
    EXPECT_EQ(info.levelCount, 7u);
    EXPECT_EQ(info.payload, BasisPayload::Etc1s);
    EXPECT_EQ(info.supercompression, Supercompression::BasisLz);
    EXPECT_TRUE(info.srgb);
    EXPECT_FALSE(info.alpha);
    EXPECT_TRUE(readKtx2Info(fileBytes("etc1s_alpha.ktx2"), kMaxDimension).alpha);
    EXPECT_FALSE(readKtx2Info(fileBytes("etc1s_noise_linear.ktx2"), kMaxDimension).srgb);
}

TEST(Ktx2FileTest, EveryEtc1sLevelDecodesAsTheReference) {
    const DecodedTexture texture = decodeKtx2(fileBytes("etc1s_mips.ktx2"), kMaxDimension);
    ASSERT_EQ(texture.levels.size(), 7u);
    for (uint32_t level = 0; level < 7; ++level) {
        const TextureLevel& l = texture.levels[level];
        EXPECT_EQ(l.width, 64u >> level);
        EXPECT_EQ(l.height, 64u >> level);
        EXPECT_EQ(l.rgba8, reference("etc1s_mips_level" + std::to_string(level) + "_ref.png", l.width, l.height))
            << "level " << level;
    }
    EXPECT_TRUE(texture.report.warnings.empty());
    EXPECT_TRUE(texture.report.notes.empty());
}

TEST(Ktx2FileTest, EveryUastcLevelDecodesAsTheReferenceInTheFilesTransferFunction) {
    const Bytes file = fileBytes("uastc_mips_l0.ktx2");
    const Ktx2Info info = readKtx2Info(file, kMaxDimension);
    EXPECT_EQ(info.payload, BasisPayload::Uastc);
    EXPECT_EQ(info.supercompression, Supercompression::None);
    const DecodedTexture texture = decodeKtx2(file, kMaxDimension);
    ASSERT_EQ(texture.levels.size(), 7u);
    for (uint32_t level = 0; level < 7; ++level) {
        const TextureLevel& l = texture.levels[level];
        const std::string name = "uastc_mips_l0_level" + std::to_string(level) + (info.srgb ? "_srgb.png" : "_linear.png");
        EXPECT_EQ(l.rgba8, reference(name, l.width, l.height)) << name;
    }
}

TEST(Ktx2FileTest, ZstandardLevelsDecodeAsTheUncompressedOnes) {
    const Bytes plain = fileBytes("uastc_mips_l0.ktx2");
    const Bytes packed = withZstandard(plain);
    EXPECT_LT(packed.size(), plain.size());
    const Ktx2Info info = readKtx2Info(packed, kMaxDimension);
    EXPECT_EQ(info.supercompression, Supercompression::Zstandard);
    const DecodedTexture a = decodeKtx2(plain, kMaxDimension), b = decodeKtx2(packed, kMaxDimension);
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (size_t level = 0; level < a.levels.size(); ++level) EXPECT_EQ(a.levels[level].rgba8, b.levels[level].rgba8);
}

TEST(Ktx2FileTest, ZstandardLiesAreRefused) {
    const Bytes packed = withZstandard(fileBytes("uastc_mips_l0.ktx2"));
    test::Ktx2Parts parts = splitKtx2(packed);
    parts.uncompressed[0] += 16;  // the level index says one more block than the image has
    EXPECT_EQ(errorOf(joinKtx2(parts)), "KTX2: level 0 inflates to 4112 bytes, its UASTC blocks need 4096");

    parts = splitKtx2(packed);
    parts.levels[0].resize(parts.levels[0].size() - 8);  // a frame cut short
    EXPECT_NE(errorOf(joinKtx2(parts)).find("KTX2: level 0: Zstandard"), std::string::npos) << errorOf(joinKtx2(parts));

    parts = splitKtx2(packed);
    parts.levels[1] = {1, 2, 3, 4, 5, 6, 7, 8};  // not a frame at all
    EXPECT_EQ(errorOf(joinKtx2(parts)), "KTX2: level 1: not a Zstandard frame");
}

TEST(Ktx2FileTest, RowsStoredBottomFirstAreFlippedWithANote) {
    const Bytes file = fileBytes("uastc_mips_l0.ktx2");
    test::Ktx2Parts parts = splitKtx2(file);
    parts.kvd = ktx2KeyValues({{"KTXorientation", "ru"}, {"KTXwriter", "test"}});
    const DecodedTexture upright = decodeKtx2(file, kMaxDimension), flipped = decodeKtx2(joinKtx2(parts), kMaxDimension);
    ASSERT_EQ(flipped.report.notes.size(), 1u);
    EXPECT_NE(flipped.report.notes[0].find("KTXorientation 'ru'"), std::string::npos);
    const TextureLevel &a = upright.levels[0], &b = flipped.levels[0];
    const size_t row = size_t(a.width) * 4;
    for (uint32_t y = 0; y < a.height; ++y)
        ASSERT_TRUE(std::equal(a.rgba8.begin() + ptrdiff_t(y * row), a.rgba8.begin() + ptrdiff_t((y + 1) * row),
                               b.rgba8.begin() + ptrdiff_t((a.height - 1 - y) * row)))
            << "row " << y;
    EXPECT_EQ(readKtx2Info(joinKtx2(parts), kMaxDimension).writer, "test");

    parts.kvd = ktx2KeyValues({{"KTXswizzle", "rrr1"}});
    const DecodedTexture swizzled = decodeKtx2(joinKtx2(parts), kMaxDimension);
    ASSERT_EQ(swizzled.report.warnings.size(), 1u);
    EXPECT_NE(swizzled.report.warnings[0].find("KTXswizzle 'rrr1'"), std::string::npos);
}

TEST(Ktx2FileTest, BrokenKeyValueDataAndDfdAreRefused) {
    const Bytes file = fileBytes("uastc_mips_l0.ktx2");
    test::Ktx2Parts parts = splitKtx2(file);
    parts.kvd = {200, 0, 0, 0, 'K', 0};  // an entry longer than its section
    EXPECT_EQ(errorOf(joinKtx2(parts)), "KTX2: key/value entry of 200 bytes runs past its section");
    parts.kvd = {4, 0, 0, 0, 'a', 'b', 'c', 'd'};  // a key without its NUL
    EXPECT_EQ(errorOf(joinKtx2(parts)), "KTX2: key/value entry without a NUL-terminated key");

    parts = splitKtx2(file);
    parts.dfd[4 + 8] = 160;  // colour model ETC1 (not Basis Universal)
    EXPECT_EQ(errorOf(joinKtx2(parts)), "KTX2: colour model 160 is not Basis Universal's ETC1S (163) or UASTC (166)");
    parts = splitKtx2(file);
    parts.dfd[4 + 8 + 2] = 7;  // transfer function BT.1886
    EXPECT_EQ(errorOf(joinKtx2(parts)), "KTX2: transfer function 7 is neither linear (1) nor sRGB (2)");
    parts = splitKtx2(file);
    parts.dfd[0] = 1;  // the DFD's own size disagrees with the header's
    EXPECT_NE(errorOf(joinKtx2(parts)).find("KTX2: data format descriptor says"), std::string::npos);
}

TEST(Ktx2FileTest, ALevelShorterThanItsBlocksIsRefused) {
    test::Ktx2Parts parts = splitKtx2(fileBytes("uastc_mips_l0.ktx2"));
    parts.levels[2].resize(parts.levels[2].size() - 16);
    parts.uncompressed[2] -= 16;
    EXPECT_EQ(errorOf(joinKtx2(parts)), "KTX2: level 2 holds 240 bytes, its UASTC blocks need 256");
}

// Every prefix of a small file, and every byte of it changed, decodes or is refused — never more.
void expectEveryDamageHandled(const Bytes& file) {
    for (size_t keep = 0; keep < file.size(); ++keep) {
        const Bytes cut(file.begin(), file.begin() + ptrdiff_t(keep));
        try {
            (void)decodeKtx2(cut, kMaxDimension);
        } catch (const UserError&) {
        }
    }
    for (size_t at = 0; at < file.size(); ++at)
        for (uint8_t flip : {uint8_t(0x01), uint8_t(0x80), uint8_t(0xFF)}) {
            Bytes bad = file;
            bad[at] ^= flip;
            try {
                const DecodedTexture texture = decodeKtx2(bad, kMaxDimension);
                ASSERT_FALSE(texture.levels.empty());
                ASSERT_EQ(texture.levels[0].rgba8.size(), size_t(texture.levels[0].width) * texture.levels[0].height * 4);
            } catch (const UserError&) {
            }
        }
}

TEST(Ktx2FileTest, EveryTruncationAndByteChangeIsHandled) {
    expectEveryDamageHandled(fileBytes("etc1s_mips.ktx2"));
    expectEveryDamageHandled(fileBytes("etc1s_alpha.ktx2"));
    expectEveryDamageHandled(withZstandard(fileBytes("uastc_mips_l0.ktx2")));
}

}  // namespace
}  // namespace candela::textures
