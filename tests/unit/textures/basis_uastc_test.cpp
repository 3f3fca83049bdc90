// UASTC LDR 4×4 decoding (textures/basis_uastc.h) against reference decoders: every level of every
// fixture in tests/data/ktx2/uastc_*.ktx2 decodes bit for bit to both reference PNGs beside it — the
// linear decode (Basis Universal's own ASTC decoder on its lossless UASTC → ASTC transcode) and the
// sRGB decode (Arm's astcenc 4.2 on the same ASTC blocks); tools/ktx2-test-data/uastc.sh says how
// they were made. The fixtures hold blocks of all 19 modes (counted below). Synthetic blocks check
// the partition tables against the UASTC spec, solid-colour blocks, the reserved mode and pattern
// indices, and trit/quint packs past their range; random and bit-flipped blocks never crash.

#include "textures/basis_uastc.h"
#include "ktx2_fixtures.h"

#include "core/errors.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace candela::textures::basis_uastc_test {
namespace {

using test::levelSize;
using test::readKtx2Fixture;
using test::u32;
using test::u64;

// The parts of a 2D UASTC KTX2 file without supercompression that the decoder needs (KTX 2.0: the
// 80-byte header, the level index after it, the data format descriptor's transfer function).
struct UastcKtx2 {
    uint32_t width = 0;
    uint32_t height = 0;
    bool srgb = false;                         // the DFD's transfer function is sRGB (2)
    std::vector<std::vector<uint8_t>> levels;  // level 0 first
};

UastcKtx2 readUastcKtx2(const std::string& name) {
    const std::vector<uint8_t> bytes = readKtx2Fixture(name + ".ktx2");
    if (bytes.size() < 80 || bytes[1] != 'K' || bytes[5] != '2') throw std::runtime_error(name + ": not a KTX2 file");
    if (u32(bytes, 44) != 0) throw std::runtime_error(name + ": supercompressed");
    if (u32(bytes, 28) > 1 || u32(bytes, 32) > 0 || u32(bytes, 36) != 1) throw std::runtime_error(name + ": not 2D");
    UastcKtx2 file;
    file.width = u32(bytes, 20);
    file.height = u32(bytes, 24);
    const uint32_t dfd = u32(bytes, 48);
    if (dfd + 16 > bytes.size() || bytes[dfd + 12] != 166) throw std::runtime_error(name + ": not UASTC");
    file.srgb = bytes[dfd + 14] == 2;
    const uint32_t levelCount = std::max(1u, u32(bytes, 40));
    for (uint32_t level = 0; level < levelCount; ++level) {
        const uint64_t offset = u64(bytes, 80 + 24 * size_t(level)), length = u64(bytes, 88 + 24 * size_t(level));
        if (offset + length > bytes.size()) throw std::runtime_error(name + ": level past the end");
        file.levels.emplace_back(bytes.begin() + ptrdiff_t(offset), bytes.begin() + ptrdiff_t(offset + length));
    }
    return file;
}

struct Png {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

Png readPng(const std::string& name) {
    const std::vector<uint8_t> bytes = readKtx2Fixture(name);
    Png png;
    int channels = 0;
    std::unique_ptr<uint8_t, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &png.width, &png.height, &channels, 4), stbi_image_free);
    if (!pixels) throw std::runtime_error(name + ": " + stbi_failure_reason());
    png.rgba.assign(pixels.get(), pixels.get() + size_t(png.width) * size_t(png.height) * 4);
    return png;
}

// The mode of a block, from the UASTC spec's "Mode Index" table (its prefix codes), independently
// of the decoder's own table.
int blockMode(const uint8_t* block) {
    static constexpr struct {
        uint8_t bits, length, mode;
    } kCodes[] = {{0x00, 2, 11}, {0x02, 3, 10}, {0x06, 3, 12}, {0x01, 4, 0},  {0x09, 4, 18},
                  {0x03, 5, 3},  {0x07, 5, 7},  {0x0B, 5, 5},  {0x0D, 5, 14}, {0x0F, 5, 9},
                  {0x13, 5, 4},  {0x17, 5, 8},  {0x1B, 5, 6},  {0x1D, 5, 2},  {0x1F, 5, 13},
                  {0x15, 6, 16}, {0x25, 6, 17}, {0x35, 6, 1},  {0x05, 7, 15}, {0x45, 7, 19}};
    for (const auto& code : kCodes)
        if ((block[0] & ((1u << code.length) - 1)) == code.bits) return code.mode;
    return -1;
}

