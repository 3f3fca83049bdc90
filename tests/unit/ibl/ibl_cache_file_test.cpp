// The on-disk IBL cache (engine/ibl/ibl_cache_file.h): round trips, the documented byte layout
// (checked against an independent writer in this file), key checks, and bad files — hand-built
// with valid checksums, truncated at every byte, flipped at every byte — each of which must be a
// clean cache miss with one line naming the file. Under the asan preset these also prove there is
// no out-of-bounds read.
#include "bad_input_expect.h"

#include "core/errors.h"
#include "ibl/ibl_cache_file.h"

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>
#include <unistd.h>

namespace candela::ibl {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;
using candela::test::expectOneLineErrorNamingFile;

constexpr uint64_t kHash = 0x0123456789abcdefull;
const std::string kSettings = "cube=256 prefilter=64 irradiance=sh9 lut=32";

using candela::test::TempDir;

// The names of the files in `dir`, sorted.
std::vector<std::string> fileNames(const TempDir& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.path())) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

void writeBytes(const fs::path& path, const Bytes& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << path;
}

Bytes readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The checksum of a hand-built file: wordHash64 of its bytes in one call (the reader and writer
// hash field by field; WordHasher's test holds that any split gives this value).
uint64_t checksum(const Bytes& bytes) { return wordHash64(0, bytes.data(), bytes.size()); }

// Builds cache files field by field, as the header documents the layout.
struct Builder {
    Bytes bytes;
    Builder& raw(const std::string& s) {
        bytes.insert(bytes.end(), s.begin(), s.end());
        return *this;
    }
    Builder& u32(uint32_t v) {
        for (int i = 0; i < 4; ++i) bytes.push_back(uint8_t(v >> (8 * i)));
        return *this;
    }
    Builder& u64(uint64_t v) {
        for (int i = 0; i < 8; ++i) bytes.push_back(uint8_t(v >> (8 * i)));
        return *this;
    }
    Builder& header(uint64_t hash = kHash, const std::string& settings = kSettings, uint32_t version = kIblCacheVersion) {
        raw(std::string("CANDELA-IBL", 12)).u32(version).u64(hash).u32(uint32_t(settings.size())).raw(settings);
        return *this;
    }
    // One image's fields; `dataBytes` is declared, `dataSize` bytes of data actually follow.
    Builder& image(const std::string& name, uint32_t format, uint32_t texelBytes, uint32_t width, uint32_t height,
                   uint32_t layers, uint32_t mips, uint64_t dataBytes, size_t dataSize) {
        u32(uint32_t(name.size())).raw(name).u32(format).u32(texelBytes).u32(width).u32(height).u32(layers).u32(mips).u64(dataBytes);
        for (size_t i = 0; i < dataSize; ++i) bytes.push_back(uint8_t(i * 7 + 1));
        return *this;
    }
    Builder& validImage() { return image("lut", 83, 4, 3, 2, 1, 2, 28, 28); }  // mips 3×2 + 1×1 = 7 texels
    Bytes finish() {
        u64(checksum(bytes));
        return bytes;
    }
};

CachedImage makeImage(std::string name, uint32_t format, uint32_t texelBytes, uint32_t width, uint32_t height,
                      uint32_t layers, uint32_t mips, uint32_t seed) {
    CachedImage image{std::move(name), format, texelBytes, width, height, layers, mips, {}};
    std::mt19937 rng(seed);
    image.data.resize(image.expectedBytes());
    for (std::byte& b : image.data) b = std::byte(rng());
    return image;
}

// The renderer's three kinds of image, at odd sizes.
std::vector<CachedImage> sampleImages() {
    return {makeImage("specular", 97, 8, 5, 3, 2, 3, 1),        // RGBA16F 5×3, 2 layers, 3 mips
            makeImage("brdf_lut", 83, 4, 7, 7, 1, 1, 2),        // RG16F 7×7
            makeImage("irradiance_sh", 109, 16, 9, 1, 1, 1, 3)};  // 9 × vec4 float32
}

// A small valid file (one tiny image) for the truncation and flip fuzzing.
std::vector<CachedImage> tinyImages() { return {makeImage("sh", 109, 16, 2, 1, 1, 1, 4)}; }

const IblCacheKey kKey{kHash, kSettings};

void expectSameImages(const std::vector<CachedImage>& a, const std::vector<CachedImage>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        SCOPED_TRACE(a[i].name);
        EXPECT_EQ(a[i].name, b[i].name);
        EXPECT_EQ(a[i].format, b[i].format);
        EXPECT_EQ(a[i].texelBytes, b[i].texelBytes);
        EXPECT_EQ(a[i].width, b[i].width);
        EXPECT_EQ(a[i].height, b[i].height);
        EXPECT_EQ(a[i].layers, b[i].layers);
        EXPECT_EQ(a[i].mips, b[i].mips);
        EXPECT_TRUE(a[i].data == b[i].data);
    }
}

