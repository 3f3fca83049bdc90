// BasisLZ/ETC1S decoding (textures/basis_etc1s.h) against Basis Universal's own transcoder: every
// level of every fixture in tests/data/ktx2/etc1s_*.ktx2 decodes bit for bit to the reference PNG
// beside it (RGB and alpha; tools/ktx2-test-data/etc1s.sh says how those references were made), and
// corrupted or truncated global data and slices throw candela::UserError with one line, never crash.

#include "textures/basis_etc1s.h"
#include "ktx2_fixtures.h"

#include "core/errors.h"
#include "textures/basis_etc1s_huffman.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstring>
#include <algorithm>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace candela::textures {
namespace {

using test::levelSize;
using test::readKtx2Fixture;
using test::u32;
using test::u64;

// The parts of a 2D BasisLZ KTX2 file the decoder reads: the supercompression global data and each
// level's bytes (KTX 2.0: the 80-byte header, then the level index). Just enough for the fixtures,
// which have no layers, faces or depth, so there is one image per level.
struct Ktx2Parts {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> globalData;
    std::vector<std::vector<uint8_t>> levels;  // level 0 first
};

Ktx2Parts readKtx2(const std::string& name) {
    const std::vector<uint8_t> bytes = readKtx2Fixture(name + ".ktx2");
    if (bytes.size() < 80 || bytes[1] != 'K' || bytes[5] != '2') throw std::runtime_error(name + ": not a KTX2 file");
    if (u32(bytes, 44) != 1) throw std::runtime_error(name + ": not BasisLZ");
    if (u32(bytes, 28) > 1 || u32(bytes, 32) > 0 || u32(bytes, 36) != 1) throw std::runtime_error(name + ": not 2D");
    Ktx2Parts parts;
    parts.width = u32(bytes, 20);
    parts.height = u32(bytes, 24);
    const uint32_t levelCount = std::max(1u, u32(bytes, 40));
    const uint64_t sgdOffset = u64(bytes, 64), sgdLength = u64(bytes, 72);
    if (sgdOffset + sgdLength > bytes.size()) throw std::runtime_error(name + ": global data past the end");
    parts.globalData.assign(bytes.begin() + long(sgdOffset), bytes.begin() + long(sgdOffset + sgdLength));
    for (uint32_t level = 0; level < levelCount; ++level) {
        const uint64_t offset = u64(bytes, 80 + 24 * level), length = u64(bytes, 88 + 24 * level);
        if (offset + length > bytes.size()) throw std::runtime_error(name + ": level past the end");
        parts.levels.emplace_back(bytes.begin() + long(offset), bytes.begin() + long(offset + length));
    }
    return parts;
}

std::vector<uint8_t> decodeLevel(const BasisLzGlobal& global, const Ktx2Parts& parts, uint32_t level) {
    const uint32_t w = levelSize(parts.width, level), h = levelSize(parts.height, level);
    std::vector<uint8_t> rgba(size_t(w) * h * 4);
    global.decode(level, parts.levels[level], w, h, rgba);
    return rgba;
}

// Decodes every image of `parts`, as a loader would; the caller expects success or a UserError.
void decodeAll(const Ktx2Parts& parts) {
    const BasisLzGlobal global = BasisLzGlobal::parse(parts.globalData, uint32_t(parts.levels.size()));
    for (uint32_t level = 0; level < parts.levels.size(); ++level) decodeLevel(global, parts, level);
}

// Runs `f`, which must either return or throw a one-line UserError starting with `prefix`.
template <class F>
void expectCleanOutcome(F&& f, const std::string& prefix, const std::string& what) {
    try {
        f();
    } catch (const UserError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(prefix, 0), 0u) << what << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << what << ": " << message;
    } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": threw something other than UserError: " << e.what();
    }
}

std::string userErrorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const UserError& e) {
        return e.what();
    }
    return {};
}

// ---- the bit reader and Huffman tables (basis_etc1s_huffman.h)