// fixture name (tests/data/ktx2/<name>.ktx2): the encoder settings are in the name (_l<N>:
// -uastc_level N); see tools/ktx2-test-data/uastc.sh.
const std::vector<std::string> kFixtures = {
    "uastc_gradient_l2", "uastc_mosaic_l3", "uastc_mosaic_alpha_l3", "uastc_gray_alpha_l2", "uastc_line_l4",
    "uastc_noise_l4",    "uastc_alpha_l1",  "uastc_odd_l2",          "uastc_mips_l0",
};

class UastcFixture : public testing::TestWithParam<std::string> {};

// Every level, both transfer functions, every texel and channel.
TEST_P(UastcFixture, EveryLevelDecodesToTheReferenceBitForBit) {
    const std::string& name = GetParam();
    const UastcKtx2 file = readUastcKtx2(name);
    ASSERT_FALSE(file.levels.empty());
    size_t texelsCompared = 0, differingBetweenModes = 0;
    for (uint32_t level = 0; level < file.levels.size(); ++level) {
        const uint32_t width = levelSize(file.width, level), height = levelSize(file.height, level);
        ASSERT_EQ(file.levels[level].size(), size_t((width + 3) / 4) * ((height + 3) / 4) * 16) << "level " << level;
        std::vector<uint8_t> decoded[2];
        for (const bool srgb : {false, true}) {
            SCOPED_TRACE(name + " level " + std::to_string(level) + (srgb ? " sRGB" : " linear"));
            const Png reference =
                readPng(name + "_level" + std::to_string(level) + (srgb ? "_srgb.png" : "_linear.png"));
            ASSERT_EQ(uint32_t(reference.width), width);
            ASSERT_EQ(uint32_t(reference.height), height);
            std::vector<uint8_t>& rgba = decoded[srgb];
            rgba.assign(size_t(width) * height * 4, 0xCD);
            decodeUastcImage(file.levels[level], width, height, srgb, rgba);
            size_t mismatches = 0;
            for (size_t i = 0; i < rgba.size(); ++i) {
                if (rgba[i] == reference.rgba[i]) continue;
                if (mismatches++ < 5)
                    ADD_FAILURE() << "texel (" << (i / 4) % width << ", " << (i / 4) / width << ") channel " << i % 4
                                  << ": decoded " << int(rgba[i]) << ", reference " << int(reference.rgba[i]);
            }
            EXPECT_EQ(mismatches, 0u);
            texelsCompared += size_t(width) * height;
        }
        for (size_t i = 0; i < decoded[0].size(); ++i) differingBetweenModes += decoded[0][i] != decoded[1][i];
    }
    // Both references are used: the sRGB decode differs from the linear one somewhere in every
    // fixture, so a decoder that ignored `srgb` would fail one of the comparisons.
    EXPECT_GT(differingBetweenModes, 0u) << name;
    std::cout << "[ UASTC    ] " << name << (file.srgb ? " (sRGB)" : " (linear)") << ": " << file.levels.size()
              << " level(s), " << texelsCompared << " texels compared\n";
}

INSTANTIATE_TEST_SUITE_P(Fixtures, UastcFixture, testing::ValuesIn(kFixtures),
                         [](const testing::TestParamInfo<std::string>& fixture) { return fixture.param; });

TEST(UastcDecode, FixturesCoverEveryMode) {
    std::array<size_t, 20> count{};
    size_t srgbFiles = 0;
    for (const std::string& name : kFixtures) {
        const UastcKtx2 file = readUastcKtx2(name);
        srgbFiles += file.srgb;
        for (const std::vector<uint8_t>& level : file.levels)
            for (size_t at = 0; at + 16 <= level.size(); at += 16) ++count[size_t(blockMode(level.data() + at))];
    }
    std::string summary;
    for (int mode = 0; mode < 19; ++mode) {
        EXPECT_GT(count[size_t(mode)], 0u) << "no fixture block of mode " << mode;
        summary += " " + std::to_string(mode) + ":" + std::to_string(count[size_t(mode)]);
    }
    EXPECT_EQ(count[19], 0u);
    EXPECT_GT(srgbFiles, 0u);                  // files of both transfer functions
    EXPECT_LT(srgbFiles, kFixtures.size());
    std::cout << "[ UASTC    ] blocks per mode:" << summary << "\n";
}