// readCacheFile's reason, expecting a miss ("" when the file was accepted: the caller's assertion fails).
std::string missReason(const fs::path& path, const IblCacheKey& key = kKey) {
    std::string reason;
    if (readCacheFile(path, key, &reason)) return {};
    return reason;
}

TEST(IblCacheFile, ExpectedBytesSumsTheMipChain) {
    // 5×3, 3×1... : mips 5×3 + 2×1 + 1×1 = 18 texels per layer.
    EXPECT_EQ(makeImage("a", 0, 8, 5, 3, 2, 3, 0).expectedBytes(), 18u * 2 * 8);
    EXPECT_EQ((CachedImage{"b", 0, 4, 1, 16, 1, 5, {}}).expectedBytes(), (16u + 8 + 4 + 2 + 1) * 4);
    EXPECT_EQ((CachedImage{"c", 0, 2, 256, 256, 6, 9, {}}).expectedBytes(), size_t(87381) * 6 * 2);
    EXPECT_EQ((CachedImage{"d", 0, 4, 7, 7, 0, 1, {}}).expectedBytes(), 0u);
    // Any dimensions: mip levels past the 32nd are 1×1 (no shift by ≥ 32), overflow saturates.
    EXPECT_EQ((CachedImage{"e", 0, 1, 1, 1, 1, 0xffffffffu, {}}).expectedBytes(), size_t(0xffffffffu));
    constexpr uint32_t kMax = std::numeric_limits<uint32_t>::max();
    EXPECT_EQ((CachedImage{"f", 0, 16, kMax, kMax, kMax, 40, {}}).expectedBytes(), std::numeric_limits<size_t>::max());
}

TEST(IblCacheFile, RoundTripIsByteExact) {
    TempDir dir;
    const fs::path path = cacheFilePath(dir.path(), kKey);
    const std::vector<CachedImage> images = sampleImages();
    ASSERT_EQ(images[0].data.size(), 288u);
    writeCacheFile(path, kKey, images);
    std::string reason;
    const auto loaded = readCacheFile(path, kKey, &reason);
    ASSERT_TRUE(loaded) << reason;
    expectSameImages(*loaded, images);
}

TEST(IblCacheFile, RoundTripOfNoImagesAndOfExtremeDimensions) {
    TempDir dir;
    writeCacheFile(dir / "empty.cibl", kKey, {});
    const auto empty = readCacheFile(dir / "empty.cibl", kKey, nullptr);
    ASSERT_TRUE(empty);
    EXPECT_TRUE(empty->empty());

    // All limits at once but small data: 1×16384 has 15 mips; 64 layers.
    const std::vector<CachedImage> images = {makeImage("tall", 1, 1, 1, 16384, 64, 15, 9)};
    writeCacheFile(dir / "tall.cibl", kKey, images);
    std::string reason;
    const auto loaded = readCacheFile(dir / "tall.cibl", kKey, &reason);
    ASSERT_TRUE(loaded) << reason;
    expectSameImages(*loaded, images);
}

