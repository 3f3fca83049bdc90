// Malformed environment files: every row crafts its file in a temporary folder and expects
// loadEnvironment to throw one UserError line "PATH: problem" containing the row's fragment. The
// fuzz tests truncate valid files at every byte and flip random bytes: each must load or fail with
// such a line. Under the asan preset these also prove there is no out-of-bounds read, crash or hang.
#include "bad_input_expect.h"
#include "environment_test_util.h"

#include <functional>
#include <random>

namespace candela::assets::test::environment_bad_input_test {
namespace {

constexpr uint32_t kWidth = 40, kHeight = 5;

struct BadCase {
    std::string name;
    std::function<fs::path(const fs::path& dir)> make;  // writes the input, returns the file to load
    std::string fragment;                               // the error message must contain this
    EnvironmentLoadOptions options = {};
};

assets::test::Bytes validHdr(Scanlines scanlines = Scanlines::Rle) {
    HdrWriter writer;
    writer.scanlines = scanlines;
    return writer.write(testTexels(kWidth, kHeight), kWidth, kHeight);
}

// A valid header for a W×H image followed by `data`.
assets::test::Bytes hdrWithData(const std::string& resolution, const Bytes& data, const std::string& lines = "FORMAT=32-bit_rle_rgbe\n") {
    Bytes bytes = toBytes("#?RADIANCE\n" + lines + "\n" + resolution + "\n");
    bytes.insert(bytes.end(), data.begin(), data.end());
    return bytes;
}

size_t headerSize(const Bytes& hdr) {
    const std::string text(hdr.begin(), hdr.end());
    return text.find("+X") + text.substr(text.find("+X")).find('\n') + 1;
}

assets::test::Bytes validExr(Imf::Compression compression = Imf::ZIP_COMPRESSION) {
    std::vector<float> rgb;
    for (uint32_t i = 0; i < 16 * 8; ++i) rgb.insert(rgb.end(), {float(i), 0.5f * float(i % 7), 2.0f});
    return makeExr(16, 8, rgbChannels(rgb, ExrType::Half), {compression});
}

// Offset of the value of EXR header attribute `name` (after name, type and size).
size_t exrAttribute(const Bytes& exr, const std::string& name, const std::string& type) {
    const std::string key = name + '\0' + type + '\0';
    const auto at = std::search(exr.begin(), exr.end(), key.begin(), key.end());
    EXPECT_NE(at, exr.end()) << name;
    return size_t(at - exr.begin()) + key.size() + 4;
}

void setI32(Bytes& bytes, size_t at, int32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + size_t(i)] = uint8_t(uint32_t(v) >> (8 * i));
}

// validExr() with one int32 of a window attribute (dataWindow or displayWindow: xMin, yMin, xMax,
// yMax at byte offsets 0, 4, 8, 12 of its value) set to `v`.
assets::test::Bytes exrWithWindowValue(const std::string& window, size_t offset, int32_t v) {
    Bytes b = validExr();
    setI32(b, exrAttribute(b, window, "box2i") + offset, v);
    return b;
}

std::function<fs::path(const fs::path&)> file(const std::string& name, std::function<Bytes()> bytes) {
    return [name, bytes](const fs::path& dir) {
        writeBytes(dir / name, bytes());
        return dir / name;
    };
}

assets::test::Bytes garbage(size_t size, uint32_t seed) {
    std::mt19937 rng(seed);
    Bytes bytes(size);
    for (uint8_t& b : bytes) b = uint8_t(rng());
    bytes[0] = 'x';  // no magic by accident
    return bytes;
}

std::vector<BadCase> badCases() {
    std::vector<BadCase> cases;
    auto add = [&](std::string name, std::function<fs::path(const fs::path&)> make, std::string fragment,
                   EnvironmentLoadOptions options = {}) { cases.push_back({std::move(name), std::move(make), std::move(fragment), options}); };
    auto hdr = [&](std::string name, std::function<Bytes()> bytes, std::string fragment, EnvironmentLoadOptions options = {}) {
        add(name, file("map.hdr", std::move(bytes)), std::move(fragment), options);
    };
    auto exr = [&](std::string name, std::function<Bytes()> bytes, std::string fragment) {
        add(name, file("map.exr", std::move(bytes)), std::move(fragment));
    };

    // Files.
    add("NonexistentFile", [](const fs::path& dir) { return dir / "nothing.hdr"; }, "cannot open: No such file");
    add("Directory", [](const fs::path& dir) { fs::create_directories(dir / "d.hdr"); return dir / "d.hdr"; }, "is a directory");
    hdr("EmptyFile", [] { return Bytes{}; }, "empty file");
    add("UnknownFormat", file("map.png", [] { return garbage(100, 1); }), "unknown environment format");
    hdr("GarbageHdr", [] { return garbage(5000, 2); }, "not a Radiance HDR file");
    exr("GarbageExr", [] { return garbage(5000, 3); }, "not an OpenEXR file (bad magic number)");

    // Radiance header.
    hdr("WrongMagic", [] { Bytes b = validHdr(); b[1] = '!'; return b; }, "not a Radiance HDR file");
    hdr("MagicOnly", [] { return toBytes("#?"); }, "truncated header (no end of the first line)");
    hdr("NoBlankLine", [] { return toBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n"); }, "truncated header (no blank line ending it)");
    hdr("NoFormat", [] { return hdrWithData("-Y 5 +X 40", validHdr(), "GAMMA=1\n"); }, "no FORMAT= line in the header");
    hdr("Xyze", [] { return hdrWithData("-Y 5 +X 40", {}, "FORMAT=32-bit_rle_xyze\n"); }, "FORMAT=32-bit_rle_xyze (CIE XYZ) is not supported");
    hdr("OtherFormat", [] { return hdrWithData("-Y 5 +X 40", {}, "FORMAT=bogus\x01\n"); }, "unsupported FORMAT='bogus?'");
    hdr("HeaderLineTooLong", [] { return toBytes("#?RADIANCE\n" + std::string(70000, 'a') + "\n\n"); }, "header line longer than 65536 bytes");
    hdr("HeaderTooLong", [] {
            std::string lines;
            for (int i = 0; i < 7000; ++i) lines += "# comment\n";
            return toBytes("#?RADIANCE\n" + lines);
        }, "header longer than 65536 bytes");
    hdr("NoResolution", [] { return toBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n"); }, "truncated: no resolution line");
    hdr("ResolutionNotANumber", [] { return hdrWithData("-Y five +X 40", {}); }, "bad resolution line '-Y five +X 40'");
    hdr("ResolutionNegative", [] { return hdrWithData("-Y -5 +X 40", {}); }, "bad resolution line");
    hdr("ResolutionSameAxis", [] { return hdrWithData("-Y 5 +Y 40", {}); }, "bad resolution line");
    hdr("ResolutionExtraWord", [] { return hdrWithData("-Y 5 +X 40 +Z 1", {}); }, "bad resolution line");
    hdr("ResolutionHugeNumber", [] { return hdrWithData("-Y 99999999999999999999 +X 40", {}); }, "bad resolution line");
    hdr("ResolutionTooLong", [] { return hdrWithData(std::string(300, ' '), {}); }, "no end of line within 256 bytes");
    hdr("Transposed", [] { return hdrWithData("+X 40 -Y 5", validHdr()); }, "transposed");
    hdr("ZeroWidth", [] { return hdrWithData("-Y 5 +X 0", {}); }, "zero image size 0x5");
    hdr("ZeroHeight", [] { return hdrWithData("-Y 0 +X 40", {}); }, "zero image size 40x0");
    hdr("AbsurdSize", [] { return hdrWithData("-Y 100000 +X 200000", {}); }, "image size 200000x100000 exceeds the limit 16384x8192");
    hdr("AbsurdSizeManyRows", [] { return hdrWithData("-Y 4000000000 +X 8", {}); }, "exceeds the limit");
    hdr("BeyondConfiguredLimit", [] { return validHdr(); }, "image size 40x5 exceeds the limit 32x8192", {.maxWidth = 32});

    // Scanlines.
    const size_t header = headerSize(validHdr());
    for (size_t cut : {header, header + 2, header + 4, header + 5, header + 60, validHdr().size() - 1})
        hdr("RleTruncatedAt" + std::to_string(cut), [cut] { Bytes b = validHdr(); b.resize(cut); return b; },
            "truncated: the file ends (" + std::to_string(cut) + " bytes) inside scanline");
    for (size_t cut : {header + 3, header + 160, validHdr(Scanlines::Flat).size() - 2})
        hdr("FlatTruncatedAt" + std::to_string(cut), [cut] { Bytes b = validHdr(Scanlines::Flat); b.resize(cut); return b; },
            "truncated: the file ends");
    hdr("RleRunOverflow", [] { return hdrWithData("-Y 1 +X 8", {2, 2, 0, 8, 128 + 9, 7}); }, "RLE run of 9 at x = 0 overflows scanline 0 (width 8)");
    hdr("RleRunOverflowLater", [] { return hdrWithData("-Y 1 +X 8", {2, 2, 0, 8, 128 + 5, 7, 128 + 4, 1}); }, "RLE run of 4 at x = 5 overflows scanline 0");
    hdr("RleLiteralOverflow", [] { return hdrWithData("-Y 1 +X 8", {2, 2, 0, 8, 9, 1, 2, 3, 4, 5, 6, 7, 8, 9}); }, "RLE literal of 9 at x = 0 overflows");
    hdr("RleZeroLength", [] { return hdrWithData("-Y 1 +X 8", {2, 2, 0, 8, 0, 0, 0}); }, "scanline 0: zero-length RLE literal");
    hdr("RleLengthMismatch", [] { return hdrWithData("-Y 1 +X 8", {2, 2, 0, 9, 128 + 8, 1}); }, "scanline 0: RLE length 9 does not match the width 8");
    hdr("RleLengthMismatchSecondRow", [] {
            Bytes data = {2, 2, 0, 8, 128 + 8, 1, 128 + 8, 1, 128 + 8, 1, 128 + 8, 128, 2, 2, 1, 0};
            return hdrWithData("-Y 2 +X 8", data);
        }, "scanline 1: RLE length 256 does not match the width 8");
    hdr("OldRleOverflow", [] { return hdrWithData("-Y 1 +X 8", {9, 9, 9, 130, 1, 1, 1, 8}); }, "old-style RLE repeat of 8 at x = 1 overflows scanline 0");
    hdr("OldRleShiftOverflow", [] { return hdrWithData("-Y 1 +X 8", {9, 9, 9, 130, 1, 1, 1, 1, 1, 1, 1, 1}); }, "old-style RLE repeat of 256 at x = 2");
    hdr("OldRleManyMarkers", [] {
            Bytes data = {9, 9, 9, 130};
            for (int i = 0; i < 6; ++i) data.insert(data.end(), {1, 1, 1, 0});
            data.insert(data.end(), {1, 1, 1, 1});
            return hdrWithData("-Y 1 +X 8", data);
        }, "old-style RLE repeat of 18446744073709551615");
    hdr("OldRleNoPrevious", [] { return hdrWithData("-Y 1 +X 4", {1, 1, 1, 2, 9, 9, 9, 130, 9, 9, 9, 130}); }, "old-style RLE repeat before the first texel");
    hdr("GarbageAfterHeader", [] { return hdrWithData("-Y 5 +X 40", garbage(300, 4)); }, "truncated: the file ends (");

    // OpenEXR.
    exr("ExrWrongMagic", [] { Bytes b = validExr(); b[3] = 2; return b; }, "not an OpenEXR file (bad magic number)");
    exr("ExrBadVersion", [] { Bytes b = validExr(); b[4] = 3; return b; }, "invalid EXR header: File is of an unsupported version: 3");
    exr("ExrTruncatedMagic", [] { Bytes b = validExr(); b.resize(6); return b; }, "truncated EXR (6 bytes)");
    exr("ExrTiledFlag", [] { Bytes b = validExr(); b[5] |= 0x2; return b; }, "invalid EXR header");
    exr("ExrDeepFlag", [] { Bytes b = validExr(); b[5] |= 0x8; return b; }, "invalid EXR header");
    exr("ExrMultipartFlag", [] { Bytes b = validExr(); b[5] |= 0x10; return b; }, "invalid EXR header");
    for (size_t cut : {size_t(8), size_t(20), size_t(100)})
        exr("ExrTruncatedHeaderAt" + std::to_string(cut), [cut] { Bytes b = validExr(); b.resize(cut); return b; }, "invalid EXR header");
    for (size_t back : {size_t(1), size_t(30)})
        exr("ExrTruncatedPixelsBy" + std::to_string(back), [back] { Bytes b = validExr(); b.resize(b.size() - back); return b; },
            "cannot decode EXR pixels");
    exr("ExrAbsurdSize", [] { return exrWithWindowValue("dataWindow", 8, 99999); }, "invalid EXR header: Invalid width (100000) too large (max 16384)");
    exr("ExrHugeWindow", [] {
            Bytes b = validExr();
            const size_t at = exrAttribute(b, "dataWindow", "box2i");
            setI32(b, at, INT32_MIN);
            setI32(b, at + 8, INT32_MAX);
            return b;
        }, "invalid EXR header: Invalid data window (-2147483648, 0 - 2147483647, 7)");
    exr("ExrInvertedWindow", [] { return exrWithWindowValue("dataWindow", 8, -3); }, "invalid EXR header: Invalid data window (0, 0 - -3, 7)");
    // Attribute sizes are checked against their type and the file before anything is allocated
    // from them (OpenEXRCore's strict header validation; fuzzing found what the lenient one lets by).
    exr("ExrAttributeBeyondTheFile", [] {
            Bytes b = validExr();
            const std::string attribute = std::string("foo") + '\0' + "bar" + '\0';
            Bytes inserted(attribute.begin(), attribute.end());
            inserted.insert(inserted.end(), {0x00, 0x00, 0x00, 0x70, 'x', 'y', 'z'});  // 0x70000000 bytes
            b.insert(b.begin() + 8, inserted.begin(), inserted.end());
            return b;
        }, "invalid EXR header: Attribute 'foo', type 'bar': Invalid size 1879048192");
    exr("ExrWindowOfTheWrongSize", [] {
            Bytes b = validExr();
            const size_t at = exrAttribute(b, "dataWindow", "box2i");
            setI32(b, at - 4, 35);
            b.insert(b.begin() + std::ptrdiff_t(at + 16), 19, 0);
            return b;
        }, "invalid EXR header: Attribute 'dataWindow': Invalid size 35");
    // The display window is the picture we allocate: held to the same limits.
    exr("ExrHugeDisplayWindow", [] { return exrWithWindowValue("displayWindow", 8, 99999); }, "image size 100000x8 exceeds the limit 16384x8192");
    exr("ExrInvertedDisplayWindow", [] { return exrWithWindowValue("displayWindow", 12, -3); }, "display window");
    exr("ExrNoRgb", [] { return test::makeExr(4, 2, {{"Z", test::ExrType::Float, std::vector<float>(8, 1.0f)}}); }, "no R, G, B (or Y) channels");
    exr("ExrUintRed", [] {
            std::vector<test::ExrChannel> channels = test::rgbChannels(std::vector<float>(24, 1.0f), test::ExrType::Float);
            channels[0].type = test::ExrType::Uint;
            return test::makeExr(4, 2, channels);
        }, "channel R is UINT; only HALF and FLOAT are supported");
    exr("ExrGarbagePixels", [] {
            Bytes b = validExr();
            for (size_t i = b.size() - 40; i < b.size(); ++i) b[i] = uint8_t(i * 37);
            return b;
        }, "cannot decode EXR pixels");
    return cases;
}

class EnvironmentBadInputRow : public testing::TestWithParam<BadCase> {};

TEST_P(EnvironmentBadInputRow, IsOneLineUserErrorNamingTheFile) {
    EnvTempDir dir;
    const BadCase& c = GetParam();
    const fs::path path = c.make(dir.path());
    const std::string message = environmentLoadError(path, c.options);
    RecordProperty("message", message);
    candela::test::expectOneLineErrorNamingFile(path, message, c.fragment);
}

INSTANTIATE_TEST_SUITE_P(EnvironmentBadInput, EnvironmentBadInputRow, testing::ValuesIn(badCases()),
                         [](const testing::TestParamInfo<BadCase>& row) { return row.param.name; });

// The unmodified inputs the table starts from do load, so each row fails for its own reason.
TEST(EnvironmentBadInputBaseline, UnmodifiedInputsLoad) {
    EnvTempDir dir;
    for (Scanlines s : {Scanlines::Rle, Scanlines::Flat, Scanlines::OldRle}) {
        writeBytes(dir / "ok.hdr", validHdr(s));
        EXPECT_EQ(environmentLoadError(dir / "ok.hdr"), "");
    }
    writeBytes(dir / "ok.exr", validExr());
    EXPECT_EQ(environmentLoadError(dir / "ok.exr"), "");
    writeBytes(dir / "one.hdr", hdrWithData("-Y 1 +X 8", {2, 2, 0, 8, 128 + 8, 1, 128 + 8, 1, 128 + 8, 1, 128 + 8, 128}));
    EXPECT_EQ(environmentLoadError(dir / "one.hdr"), "");
}

// Each valid file cut at every length from 0 to size − 1 fails with one line naming the file.
void expectEveryTruncationFails(const Bytes& valid, const std::string& name) {
    EnvTempDir dir;
    const fs::path path = dir / name;
    for (size_t cut = 0; cut < valid.size(); ++cut) {
        writeBytes(path, Bytes(valid.begin(), valid.begin() + std::ptrdiff_t(cut)));
        const std::string message = environmentLoadError(path);
        ASSERT_FALSE(message.empty()) << "loaded when cut to " << cut << " bytes";
        ASSERT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
        ASSERT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(EnvironmentFuzz, HdrTruncatedAtEveryOffset) {
    expectEveryTruncationFails(validHdr(Scanlines::Rle), "rle.hdr");
    expectEveryTruncationFails(validHdr(Scanlines::Flat), "flat.hdr");
    expectEveryTruncationFails(validHdr(Scanlines::OldRle), "old.hdr");
}

TEST(EnvironmentFuzz, ExrTruncatedAtEveryOffset) {
    for (Imf::Compression compression : candela::test::kExrCompressions)
        expectEveryTruncationFails(validExr(compression), "cut_" + candela::test::compressionName(compression) + ".exr");
}

TEST(EnvironmentFuzz, TiledExrTruncatedAtEveryOffset) {
    // One level: every tile is read. (With mipmaps, a cut that loses only smaller levels still
    // loads: only level 0 is read.)
    std::vector<float> rgb;
    for (uint32_t i = 0; i < 16 * 8; ++i) rgb.insert(rgb.end(), {float(i), 0.5f * float(i % 7), 2.0f});
    expectEveryTruncationFails(test::makeExr(16, 8, test::rgbChannels(rgb, test::ExrType::Float), {Imf::PIZ_COMPRESSION, true, 4}), "tiled.exr");
}

// Random byte changes (1–8 per file, seeded): each file loads or fails with one line.
void expectMutationsAreSafe(const Bytes& valid, const std::string& name, size_t skip, uint32_t seed) {
    EnvTempDir dir;
    const fs::path path = dir / name;
    std::mt19937 rng(seed);
    for (int round = 0; round < 400; ++round) {
        Bytes bytes = valid;
        const int changes = 1 + int(rng() % 8);
        for (int i = 0; i < changes; ++i) bytes[skip + rng() % (bytes.size() - skip)] = uint8_t(rng());
        writeBytes(path, bytes);
        const std::string message = environmentLoadError(path);
        if (message.empty()) continue;
        ASSERT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
        ASSERT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(EnvironmentFuzz, HdrRandomMutations) {
    expectMutationsAreSafe(validHdr(Scanlines::Rle), "m.hdr", 2, 11);
    expectMutationsAreSafe(validHdr(Scanlines::OldRle), "o.hdr", 2, 12);
}

TEST(EnvironmentFuzz, ExrRandomMutations) {
    expectMutationsAreSafe(validExr(Imf::ZIP_COMPRESSION), "z.exr", 8, 13);
    expectMutationsAreSafe(validExr(Imf::NO_COMPRESSION), "n.exr", 8, 14);
}

}  // namespace
}  // namespace candela::assets::test::environment_bad_input_test