// ---- Synthetic blocks ---------------------------------------------------------------------------

// Writes fields from bit 0 (byte 0's least significant bit) up, as UASTC blocks are laid out.
class BlockWriter {
public:
    BlockWriter& put(uint32_t value, uint32_t bitCount) {
        for (uint32_t i = 0; i < bitCount; ++i, ++mPosition)
            if ((value >> i) & 1) mBlock[mPosition / 8] |= uint8_t(1u << (mPosition % 8));
        return *this;
    }
    BlockWriter& skip(uint32_t bitCount) {
        mPosition += bitCount;
        return *this;
    }
    const std::array<uint8_t, 16>& block() const { return mBlock; }

private:
    std::array<uint8_t, 16> mBlock{};
    uint32_t mPosition = 0;
};

std::array<uint8_t, 64> decode(const std::array<uint8_t, 16>& block, bool srgb, bool* ok = nullptr) {
    std::array<uint8_t, 64> texels{};
    const bool valid = decodeUastcBlock(block.data(), srgb, texels.data());
    if (ok) *ok = valid;
    else EXPECT_TRUE(valid);
    return texels;
}

TEST(UastcDecode, SolidColourBlocksGiveTheirColourInBothModes) {
    // Mode 8: code 0x17 (5 bits), then R, G, B, A, then ETC1 hints (random here: they must not matter).
    BlockWriter writer;
    writer.put(0x17, 5).put(0x12, 8).put(0xC4, 8).put(0x00, 8).put(0x7F, 8).put(0x5A5A5A, 24);
    for (const bool srgb : {false, true}) {
        const std::array<uint8_t, 64> texels = decode(writer.block(), srgb);
        for (size_t i = 0; i < 16; ++i) {
            EXPECT_EQ(texels[4 * i + 0], 0x12);
            EXPECT_EQ(texels[4 * i + 1], 0xC4);
            EXPECT_EQ(texels[4 * i + 2], 0x00);
            EXPECT_EQ(texels[4 * i + 3], 0x7F);
        }
    }
}

// The UASTC spec's partition tables ("Partition table for 2-subset Mode Indices 2, 4, 9, and 16",
// "... for 2-subset Mode Index 7", "... for 3-subset Mode Index 3"): the subset of texels 0..15.
const char* const kTwoSubsetPatterns[30] = {
    "0011001100110011", "0001000100010001", "1000100010001000", "0001001100110111", "1111111011101100",
    "0011011101111111", "1110110010000000", "1111111011001000", "0000000000010011", "1100100000000000",
    "0000000101111111", "1111111111101000", "1110100000000000", "1111111100000000", "0000111111111111",
    "1111111111110000", "1000111011111111", "1111111101110001", "0111001100010000", "0011000100000000",
    "0000100011001110", "1111111101110011", "1000110011001110", "0011000100010000", "1111011101110011",
    "0110011001100110", "1111000000001111", "1010101010101010", "1111000011110000", "1001001101101100",
};
const char* const kMode7Patterns[19] = {
    "0000111100000000", "0010001000100010", "1100110010000000", "0000000100110011", "1111111100001111",
    "0100010001000100", "0001001111111111", "0111001100110011", "1100000000111100", "0111011100000000",
    "0000000011101110", "1100000000001100", "0111001100000000", "0000000111111111", "1111111111110110",
    "1100110011001000", "1111111110001000", "0011011011001000", "1111011100000000",
};
const char* const kThreeSubsetPatterns[11] = {
    "0000000011221122", "1111111100002222", "1111000000002222", "1111222200000000", "1120112011201120",
    "0112011201120112", "0211021102110211", "2000200021112111", "2012201220122012", "1111000022221111",
    "0022001100110022",
};