TEST(IblCacheFile, LayoutMatchesTheHeader) {
    TempDir dir;
    const std::vector<CachedImage> images = sampleImages();
    writeCacheFile(dir / "a.cibl", kKey, images);
    Builder expected;
    expected.header().u32(3);
    for (const CachedImage& image : images) {
        expected.u32(uint32_t(image.name.size())).raw(image.name);
        for (uint32_t v : {image.format, image.texelBytes, image.width, image.height, image.layers, image.mips}) expected.u32(v);
        expected.u64(image.data.size());
        for (std::byte b : image.data) expected.bytes.push_back(uint8_t(b));
    }
    const Bytes written = readBytes(dir / "a.cibl");
    const Bytes built = expected.finish();
    ASSERT_EQ(written.size(), built.size());
    EXPECT_TRUE(written == built);
    // The first bytes spelled out: magic, version 2, the hash's low byte first.
    EXPECT_EQ(std::string(written.begin(), written.begin() + 12), std::string("CANDELA-IBL\0", 12));
    EXPECT_EQ(written[12], 2);
    EXPECT_EQ(written[13] | written[14] | written[15], 0);
    EXPECT_EQ(written[16], 0xef);
    EXPECT_EQ(written[23], 0x01);
}

TEST(IblCacheFilePath, NameIsHashDashSettingsHash) {
    // FNV-1a 64 reference values.
    EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
    EXPECT_EQ(cacheFilePath("cache", {kHash, "foobar"}).string(), (fs::path("cache") / "0123456789abcdef-85944171f73967e8.cibl").string());
    EXPECT_EQ(cacheFilePath("cache", {0x1f, ""}).filename().string(), "000000000000001f-cbf29ce484222325.cibl");
}

TEST(IblCacheFilePath, DifferentKeysGiveDifferentPaths) {
    auto name = [](const IblCacheKey& key) { return cacheFilePath("d", key).string(); };
    const std::string base = name(kKey);
    EXPECT_EQ(name(kKey), base);
    EXPECT_NE(name({kHash, kSettings + " "}), base);
    EXPECT_NE(name({kHash, "cube=128 prefilter=64 irradiance=sh9 lut=32"}), base);
    EXPECT_NE(name({kHash + 1, kSettings}), base);
}

TEST(IblCacheFile, MissingFileIsAMissNamingThePath) {
    TempDir dir;
    const fs::path path = dir / "none.cibl";
    std::string reason;
    EXPECT_FALSE(readCacheFile(path, kKey, &reason));
    expectOneLineErrorNamingFile(path, reason, "cannot open: No such file");
    EXPECT_FALSE(readCacheFile(path, kKey, nullptr));  // a null reason is allowed
    fs::create_directories(dir / "d.cibl");
    expectOneLineErrorNamingFile(dir / "d.cibl", missReason(dir / "d.cibl"), "is a directory");
    writeBytes(dir / "empty.cibl", {});
    expectOneLineErrorNamingFile(dir / "empty.cibl", missReason(dir / "empty.cibl"), "empty file");
}

TEST(IblCacheFile, AnotherKeyIsAMiss) {
    TempDir dir;
    const fs::path path = dir / "a.cibl";
    writeCacheFile(path, kKey, sampleImages());
    expectOneLineErrorNamingFile(path, missReason(path, {kHash ^ 1, kSettings}),
                                 "made for another environment (content hash 0123456789abcdef, expected 0123456789abcdee)");
    // Other settings of another length and of the same length (as a file-name collision would have).
    expectOneLineErrorNamingFile(path, missReason(path, {kHash, "cube=512"}),
                                 "made for other settings ('" + kSettings + "', expected 'cube=512')");
    std::string sameLength = kSettings;
    sameLength.back() = '3';
    expectOneLineErrorNamingFile(path, missReason(path, {kHash, sameLength}), "made for other settings");
    EXPECT_TRUE(readCacheFile(path, kKey, nullptr));
}

TEST(IblCacheFile, TrailingBytesAreAMiss) {
    TempDir dir;
    const fs::path path = dir / "a.cibl";
    writeCacheFile(path, kKey, tinyImages());
    Bytes bytes = readBytes(path);
    bytes.push_back(0);
    writeBytes(path, bytes);
    expectOneLineErrorNamingFile(path, missReason(path), "1 unexpected bytes after the checksum");
    bytes.insert(bytes.end(), 100, 'x');
    writeBytes(path, bytes);
    expectOneLineErrorNamingFile(path, missReason(path), "101 unexpected bytes after the checksum");
}