// Packs values least significant bit first, as BasisLZ streams are written.
struct BitWriter {
    std::vector<uint8_t> bytes;
    uint32_t used = 0;
    void put(uint32_t value, uint32_t count) {
        for (uint32_t i = 0; i < count; ++i, ++used) {
            if (used % 8 == 0) bytes.push_back(0);
            bytes.back() = uint8_t(bytes.back() | ((value >> i) & 1) << (used % 8));
        }
    }
    // A Huffman code goes out most significant bit first (RFC 1951 section 3.1.1).
    void code(uint32_t code, uint32_t length) {
        for (uint32_t i = length; i-- > 0;) put(code >> i, 1);
    }
};

TEST(BasisLzHuffman, DecodesCanonicalCodes) {
    // Lengths 2, 1, 3, 3 give the canonical codes 10, 0, 110, 111 (RFC 1951 section 3.2.2).
    const std::vector<uint8_t> lengths = {2, 1, 3, 3};
    const etc1s::HuffmanTable table(lengths);
    BitWriter w;
    for (const uint32_t symbol : {1u, 0u, 3u, 2u, 1u, 3u}) {
        const uint32_t codes[] = {0b10, 0b0, 0b110, 0b111};
        w.code(codes[symbol], lengths[symbol]);
    }
    w.put(0x5A, 7);
    etc1s::BitReader reader(w.bytes);
    for (const uint32_t symbol : {1u, 0u, 3u, 2u, 1u, 3u}) EXPECT_EQ(reader.huffman(table), symbol);
    EXPECT_EQ(reader.bits(7), 0x5Au);
    EXPECT_THROW(reader.bits(8), etc1s::StreamError);  // 6 + 7 bits read of 16, 8 more is past the end
}

TEST(BasisLzHuffman, DecodesCodesLongerThanTheFastTable) {
    // Lengths 1, 2, ..., 15, 16, 16: a complete code whose last symbols need the slow path.
    std::vector<uint8_t> lengths;
    for (uint8_t length = 1; length <= 16; ++length) lengths.push_back(length);
    lengths.push_back(16);
    const etc1s::HuffmanTable table(lengths);
    BitWriter w;
    for (uint32_t symbol = 0; symbol < lengths.size(); ++symbol) {
        // Symbol k < 16 has k + 1 bits: k ones then a zero; the two 16-bit codes are 15 ones then 0 or 1.
        const uint32_t length = lengths[symbol];
        const uint32_t ones = symbol < 16 ? symbol : 15;
        const uint32_t code = ((1u << ones) - 1) << (length - ones) | (symbol == 16 ? 1 : 0);
        w.code(code, length);
    }
    etc1s::BitReader reader(w.bytes);
    for (uint32_t symbol = 0; symbol < lengths.size(); ++symbol) EXPECT_EQ(reader.huffman(table), symbol);
}

TEST(BasisLzHuffman, RefusesCodesThatAreNotCompletePrefixCodes) {
    EXPECT_THROW(etc1s::HuffmanTable(std::vector<uint8_t>{1, 2}), etc1s::StreamError);     // incomplete
    EXPECT_THROW(etc1s::HuffmanTable(std::vector<uint8_t>{1, 1, 1}), etc1s::StreamError);  // oversubscribed
    EXPECT_THROW(etc1s::HuffmanTable(std::vector<uint8_t>{17, 1}), etc1s::StreamError);    // longer than 16 bits
    EXPECT_NO_THROW(etc1s::HuffmanTable(std::vector<uint8_t>{1, 1}));
}

TEST(BasisLzHuffman, DegenerateTables) {
    // One used symbol: its code is all zeros, and any other bits are no code.
    const etc1s::HuffmanTable single(std::vector<uint8_t>{0, 0, 2});
    const std::vector<uint8_t> zeros = {0x00}, ones = {0xFF};
    etc1s::BitReader zeroReader(zeros);
    EXPECT_EQ(zeroReader.huffman(single), 2u);
    EXPECT_EQ(zeroReader.huffman(single), 2u);
    etc1s::BitReader oneReader(ones);
    EXPECT_THROW(oneReader.huffman(single), etc1s::StreamError);
    // No used symbol at all (a table stored for a stream that never reads it): reading throws.
    const etc1s::HuffmanTable none(std::vector<uint8_t>{0, 0, 0});
    EXPECT_EQ(none.symbolCount(), 3u);
    etc1s::BitReader noneReader(zeros);
    EXPECT_THROW(noneReader.huffman(none), etc1s::StreamError);
}