// A block of `mode` whose subsets have distinct flat colours (endpoint pairs of equal values) and
// whose weights are all 0, so each texel's red value names its subset.
struct PatternMode {
    int mode;
    uint32_t code, codeLength, patternBits, packBits[4], endpointBits, subsetValue[3];
};
constexpr PatternMode kMode2 = {2, 0x1D, 5, 5, {0, 0, 0, 0}, 4, {0, 15, 0}};   // 4-bit endpoints: 0, 255
constexpr PatternMode kMode7 = {7, 0x07, 5, 5, {7, 7, 7, 7}, 3, {0, 1, 0}};    // quint 0: bits 0 → 0, 1 → 255
constexpr PatternMode kMode3 = {3, 0x03, 5, 4, {8, 8, 8, 5}, 2, {0, 1, 2}};    // trit 0: bits 0, 1, 2 → 0, 255, 69

std::array<uint8_t, 16> patternBlock(const PatternMode& m, uint32_t pattern) {
    BlockWriter writer;
    writer.put(m.code, m.codeLength).skip(15).put(pattern, m.patternBits);  // 15 hint bits
    for (uint32_t bits : m.packBits) writer.put(0, bits);                    // trits / quints of 0
    const uint32_t subsets = m.mode == 3 ? 3 : 2;
    for (uint32_t s = 0; s < subsets; ++s)
        for (uint32_t v = 0; v < 6; ++v) writer.put(m.subsetValue[s], m.endpointBits);
    return writer.block();  // the weights are zero bits
}

void expectPatterns(const PatternMode& m, const char* const* patterns, uint32_t count) {
    const uint8_t redOfSubset[3] = {0, 255, 69};
    for (uint32_t p = 0; p < count; ++p) {
        const std::array<uint8_t, 64> texels = decode(patternBlock(m, p), false);
        std::string subsets;
        for (size_t i = 0; i < 16; ++i) {
            const uint8_t red = texels[4 * i];
            subsets += red == redOfSubset[0] ? '0' : red == redOfSubset[1] ? '1' : red == redOfSubset[2] ? '2' : '?';
        }
        EXPECT_EQ(subsets, patterns[p]) << "mode " << m.mode << " pattern " << p;
    }
    // Pattern indices past the table are invalid blocks.
    for (uint32_t p = count; p < (1u << m.patternBits); ++p) {
        bool ok = true;
        decode(patternBlock(m, p), false, &ok);
        EXPECT_FALSE(ok) << "mode " << m.mode << " pattern " << p;
    }
}

TEST(UastcDecode, PartitionPatternsMatchTheSpecTables) {
    expectPatterns(kMode2, kTwoSubsetPatterns, 30);
    expectPatterns(kMode7, kMode7Patterns, 19);
    expectPatterns(kMode3, kThreeSubsetPatterns, 11);
}

TEST(UastcDecode, ReservedModeIsInvalid) {
    std::mt19937 random(19);
    for (int i = 0; i < 1000; ++i) {
        std::array<uint8_t, 16> block;
        for (uint8_t& byte : block) byte = uint8_t(random());
        block[0] = uint8_t((block[0] & 0x80) | 0x45);  // mode 19's code, "reserved for future expansion"
        bool ok = true;
        decode(block, i % 2 == 1, &ok);
        EXPECT_FALSE(ok);
    }
}

// The spec asks decoders to take packs of 243..255 trits (125..127 quints) digit by digit
// ("resilient to ET bytes containing 243..255"): such a block decodes like the one whose pack is
// 243 (125) less.
TEST(UastcDecode, TritAndQuintPacksPastTheirRangeDecodeDigitByDigit) {
    std::mt19937 random(243);
    for (int i = 0; i < 200; ++i) {
        std::array<uint8_t, 16> base;
        for (uint8_t& byte : base) byte = uint8_t(random());
        // Mode 0 (code 0x1, 4 bits; 15 hint bits; ET[0] at bit 19) and mode 6 (code 0x1B, 5 bits;
        // 15 hint bits; CSEL; EQ[0] at bit 22).
        for (const auto& [code, codeLength, packAt, packBits, over] :
             {std::array<uint32_t, 5>{0x1, 4, 19, 8, 243}, std::array<uint32_t, 5>{0x1B, 5, 22, 7, 125}}) {
            std::array<uint8_t, 16> low = base, high = base;
            const uint32_t pack = uint32_t(random()) % ((1u << packBits) - over);
            for (std::array<uint8_t, 16>* block : {&low, &high}) {
                const uint32_t value = block == &low ? pack : pack + over;
                (*block)[0] = uint8_t(((*block)[0] & ~((1u << codeLength) - 1)) | code);
                for (uint32_t b = 0; b < packBits; ++b) {
                    const uint32_t at = packAt + b;
                    uint8_t& byte = (*block)[at / 8];
                    byte = uint8_t((byte & ~(1u << (at % 8))) | (((value >> b) & 1) << (at % 8)));
                }
            }
            EXPECT_EQ(decode(low, false), decode(high, false)) << "mode code " << code << " pack " << pack;
        }
    }
}