// Every prefix of a valid file is a miss with one line naming the file.
TEST(IblCacheFile, TruncationAtEveryByteIsAMiss) {
    TempDir dir;
    writeCacheFile(dir / "valid.cibl", kKey, tinyImages());
    const Bytes valid = readBytes(dir / "valid.cibl");
    ASSERT_GT(valid.size(), 100u);
    const fs::path path = dir / "cut.cibl";
    for (size_t cut = 0; cut < valid.size(); ++cut) {
        SCOPED_TRACE("cut at " + std::to_string(cut));
        writeBytes(path, Bytes(valid.begin(), valid.begin() + std::ptrdiff_t(cut)));
        expectOneLineErrorNamingFile(path, missReason(path), cut == 0 ? "empty file" : "truncated: ");
    }
}

// Any single changed byte is a miss: FNV-1a detects every single-byte change, and changes in
// length, dimension or key fields are rejected before the checksum is reached.
TEST(IblCacheFile, EverySingleByteFlipIsAMiss) {
    TempDir dir;
    writeCacheFile(dir / "valid.cibl", kKey, tinyImages());
    const Bytes valid = readBytes(dir / "valid.cibl");
    const fs::path path = dir / "flipped.cibl";
    for (size_t at = 0; at < valid.size(); ++at) {
        for (uint8_t mask : {0x01, 0x80, 0xff}) {
            SCOPED_TRACE("byte " + std::to_string(at) + " ^ " + std::to_string(mask));
            Bytes bytes = valid;
            bytes[at] ^= mask;
            writeBytes(path, bytes);
            expectOneLineErrorNamingFile(path, missReason(path), "");
        }
    }
}

struct BadFile {
    std::string name;
    std::function<Bytes()> bytes;
    std::string fragment;
};