TEST(BasisLzHuffman, VariableLengthIntegers) {
    BitWriter w;
    w.put(0x0B, 5);  // vlc4: 11 in one chunk
    w.put(0x10 | 0x3, 5);  // vlc4: 3 + (2 << 4) = 35, the first chunk with its continuation bit
    w.put(0x2, 5);
    w.put(0x80 | 0x7F, 8);  // vlc7: 127 + (1 << 7) = 255
    w.put(0x01, 8);
    for (int i = 0; i < 8; ++i) w.put(0x1F, 5);  // vlc4 still continuing after 32 bits
    etc1s::BitReader reader(w.bytes);
    EXPECT_EQ(reader.vlc(4), 11u);
    EXPECT_EQ(reader.vlc(4), 35u);
    EXPECT_EQ(reader.vlc(7), 255u);
    EXPECT_THROW(reader.vlc(4), etc1s::StreamError);
}

// ---- bit-exact decodes against the reference transcoder

struct Fixture {
    const char* name;
    uint32_t levels;
    bool alpha;
};

// The encodings tools/ktx2-test-data/etc1s.sh makes: smooth and hard-edged colour at two qualities,
// fixed-seed noise (a raw selector codebook), alpha slices, partial edge blocks, grayscale endpoints,
// long runs (VLC-coded run lengths), large codebooks with Huffman codes over 10 bits, and mips.
const Fixture kFixtures[] = {
    {"etc1s_gradient_q128", 1, false}, {"etc1s_gradient_q255", 1, false}, {"etc1s_noise_linear", 1, false},
    {"etc1s_alpha", 1, true},          {"etc1s_odd_q64", 1, true},        {"etc1s_gray", 1, false},
    {"etc1s_flat", 1, false},          {"etc1s_plasma_q255", 1, false},   {"etc1s_mips", 7, false},
};

void PrintTo(const Fixture& fixture, std::ostream* os) { *os << fixture.name; }

class Etc1sReference : public testing::TestWithParam<Fixture> {};

