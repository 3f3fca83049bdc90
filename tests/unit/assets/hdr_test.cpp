// Radiance .hdr round trips: files written here (flat, new-style RLE and old-style RLE scanlines,
// tolerant headers, flipped orientations) read back exactly. "Exactly" means every channel equals
// m · 2^(e − 136) of the RGBE bytes written (bit for bit); against the floats the RGBE bytes were
// made from, RGBE's shared 8-bit mantissa leaves each channel within max(r, g, b)/128.
#include "environment_test_util.h"

namespace candela::assets::test {
namespace {

constexpr uint32_t kWidth = 40, kHeight = 5;  // ≥ 8 wide so the RLE path is taken

// Loads `bytes` written to a file and checks every texel against `texels` bit for bit.
void expectExact(const Bytes& bytes, const std::vector<Rgbe>& texels, uint32_t width, uint32_t height,
                 const std::string& name = "map.hdr") {
    EnvTempDir dir;
    writeBytes(dir / name, bytes);
    const Environment env = loadEnvironment(dir / name);
    ASSERT_EQ(env.width, width);
    ASSERT_EQ(env.height, height);
    ASSERT_EQ(env.rgb.size(), size_t(width) * height * 3);
    EXPECT_EQ(env.replacedTexels, 0u);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const std::array<float, 3> want = decodeRgbe(texels[size_t(y) * width + x]);
            for (int c = 0; c < 3; ++c) ASSERT_EQ(env.texel(x, y)[c], want[size_t(c)]) << "texel " << x << "," << y << " channel " << c;
        }
}

TEST(HdrRoundTrip, RleScanlines) {
    const std::vector<Rgbe> texels = testTexels(kWidth, kHeight);
    const Bytes bytes = HdrWriter{}.write(texels, kWidth, kHeight);
    expectExact(bytes, texels, kWidth, kHeight);
}

TEST(HdrRoundTrip, FlatScanlines) {
    const std::vector<Rgbe> texels = testTexels(kWidth, kHeight);
    HdrWriter writer;
    writer.scanlines = Scanlines::Flat;
    expectExact(writer.write(texels, kWidth, kHeight), texels, kWidth, kHeight);
}

TEST(HdrRoundTrip, OldStyleRleWithMultiByteRepeats) {
    // 300 equal texels in a row need two repeat markers (299 = 43 + 1 · 256).
    const uint32_t width = 300, height = 3;
    std::vector<Rgbe> texels(size_t(width) * height, encodeRgbe(1.5f, 1.0f, 0.5f));
    texels[size_t(width)] = encodeRgbe(0.25f, 0.5f, 0.75f);      // row 1 starts differently
    texels[size_t(2) * width + 7] = encodeRgbe(9.0f, 8.0f, 7.0f); // row 2 has a break
    HdrWriter writer;
    writer.scanlines = Scanlines::OldRle;
    const Bytes bytes = writer.write(texels, width, height);
    EXPECT_LT(bytes.size(), 100u) << "the old-style runs should compress";
    expectExact(bytes, texels, width, height);
}

TEST(HdrRoundTrip, OldStyleRepeatContinuesFromThePreviousScanline) {
    // Radiance's reader lets a scanline start with a repeat of the previous scanline's last texel.
    const uint32_t width = 4, height = 2;
    const Rgbe a = encodeRgbe(1.0f, 2.0f, 3.0f), b = encodeRgbe(4.0f, 5.0f, 6.0f);
    Bytes bytes = toBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n");
    for (int i = 0; i < 3; ++i) bytes.insert(bytes.end(), a.begin(), a.end());
    bytes.insert(bytes.end(), b.begin(), b.end());
    bytes.insert(bytes.end(), {1, 1, 1, 4});  // row 1: four copies of b
    expectExact(bytes, {a, a, a, b, b, b, b, b}, width, height);
}

TEST(HdrRoundTrip, MixedRleAndFlatScanlines) {
    const std::vector<Rgbe> texels = testTexels(kWidth, kHeight);
    Bytes bytes = toBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 5 +X 40\n");
    for (uint32_t y = 0; y < kHeight; ++y) {
        const std::vector<Rgbe> line(texels.begin() + y * kWidth, texels.begin() + (y + 1) * kWidth);
        if (y % 2) HdrWriter::appendRle(bytes, line);
        else
            for (const Rgbe& p : line) bytes.insert(bytes.end(), p.begin(), p.end());
    }
    expectExact(bytes, texels, kWidth, kHeight);
}

TEST(HdrRoundTrip, NarrowAndWideImagesAreFlat) {
    // Below 8 texels Radiance never uses RLE; 1×1 and 7×3 must read.
    for (const auto& [w, h] : {std::pair{1u, 1u}, std::pair{7u, 3u}, std::pair{2u, 1u}}) {
        const std::vector<Rgbe> texels = testTexels(w, h);
        HdrWriter writer;
        writer.scanlines = Scanlines::Flat;
        expectExact(writer.write(texels, w, h), texels, w, h);
    }
}

TEST(HdrRoundTrip, TolerantHeaders) {
    const std::vector<Rgbe> texels = testTexels(kWidth, kHeight);
    const std::vector<std::pair<std::string, std::string>> headers = {
        {"#?RADIANCE\n", "FORMAT=32-bit_rle_rgbe\n"},
        {"#?RGBE\n", "FORMAT=32-bit_rle_rgbe\n"},
        {"#?RADIANCE\n", "#?RADIANCE\nGAMMA=1\nPRIMARIES=0 0 0 0 0 0 0 0\nFORMAT=32-bit_rle_rgbe\n"},  // Photoshop
        {"#?RADIANCE\n", "# Made with Adobe Photoshop\nGAMMA=1\nFORMAT=32-bit_rle_rgbe\n"},
        {"#?RADIANCE\n", "pfilt -x 40 -y 5\nSOFTWARE=x\nVIEW= -vta -vh 360\nEXPOSURE=1.0\nFORMAT=32-bit_rle_rgbe  \n"},
        {"#?RADIANCE\r\n", "FORMAT=32-bit_rle_rgbe\r\n# odd=line=\r\n\r"},  // CRLF, blank line too
        {"#?\n", "FORMAT=32-bit_rle_rgbe\nPRIMARIES=0.640 0.330 0.300 0.600 0.150 0.060 0.3127 0.3290\n"},
    };
    for (const auto& [magic, lines] : headers) {
        SCOPED_TRACE(magic + lines);
        HdrWriter writer;
        writer.magic = magic;
        writer.headerLines = lines;
        if (magic.ends_with("\r\n")) writer.resolution = "-Y 5 +X 40\r";
        expectExact(writer.write(texels, kWidth, kHeight), texels, kWidth, kHeight);
    }
}

TEST(HdrRoundTrip, ExposureIsIgnoredWithAWarning) {
    const std::vector<Rgbe> texels = testTexels(kWidth, kHeight);
    HdrWriter writer;
    writer.headerLines = "EXPOSURE=2\nEXPOSURE=1.5\nFORMAT=32-bit_rle_rgbe\n";
    EnvTempDir dir;
    writeBytes(dir / "e.hdr", writer.write(texels, kWidth, kHeight));
    const Environment env = loadEnvironment(dir / "e.hdr");
    EXPECT_EQ(env.texel(5, 1)[0], decodeRgbe(texels[kWidth + 5])[0]);
    ASSERT_EQ(env.report.warnings.size(), 2u);  // and 40x5 is not 2:1
    EXPECT_EQ(env.report.warnings[0], (dir / "e.hdr").string() +
                                   ": EXPOSURE=3 in the header is ignored (texels are used as stored, as other viewers do)");
}

TEST(HdrRoundTrip, FlippedOrientationsAreNormalized) {
    const std::vector<Rgbe> texels = testTexels(kWidth, kHeight);
    struct Case { const char* resolution; bool flipY, flipX; };
    for (const Case& c : {Case{"+Y 5 +X 40", true, false}, Case{"-Y 5 -X 40", false, true}, Case{"+Y 5 -X 40", true, true}}) {
        SCOPED_TRACE(c.resolution);
        HdrWriter writer;
        writer.resolution = c.resolution;
        writer.flipY = c.flipY;
        writer.flipX = c.flipX;
        expectExact(writer.write(texels, kWidth, kHeight), texels, kWidth, kHeight);
    }
}

TEST(HdrRoundTrip, QuantizationWithinOneMantissaStep) {
    // Floats → RGBE → reader: each channel within max(r, g, b)/128 of the float written.
    const uint32_t width = 64, height = 2;
    std::vector<float> floats;
    std::vector<Rgbe> texels;
    for (uint32_t i = 0; i < width * height; ++i) {
        const float r = std::exp2(float(i % 40) - 20.0f) * (1.0f + 0.37f * float(i % 3));
        const float g = r * 0.31f, b = r * float(i % 5) * 0.2f;
        floats.insert(floats.end(), {r, g, b});
        texels.push_back(encodeRgbe(r, g, b));
    }
    EnvTempDir dir;
    writeBytes(dir / "q.hdr", HdrWriter{}.write(texels, width, height));
    const Environment env = loadEnvironment(dir / "q.hdr");
    for (size_t i = 0; i < texels.size(); ++i) {
        const float maxChannel = std::max({floats[i * 3], floats[i * 3 + 1], floats[i * 3 + 2]});
        for (size_t c = 0; c < 3; ++c) {
            const float got = env.rgb[i * 3 + c], want = floats[i * 3 + c];
            EXPECT_LE(got, want) << "truncating encoder";
            EXPECT_LE(want - got, maxChannel / 128.0f) << "texel " << i << " channel " << c;
        }
    }
}

TEST(HdrRoundTrip, ContentDecidesTheFormatNotTheExtension) {
    const std::vector<Rgbe> texels = testTexels(kWidth, kHeight);
    expectExact(HdrWriter{}.write(texels, kWidth, kHeight), texels, kWidth, kHeight, "map.exr");
    expectExact(HdrWriter{}.write(texels, kWidth, kHeight), texels, kWidth, kHeight, "map");
}

}  // namespace
}  // namespace candela::assets::test