// Hand-built files with valid checksums: only the validation can reject them.
std::vector<BadFile> badFiles() {
    auto oneImage = [](std::function<void(Builder&)> image) {
        return [image] {
            Builder b;
            b.header().u32(1);
            image(b);
            return b.finish();
        };
    };
    // An image with one field changed (format 83, 4-byte texels, 3×2, 1 layer, 2 mips, 28 bytes).
    auto dims = [&](uint32_t texelBytes, uint32_t width, uint32_t height, uint32_t layers, uint32_t mips) {
        return oneImage([=](Builder& b) { b.image("lut", 83, texelBytes, width, height, layers, mips, 28, 28); });
    };
    constexpr uint32_t kU32Max = std::numeric_limits<uint32_t>::max();
    return {
        {"Valid control row (accepted)", [] { return Builder().header().u32(1).validImage().finish(); }, ""},
        {"WrongMagic", [] { Bytes b = Builder().header().u32(0).finish(); b[7] = '_'; return b; }, "not an IBL cache file (bad magic)"},
        {"OtherMagic", [] { return Bytes(100, 'x'); }, "not an IBL cache file (bad magic)"},
        {"OtherVersion", [] { return Builder().header(kHash, kSettings, 1).u32(1).validImage().finish(); }, "cache format version 1, expected 2"},
        {"VersionZero", [] { return Builder().header(kHash, kSettings, 0).u32(0).finish(); }, "cache format version 0, expected 2"},
        {"HugeSettingsLength", [] { Builder b; b.raw(std::string("CANDELA-IBL", 12)).u32(kIblCacheVersion).u64(kHash).u32(kU32Max); return b.finish(); },
         "truncated: the settings text of 4294967295 bytes passes the end of the file"},
        {"TooManyImages", [] { return Builder().header().u32(17).finish(); }, "17 images, more than 16"},
        {"HugeImageCount", [] { return Builder().header().u32(kU32Max).finish(); }, "4294967295 images, more than 16"},
        {"EmptyName", oneImage([](Builder& b) { b.image("", 83, 4, 3, 2, 1, 2, 28, 28); }), "image 0: image name length 0 is not in 1..64"},
        {"LongName", oneImage([](Builder& b) { b.image(std::string(65, 'n'), 83, 4, 3, 2, 1, 2, 28, 28); }), "image name length 65 is not in 1..64"},
        {"HugeNameLength", oneImage([](Builder& b) { b.u32(kU32Max); }), "image name length 4294967295 is not in 1..64"},
        {"TexelBytesZero", dims(0, 3, 2, 1, 2), "image 'lut': texelBytes 0 is not in 1..16"},
        {"TexelBytes17", dims(17, 3, 2, 1, 2), "texelBytes 17 is not in 1..16"},
        {"WidthZero", dims(4, 0, 2, 1, 2), "width 0 is not in 1..16384"},
        {"WidthBillion", dims(4, 1000000000, 2, 1, 2), "width 1000000000 is not in 1..16384"},
        {"Height16385", dims(4, 3, 16385, 1, 2), "height 16385 is not in 1..16384"},
        {"HeightMax", dims(4, 3, kU32Max, 1, 2), "height 4294967295 is not in 1..16384"},
        {"LayersZero", dims(4, 3, 2, 0, 2), "layers 0 is not in 1..64"},
        {"Layers65", dims(4, 3, 2, 65, 2), "layers 65 is not in 1..64"},
        {"MipsZero", dims(4, 3, 2, 1, 0), "mips 0 is not in 1..16"},
        {"Mips17", dims(4, 16384, 16384, 1, 17), "mips 17 is not in 1..16"},
        {"MipsBeyondTheChain", dims(4, 3, 2, 1, 3), "mips 3 exceeds the 2 levels of a 3x2 image"},
        {"DataSizeDisagrees", oneImage([](Builder& b) { b.image("lut", 83, 4, 3, 2, 1, 2, 29, 29); }),
         "image 'lut': 29 data bytes, but 3x2, 1 layers, 2 mips of 4-byte texels make 28"},
        {"DataSizeHuge", oneImage([](Builder& b) { b.image("lut", 83, 4, 3, 2, 1, 2, ~uint64_t(0), 0); }),
         "18446744073709551615 data bytes, but"},
        // Legal dimensions, 1 GiB of texels declared, none present: rejected before allocating.
        {"DataBeyondTheFile", oneImage([](Builder& b) { b.image("big", 109, 16, 8192, 8192, 1, 1, uint64_t(1) << 30, 0); }),
         "truncated: image 'big' declares 1073741824 data bytes but only 0 remain before the checksum"},
        // 16384² × 16 bytes = 4 GiB: beyond the payload limit.
        {"PayloadOver2GiB", oneImage([](Builder& b) { b.image("big", 109, 16, 16384, 16384, 1, 1, uint64_t(4) << 30, 0); }),
         "the images' data adds up to more than 2147483648 bytes"},
        // Exactly 2 GiB is within the limit (but not in this file).
        {"Exactly2GiB", [] {
             Builder b;
             b.header().u32(2).image("a", 97, 8, 16384, 16384, 1, 1, uint64_t(2) << 30, 0).image("b", 97, 8, 1, 1, 1, 1, 8, 8);
             return b.finish();
         }, "truncated: image 'a' declares 2147483648 data bytes"},
        {"SecondImageTruncated", [] {
             Builder b;
             b.header().u32(2).validImage().image("b", 97, 8, 2, 2, 1, 1, 32, 31);
             return b.finish();
         }, "truncated: image 'b' declares 32 data bytes but only 31 remain before the checksum"},
        {"ControlCharactersInName", oneImage([](Builder& b) { b.image("a\nb", 83, 0, 3, 2, 1, 2, 28, 28); }), "image 'a?b': texelBytes 0"},
        {"ChecksumWrong", [] { Bytes b = Builder().header().u32(1).validImage().finish(); b.back() ^= 0x40; return b; },
         "checksum mismatch (stored "},
        {"ChecksumMissing", [] { return Builder().header().u32(1).validImage().bytes; },
         "truncated: image 'lut' declares 28 data bytes but only 20 remain before the checksum"},
        {"ChecksumCutNoImages", [] { Bytes b = Builder().header().u32(0).finish(); b.resize(b.size() - 3); return b; },
         "truncated: the file ends (" + std::to_string(Builder().header().u32(0).bytes.size() + 5) + " bytes) inside the checksum"},
    };
}