TEST_P(Etc1sReference, EveryLevelMatchesTheReferenceTranscoderBitForBit) {
    const Fixture fixture = GetParam();
    const Ktx2Parts parts = readKtx2(fixture.name);
    ASSERT_EQ(parts.levels.size(), fixture.levels);
    const BasisLzGlobal global = BasisLzGlobal::parse(parts.globalData, fixture.levels);
    ASSERT_EQ(global.imageCount(), fixture.levels);
    for (uint32_t level = 0; level < fixture.levels; ++level) {
        SCOPED_TRACE("level " + std::to_string(level));
        EXPECT_EQ(global.imageDesc(level).alphaSliceByteLength != 0, fixture.alpha);
        const std::vector<uint8_t> decoded = decodeLevel(global, parts, level);

        const std::string refPath =
            (test::ktx2FixtureDir() / (std::string(fixture.name) + "_level" + std::to_string(level) + "_ref.png")).string();
        int w = 0, h = 0, channels = 0;
        const std::unique_ptr<stbi_uc, void (*)(void*)> ref(stbi_load(refPath.c_str(), &w, &h, &channels, 4),
                                                             stbi_image_free);
        ASSERT_TRUE(ref) << refPath;
        ASSERT_EQ(uint32_t(w), levelSize(parts.width, level));
        ASSERT_EQ(uint32_t(h), levelSize(parts.height, level));

        size_t mismatches = 0;
        uint8_t minAlpha = 255;
        for (size_t i = 0; i < decoded.size(); ++i) {
            if (i % 4 == 3) minAlpha = std::min(minAlpha, ref.get()[i]);
            if (decoded[i] == ref.get()[i]) continue;
            if (mismatches++ < 5)
                ADD_FAILURE() << "texel (" << (i / 4) % size_t(w) << ", " << (i / 4) / size_t(w) << ") channel "
                              << i % 4 << ": decoded " << int(decoded[i]) << ", reference " << int(ref.get()[i]);
        }
        EXPECT_EQ(mismatches, 0u) << "of " << decoded.size() << " bytes";
        // The alpha fixtures' references must hold alpha the comparison can get wrong.
        if (fixture.alpha && level == 0) {
            EXPECT_LT(minAlpha, 128);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, Etc1sReference, testing::ValuesIn(kFixtures),
                         [](const testing::TestParamInfo<Fixture>& param) { return std::string(param.param.name); });

// ---- the global data's layout and its checks

constexpr const char* kGlobalPrefix = "BasisLZ global data: ";

TEST(BasisLzGlobal, ReadsTheImageDescriptions) {
    const Ktx2Parts parts = readKtx2("etc1s_alpha");
    const BasisLzGlobal global = BasisLzGlobal::parse(parts.globalData, 1);
    const BasisLzImageDesc& desc = global.imageDesc(0);
    EXPECT_EQ(desc.imageFlags, 0u);
    EXPECT_EQ(desc.rgbSliceByteOffset, u32(parts.globalData, 24));
    EXPECT_EQ(desc.rgbSliceByteLength, u32(parts.globalData, 28));
    EXPECT_EQ(desc.alphaSliceByteOffset, u32(parts.globalData, 32));
    EXPECT_EQ(desc.alphaSliceByteLength, u32(parts.globalData, 36));
    EXPECT_EQ(uint64_t(desc.rgbSliceByteOffset) + desc.rgbSliceByteLength, desc.alphaSliceByteOffset);
    EXPECT_EQ(uint64_t(desc.alphaSliceByteOffset) + desc.alphaSliceByteLength, parts.levels[0].size());
}

TEST(BasisLzGlobal, RefusesInconsistentHeaders) {
    const Ktx2Parts parts = readKtx2("etc1s_mips");
    auto parseWith = [&](std::vector<uint8_t> data, uint32_t images) {
        return userErrorOf([&] { BasisLzGlobal::parse(data, images); });
    };
    const std::vector<uint8_t>& good = parts.globalData;
    EXPECT_EQ(parseWith(good, 7), "");
    EXPECT_NE(parseWith(good, 6).find("add up to"), std::string::npos);
    EXPECT_NE(parseWith(good, 8).find("add up to"), std::string::npos);
    EXPECT_NE(parseWith(good, 0).find("no images"), std::string::npos);
    EXPECT_NE(parseWith({good.begin(), good.begin() + 19}, 7).find("header"), std::string::npos);

    std::vector<uint8_t> bad = good;
    bad[0] = bad[1] = 0;  // endpointCount
    EXPECT_NE(parseWith(bad, 7).find("endpointCount is 0"), std::string::npos);
    bad = good;
    bad[2] = bad[3] = 0;  // selectorCount
    EXPECT_NE(parseWith(bad, 7).find("selectorCount is 0"), std::string::npos);
    bad = good;
    bad[16] = 4;  // extendedByteLength, with the 4 bytes it claims
    bad.insert(bad.end(), 4, 0);
    EXPECT_NE(parseWith(bad, 7).find("extendedByteLength"), std::string::npos);
    bad = good;
    std::memset(bad.data() + 20 + 20 * 3 + 8, 0, 4);  // image 3's rgbSliceByteLength
    EXPECT_NE(parseWith(bad, 7).find("image 3: rgbSliceByteLength is 0"), std::string::npos);
    bad = good;
    bad[20 + 20 * 2 + 12] = 1;  // image 2's alphaSliceByteOffset without an alpha slice
    EXPECT_NE(parseWith(bad, 7).find("image 2: an alpha slice offset"), std::string::npos);
    bad = good;
    bad[20 + 20 * 5 + 16] = 1;  // image 5 with an alpha slice the others lack
    EXPECT_NE(parseWith(bad, 7).find("image 5: alpha slice presence"), std::string::npos);

    // The selector codebook starts with two reserved bits that must be 0.
    const size_t selectorsAt = 20 + 20 * 7 + u32(good, 4);
    bad = good;
    bad[selectorsAt] |= 1;
    EXPECT_NE(parseWith(bad, 7).find("selector codebook: reserved bits"), std::string::npos);
    for (const std::string& message : {parseWith(bad, 7), parseWith(good, 6)}) {
        EXPECT_EQ(message.rfind(kGlobalPrefix, 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(BasisLzGlobal, EveryTruncationOfTheGlobalDataIsRefused) {
    const Ktx2Parts parts = readKtx2("etc1s_alpha");
    for (size_t length = 0; length < parts.globalData.size(); ++length) {
        const std::vector<uint8_t> cut(parts.globalData.begin(), parts.globalData.begin() + long(length));
        const std::string message = userErrorOf([&] { BasisLzGlobal::parse(cut, 1); });
        EXPECT_EQ(message.rfind(kGlobalPrefix, 0), 0u) << "length " << length << ": " << message;
    }
}

// The sections themselves cut short, with the header's lengths shrunk to match: each codebook and the
// tables end inside their bits, which the bit reader must notice.
TEST(BasisLzGlobal, ShortenedSectionsAreRefused) {
    const Ktx2Parts parts = readKtx2("etc1s_noise_linear");
    const std::vector<uint8_t>& good = parts.globalData;
    const size_t sectionsAt = 20 + 20;
    for (uint32_t section = 0; section < 3; ++section) {
        const uint32_t length = u32(good, 4 + 4 * section);
        size_t start = sectionsAt;
        for (uint32_t s = 0; s < section; ++s) start += u32(good, 4 + 4 * s);
        for (uint32_t cut = 1; cut <= std::min<uint32_t>(length, 8); ++cut) {
            std::vector<uint8_t> bad = good;
            bad.erase(bad.begin() + long(start + length - cut), bad.begin() + long(start + length));
            const uint32_t shorter = length - cut;
            std::memcpy(bad.data() + 4 + 4 * section, &shorter, 4);
            const std::string message = userErrorOf([&] { BasisLzGlobal::parse(bad, 1); });
            EXPECT_EQ(message.rfind(kGlobalPrefix, 0), 0u)
                << "section " << section << " cut by " << cut << ": " << message;
        }
    }
}

TEST(BasisLzGlobal, SingleByteCorruptionsOfTheGlobalDataNeverCrash) {
    for (const char* name : {"etc1s_alpha", "etc1s_noise_linear", "etc1s_gray", "etc1s_mips"}) {
        Ktx2Parts parts = readKtx2(name);
        const std::vector<uint8_t> good = parts.globalData;
        for (size_t at = 0; at < good.size(); ++at) {
            for (const uint8_t flip : {uint8_t(0x01), uint8_t(0x10), uint8_t(0x80), uint8_t(0xFF)}) {
                parts.globalData = good;
                parts.globalData[at] ^= flip;
                // A corruption may still parse (and then decode): the prefix is whichever part refused it.
                try {
                    const BasisLzGlobal global = BasisLzGlobal::parse(parts.globalData, uint32_t(parts.levels.size()));
                    expectCleanOutcome(
                        [&] {
                            for (uint32_t level = 0; level < parts.levels.size(); ++level)
                                decodeLevel(global, parts, level);
                        },
                        "BasisLZ image ", std::string(name) + " byte " + std::to_string(at));
                } catch (const UserError& e) {
                    EXPECT_EQ(std::string(e.what()).rfind(kGlobalPrefix, 0), 0u) << e.what();
                }
            }
        }
    }
}

// ---- slices

TEST(BasisLzDecode, RefusesPFrames) {
    Ktx2Parts parts = readKtx2("etc1s_gradient_q128");
    parts.globalData[20] |= 0x02;  // image 0's imageFlags: isPFrame
    const BasisLzGlobal global = BasisLzGlobal::parse(parts.globalData, 1);
    const std::string message = userErrorOf([&] { decodeLevel(global, parts, 0); });
    EXPECT_EQ(message.rfind("BasisLZ image 0: ", 0), 0u) << message;
    EXPECT_NE(message.find("P-frame"), std::string::npos) << message;
}

TEST(BasisLzDecode, EveryTruncationOfTheLevelIsRefused) {
    // The level holds the RGB slice then the alpha slice: any shorter level cuts the alpha slice.
    const Ktx2Parts parts = readKtx2("etc1s_alpha");
    const BasisLzGlobal global = BasisLzGlobal::parse(parts.globalData, 1);
    std::vector<uint8_t> rgba(size_t(parts.width) * parts.height * 4);
    for (size_t length = 0; length < parts.levels[0].size(); ++length) {
        const std::span<const uint8_t> cut(parts.levels[0].data(), length);
        const std::string message = userErrorOf([&] { global.decode(0, cut, parts.width, parts.height, rgba); });
        EXPECT_EQ(message.rfind("BasisLZ image 0: ", 0), 0u) << "length " << length << ": " << message;
        EXPECT_NE(message.find("outside its level"), std::string::npos) << message;
    }
}

// Slices shortened inside the level (the image description's lengths reduced): the bit stream ends
// before the last block, which must be an error rather than a read past the slice.
TEST(BasisLzDecode, ShortenedSlicesAreRefused) {
    for (const char* name : {"etc1s_alpha", "etc1s_noise_linear", "etc1s_flat"}) {
        const Ktx2Parts parts = readKtx2(name);
        for (const size_t field : {28u, 36u}) {  // rgbSliceByteLength, alphaSliceByteLength of image 0
            const uint32_t length = u32(parts.globalData, field);
            for (uint32_t shorter = 1; shorter < length; ++shorter) {  // (parse refuses an empty RGB slice)
                std::vector<uint8_t> globalData = parts.globalData;
                std::memcpy(globalData.data() + field, &shorter, 4);
                const BasisLzGlobal global = BasisLzGlobal::parse(globalData, 1);
                const std::string message = userErrorOf([&] { decodeLevel(global, parts, 0); });
                EXPECT_EQ(message.rfind("BasisLZ image 0: ", 0), 0u)
                    << name << " length " << shorter << ": " << message;
                EXPECT_NE(message.find("slice: "), std::string::npos) << message;
            }
        }
    }
}

TEST(BasisLzDecode, SingleByteCorruptionsOfTheSlicesNeverCrash) {
    for (const char* name : {"etc1s_alpha", "etc1s_odd_q64", "etc1s_flat", "etc1s_plasma_q255", "etc1s_mips"}) {
        Ktx2Parts parts = readKtx2(name);
        const BasisLzGlobal global = BasisLzGlobal::parse(parts.globalData, uint32_t(parts.levels.size()));
        for (uint32_t level = 0; level < parts.levels.size(); ++level) {
            const std::vector<uint8_t> good = parts.levels[level];
            for (size_t at = 0; at < good.size(); ++at) {
                for (const uint8_t flip : {uint8_t(0x01), uint8_t(0x08), uint8_t(0x80), uint8_t(0xFF)}) {
                    parts.levels[level] = good;
                    parts.levels[level][at] ^= flip;
                    expectCleanOutcome([&] { decodeLevel(global, parts, level); },
                                       "BasisLZ image " + std::to_string(level) + ": ",
                                       std::string(name) + " level " + std::to_string(level) + " byte " +
                                           std::to_string(at));
                }
            }
            parts.levels[level] = good;
        }
    }
}

// Random bytes for a whole level, and random bytes for a whole global data block of the right size.
TEST(BasisLzDecode, RandomBytesNeverCrash) {
    const Ktx2Parts parts = readKtx2("etc1s_gradient_q255");
    const BasisLzGlobal global = BasisLzGlobal::parse(parts.globalData, 1);
    uint32_t seed = 12345;
    auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
    for (int round = 0; round < 2000; ++round) {
        Ktx2Parts noisy = parts;
        for (uint8_t& byte : noisy.levels[0]) byte = uint8_t(next() >> 24);
        expectCleanOutcome([&] { decodeLevel(global, noisy, 0); }, "BasisLZ image 0: ",
                           "random level " + std::to_string(round));
        // Keep the header and the image description; scramble the codebooks and tables.
        for (size_t i = 40; i < noisy.globalData.size(); ++i) noisy.globalData[i] = uint8_t(next() >> 24);
        noisy.levels[0] = parts.levels[0];
        expectCleanOutcome([&] { decodeAll(noisy); }, "BasisLZ ", "random global data " + std::to_string(round));
    }
}

}  // namespace
}  // namespace candela::textures