// ---- Robustness ---------------------------------------------------------------------------------

// Random blocks: invalid exactly as often as the spec's invalid encodings occur — mode 19 (1/128),
// pattern indices 30, 31 in modes 2, 4, 9 (1/32 each) and 16 (1/64), 11..15 in mode 3 (1/32),
// 19..31 in mode 7 (1/32) — and the decoder never reads or writes out of bounds (the sanitizer
// builds check that).
TEST(UastcDecode, RandomBlocksNeverCrashAndFailOnlyWhereTheSpecSays) {
    constexpr int kBlocks = 300000;
    std::mt19937_64 random(0xA57C);
    std::array<uint8_t, 16> block;
    std::array<uint8_t, 64 + 8> texels;
    texels.fill(0xEE);
    int invalid = 0;
    for (int i = 0; i < kBlocks; ++i) {
        const uint64_t a = random(), b = random();
        std::memcpy(block.data(), &a, 8);
        std::memcpy(block.data() + 8, &b, 8);
        invalid += !decodeUastcBlock(block.data(), (a >> 63) != 0, texels.data());
    }
    for (size_t i = 64; i < texels.size(); ++i) EXPECT_EQ(texels[i], 0xEE) << "wrote past texel 15";
    const double expected = kBlocks * (1.0 / 128 + (3.0 / 32 + 1.0 / 64) * 2 / 32 + 5.0 / 32 / 16 + 13.0 / 32 / 32);
    EXPECT_NEAR(invalid, expected, expected * 0.05);
}

// Every single-bit flip of every fixture block: still one of the two outcomes, never a crash.
TEST(UastcDecode, BitFlippedFixtureBlocksNeverCrash) {
    size_t tried = 0, valid = 0;
    for (const std::string& name : kFixtures) {
        for (const std::vector<uint8_t>& blocks : readUastcKtx2(name).levels) {
            for (size_t at = 0; at + 16 <= blocks.size(); at += 16) {
                for (uint32_t bit = 0; bit < 128; ++bit) {
                    std::array<uint8_t, 16> block;
                    std::memcpy(block.data(), blocks.data() + at, 16);
                    block[bit / 8] ^= uint8_t(1u << (bit % 8));
                    std::array<uint8_t, 64> texels;
                    valid += decodeUastcBlock(block.data(), bit % 2 == 1, texels.data());
                    ++tried;
                }
            }
        }
    }
    EXPECT_GT(tried, 100000u);
    EXPECT_GT(valid, tried / 2);  // most flips hit endpoints, weights or hints
    EXPECT_LT(valid, tried);      // some hit a mode code or a pattern index
}

TEST(UastcDecode, ImageThrowsUserErrorNamingTheInvalidBlock) {
    const UastcKtx2 file = readUastcKtx2("uastc_odd_l2");  // 37 × 23: 10 × 6 blocks
    std::vector<uint8_t> blocks = file.levels[0];
    std::vector<uint8_t> rgba(size_t(file.width) * file.height * 4);
    EXPECT_NO_THROW(decodeUastcImage(blocks, file.width, file.height, true, rgba));
    blocks[23 * 16] = 0x45;  // block 23 is column 3 of row 2; mode 19
    try {
        decodeUastcImage(blocks, file.width, file.height, true, rgba);
        ADD_FAILURE() << "no error";
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "UASTC block 23 at (3, 2): invalid block");
    }
}

}  // namespace
}  // namespace candela::textures::basis_uastc_test