TEST(IblCacheFileBadInput, HandBuiltFilesWithValidChecksums) {
    TempDir dir;
    const fs::path path = dir / "bad.cibl";
    for (const BadFile& row : badFiles()) {
        SCOPED_TRACE(row.name);
        writeBytes(path, row.bytes());
        std::string reason;
        const auto loaded = readCacheFile(path, kKey, &reason);
        if (row.fragment.empty()) {
            ASSERT_TRUE(loaded) << reason;
            ASSERT_EQ(loaded->size(), 1u);
            EXPECT_EQ((*loaded)[0].data.size(), 28u);
            continue;
        }
        EXPECT_FALSE(loaded);
        expectOneLineErrorNamingFile(path, reason, row.fragment);
    }
}

TEST(IblCacheFileWrite, UncreatableDirectoryThrowsUserErrorNamingThePath) {
    TempDir dir;
    writeBytes(dir / "plain_file", {1, 2, 3});
    const fs::path path = dir / "plain_file" / "cache" / "a.cibl";
    try {
        writeCacheFile(path, kKey, sampleImages());
        FAIL() << "no error";
    } catch (const UserError& e) {
        expectOneLineErrorNamingFile(path, e.what(), "cannot create the directory");
    }
}

TEST(IblCacheFileWrite, CreatesTheDirectoryAndLeavesNoTemporary) {
    TempDir dir;
    const fs::path path = cacheFilePath(dir / "nested" / "cache", kKey);
    writeCacheFile(path, kKey, sampleImages());
    ASSERT_TRUE(readCacheFile(path, kKey, nullptr));
    // Overwriting replaces the file whole.
    const std::vector<CachedImage> other = tinyImages();
    writeCacheFile(path, kKey, other);
    const auto loaded = readCacheFile(path, kKey, nullptr);
    ASSERT_TRUE(loaded);
    expectSameImages(*loaded, other);
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(path.parent_path())) files.push_back(entry.path().filename().string());
    EXPECT_EQ(files, std::vector<std::string>{path.filename().string()});
}

TEST(IblCacheFileWrite, FailedRenameThrowsAndRemovesTheTemporary) {
    TempDir dir;
    const fs::path path = dir / "a.cibl";
    fs::create_directories(path / "occupied");  // a non-empty directory where the file should go
    try {
        writeCacheFile(path, kKey, sampleImages());
        FAIL() << "no error";
    } catch (const UserError& e) {
        expectOneLineErrorNamingFile(path, e.what(), "cannot rename the temporary file");
    }
    EXPECT_EQ(fileNames(dir), std::vector<std::string>{"a.cibl"});
}

TEST(IblCacheFileWrite, InvalidImagesAreRejectedAndNothingIsWritten) {
    TempDir dir;
    const fs::path path = dir / "a.cibl";
    auto expectInvalid = [&](std::vector<CachedImage> images, const std::string& fragment) {
        try {
            writeCacheFile(path, kKey, images);
            ADD_FAILURE() << "no error for " << fragment;
        } catch (const std::invalid_argument& e) {
            expectOneLineErrorNamingFile(path, e.what(), fragment);
        }
    };
    std::vector<CachedImage> images = sampleImages();
    images[1].data.pop_back();
    expectInvalid(images, "image 'brdf_lut': 195 data bytes, but 7x7, 1 layers, 1 mips of 4-byte texels make 196");
    images = sampleImages();
    images[0].mips = 4;
    expectInvalid(images, "mips 4 exceeds the 3 levels of a 5x3 image");
    images = sampleImages();
    images[2].name.clear();
    expectInvalid(images, "image name length 0 is not in 1..64");
    expectInvalid(std::vector<CachedImage>(17, tinyImages()[0]), "17 images, more than 16");
    EXPECT_TRUE(fileNames(dir).empty());
}

}  // namespace
}  // namespace candela::ibl
