// OpenEXR files written with OpenEXR's C++ library (exr_test_writer.h) read back through our
// OpenEXRCore reader, and the repair of NaN, Inf and negative texels. FLOAT channels read back bit
// for bit under every lossless compression; HALF channels too, because every value written to
// them is exactly representable in half precision. The lossy compressions (B44, B44A, DWAA, DWAB)
// are held to a relative error.
#include "environment_test_util.h"

#include "assets/image_file.h"

#include <limits>

namespace candela::assets::test {
namespace {

// Interleaved RGB test texels, all exact in half precision (11-bit significands).
std::vector<float> halfExactRgb(uint32_t width, uint32_t height) {
    std::vector<float> rgb;
    for (uint32_t i = 0; i < width * height; ++i)
        rgb.insert(rgb.end(), {float(i % 97) / 64.0f, float((i * 7) % 131), float((i * 13) % 29) / 4.0f + 64.0f * float(i % 2)});
    return rgb;
}

Environment loadBytes(const EnvTempDir& dir, const Bytes& bytes, const std::string& name = "map.exr") {
    writeBytes(dir / name, bytes);
    return loadEnvironment(dir / name);
}

bool lossy(Imf::Compression compression) {
    return compression == Imf::B44_COMPRESSION || compression == Imf::B44A_COMPRESSION ||
           compression == Imf::DWAA_COMPRESSION || compression == Imf::DWAB_COMPRESSION;
}

TEST(ExrRoundTrip, FloatRgbEveryCompression) {
    const uint32_t width = 34, height = 15;
    std::vector<float> rgb;
    for (uint32_t i = 0; i < width * height; ++i) rgb.insert(rgb.end(), {std::exp2(float(i % 50) - 25.0f), 1e-7f * float(i), 1234.5678f + float(i)});
    for (Imf::Compression compression : candela::test::kExrCompressions) {
        // DWA stores R, G, B through half precision and a DCT whatever their type (this pattern's
        // 2^24 overflows half): HalfRgbEveryCompression covers it.
        if (compression == Imf::DWAA_COMPRESSION || compression == Imf::DWAB_COMPRESSION) continue;
        SCOPED_TRACE("compression " + candela::test::compressionName(compression));
        EnvTempDir dir;
        const Environment env = loadBytes(dir, test::makeExr(width, height, test::rgbChannels(rgb, test::ExrType::Float), {compression}));
        ASSERT_EQ(env.width, width);
        ASSERT_EQ(env.height, height);
        if (compression == Imf::PXR24_COMPRESSION) {
            // PXR24 keeps 24 of a float's 32 bits: a relative error below 2^-15.
            for (size_t i = 0; i < rgb.size(); ++i) ASSERT_NEAR(env.rgb[i], rgb[i], std::abs(rgb[i]) * 0x1p-15f) << i;
        } else {
            EXPECT_EQ(env.rgb, rgb);  // B44 and B44A leave FLOAT channels uncompressed
        }
        EXPECT_EQ(env.replacedTexels, 0u);
        EXPECT_TRUE(env.report.notes.empty());
        EXPECT_EQ(env.report.warnings, std::vector<std::string>{(dir / "map.exr").string() + ": 34x15 is not 2:1; it is mapped as equirectangular anyway"});
    }
}

TEST(ExrRoundTrip, HalfRgbEveryCompression) {
    const uint32_t width = 64, height = 32;
    const std::vector<float> rgb = halfExactRgb(width, height);
    for (Imf::Compression compression : candela::test::kExrCompressions) {
        SCOPED_TRACE("compression " + candela::test::compressionName(compression));
        EnvTempDir dir;
        const Environment env = loadBytes(dir, test::makeExr(width, height, test::rgbChannels(rgb, test::ExrType::Half), {compression}));
        ASSERT_EQ(env.rgb.size(), rgb.size());
        if (!lossy(compression)) {
            EXPECT_EQ(env.rgb, rgb);
            continue;
        }
        // The lossy ones: a mean relative error of a few per cent on this busy test pattern.
        double error = 0.0;
        for (size_t i = 0; i < rgb.size(); ++i) error += std::abs(env.rgb[i] - rgb[i]) / std::max(1.0f, std::abs(rgb[i]));
        EXPECT_LT(error / double(rgb.size()), 0.05);
    }
}

TEST(ExrRoundTrip, HalfRgbaIgnoresAlpha) {
    const uint32_t width = 64, height = 32;
    const std::vector<float> rgb = halfExactRgb(width, height);
    EnvTempDir dir;
    const Environment env = loadBytes(dir, test::makeExr(width, height, test::rgbChannels(rgb, test::ExrType::Half, /*alpha=*/true)));
    EXPECT_EQ(env.rgb, rgb);
    EXPECT_TRUE(env.report.warnings.empty());
}

TEST(ExrRoundTrip, TiledEveryLevelModeAndPartialTiles) {
    // 37 × 19 in 8 × 8 tiles: the last column and row of tiles are partial. Level 0 is the map.
    const uint32_t width = 37, height = 19;
    const std::vector<float> rgb = halfExactRgb(width, height);
    for (Imf::LevelMode levels : {Imf::ONE_LEVEL, Imf::MIPMAP_LEVELS, Imf::RIPMAP_LEVELS})
        for (Imf::Compression compression : {Imf::NO_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION}) {
            SCOPED_TRACE("levels " + std::to_string(int(levels)) + ", " + candela::test::compressionName(compression));
            EnvTempDir dir;
            const Environment env =
                loadBytes(dir, test::makeExr(width, height, test::rgbChannels(rgb, test::ExrType::Float), {compression, true, 8, levels}));
            ASSERT_EQ(env.width, width);
            ASSERT_EQ(env.height, height);
            EXPECT_EQ(env.rgb, rgb);
        }
}

TEST(ExrRoundTrip, WriteExrHalfRgba) {
    // What `--out frame.exr` writes (assets::writeExr: half RGBA, ZIP) reads back exactly.
    const uint32_t width = 16, height = 8;
    const std::vector<float> rgb = halfExactRgb(width, height);
    std::vector<float> rgba;
    for (size_t i = 0; i < rgb.size(); i += 3) rgba.insert(rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 0.25f});
    EnvTempDir dir;
    assets::writeExr(dir / "s.exr", width, height, rgba);
    const Environment env = loadEnvironment(dir / "s.exr");
    EXPECT_EQ(env.rgb, rgb);
    EXPECT_TRUE(env.report.warnings.empty());
}

TEST(ExrWindows, DisplayWindowIsThePictureDataOutsideIsCroppedMissingIsBlack) {
    // Data window (−2, 3)–(9, 6), display window (0, 2)–(7, 5): data columns −2, −1, 8 and 9 are
    // cropped; display row 2 has no data and is black.
    const uint32_t width = 12, height = 4;
    std::vector<float> rgb;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) rgb.insert(rgb.end(), {float(x), float(y), 1.0f});
    test::ExrLayout layout;
    layout.dataX = -2;
    layout.dataY = 3;
    layout.display = Imath::Box2i({0, 2}, {7, 5});
    for (bool tiled : {false, true}) {
        SCOPED_TRACE(tiled ? "tiled" : "scanlines");
        layout.tiled = tiled;
        layout.tileSize = 4;
        EnvTempDir dir;
        const Environment env = loadBytes(dir, test::makeExr(width, height, test::rgbChannels(rgb, test::ExrType::Float), layout));
        ASSERT_EQ(env.width, 8u);
        ASSERT_EQ(env.height, 4u);
        for (uint32_t x = 0; x < 8; ++x) EXPECT_EQ(env.texel(x, 0)[2], 0.0f) << "display row 2 has no data";
        for (uint32_t y = 1; y < 4; ++y)
            for (uint32_t x = 0; x < 8; ++x) {
                // Display (x, y + 2) is data column x + 2, data row y − 1.
                EXPECT_EQ(env.texel(x, y)[0], float(x + 2));
                EXPECT_EQ(env.texel(x, y)[1], float(y - 1));
                EXPECT_EQ(env.texel(x, y)[2], 1.0f);
            }
        EXPECT_EQ(env.report.notes, std::vector<std::string>{(dir / "map.exr").string() +
                                                      ": the data window (-2,3)-(9,6) does not cover the display "
                                                      "window (0,2)-(7,5); the rest is black"});
    }
}

TEST(ExrWindows, DataWindowInsideTheDisplayWindowIsDecodedInPlace) {
    // Data (2, 1)–(5, 2) inside display (0, 0)–(7, 3): the library writes straight into the
    // picture; the texels around the data stay black. Grey (Y) and colour alike.
    const uint32_t width = 4, height = 2;
    std::vector<float> y(width * height);
    for (size_t i = 0; i < y.size(); ++i) y[i] = 1.0f + float(i);
    test::ExrLayout layout;
    layout.dataX = 2;
    layout.dataY = 1;
    layout.display = Imath::Box2i({0, 0}, {7, 3});
    for (bool grey : {true, false}) {
        SCOPED_TRACE(grey ? "Y" : "RGB");
        std::vector<float> rgb;
        for (float v : y) rgb.insert(rgb.end(), {v, 2.0f * v, 3.0f * v});
        EnvTempDir dir;
        const Environment env = loadBytes(
            dir, test::makeExr(width, height, grey ? std::vector<test::ExrChannel>{{"Y", test::ExrType::Half, y}} : rgbChannels(rgb, ExrType::Float), layout));
        ASSERT_EQ(env.width, 8u);
        ASSERT_EQ(env.height, 4u);
        for (uint32_t py = 0; py < 4; ++py)
            for (uint32_t px = 0; px < 8; ++px) {
                const bool inside = px >= 2 && px <= 5 && py >= 1 && py <= 2;
                const float v = inside ? y[(py - 1) * width + (px - 2)] : 0.0f;
                const float* t = env.texel(px, py);
                EXPECT_EQ(t[0], v) << px << "," << py;
                EXPECT_EQ(t[1], grey ? v : 2.0f * v) << px << "," << py;
                EXPECT_EQ(t[2], grey ? v : 3.0f * v) << px << "," << py;
            }
        EXPECT_EQ(env.report.notes.size(), 1u);
    }
}

TEST(ExrParts, FirstColourPartIsUsedWithANote) {
    const uint32_t width = 8, height = 4;
    const std::vector<float> rgb = halfExactRgb(width, height);
    const std::vector<float> depth(width * height, 3.0f);
    test::ExrPart z{"depth", width, height, {{"Z", ExrType::Float, depth}}, {}, false};
    ExrPart deep{"samples", width, height, rgbChannels(rgb, ExrType::Float), {Imf::ZIPS_COMPRESSION}, true};
    ExrPart colour{"beauty", width, height, rgbChannels(rgb, ExrType::Half), {Imf::PIZ_COMPRESSION, true, 4}, false};
    ExrPart other{"other", width, height, rgbChannels(std::vector<float>(rgb.size(), 9.0f), ExrType::Half), {}, false};
    EnvTempDir dir;
    const Environment env = loadBytes(dir, test::makeExrParts({z, deep, colour, other}));
    EXPECT_EQ(env.rgb, rgb);
    EXPECT_TRUE(env.report.warnings.empty());
    EXPECT_EQ(env.report.notes, std::vector<std::string>{(dir / "map.exr").string() + ": 4-part EXR: part 2 'beauty' used (the first with R, G, B)"});
}

TEST(ExrParts, DeepOnlyIsRefusedInOneLine) {
    const uint32_t width = 8, height = 4;
    EnvTempDir dir;
    test::ExrPart deep{"samples", width, height, rgbChannels(halfExactRgb(width, height), ExrType::Float), {Imf::RLE_COMPRESSION}, true};
    ExrPart second = deep;
    second.name = "more samples";
    for (const std::vector<ExrPart>& parts : {std::vector<ExrPart>{deep}, std::vector<ExrPart>{deep, second}}) {
        writeBytes(dir / "deep.exr", test::makeExrParts(parts));
        try {
            loadEnvironment(dir / "deep.exr");
            ADD_FAILURE() << "a deep file loaded";
        } catch (const UserError& e) {
            EXPECT_EQ(std::string(e.what()), (dir / "deep.exr").string() +
                                                 ": deep EXR is not supported (it holds samples at depths, not one "
                                                 "colour per pixel)");
        }
    }
}

TEST(ExrRoundTrip, GreyYChannelAndExtraChannels) {
    const uint32_t width = 8, height = 4;
    std::vector<float> y(width * height), depth(width * height, 7.0f);
    for (size_t i = 0; i < y.size(); ++i) y[i] = float(i) * 0.5f;
    EnvTempDir dir;
    const Environment grey = loadBytes(dir, test::makeExr(width, height, {{"Y", test::ExrType::Half, y}}), "y.exr");
    for (size_t i = 0; i < y.size(); ++i)
        for (size_t c = 0; c < 3; ++c) ASSERT_EQ(grey.rgb[i * 3 + c], y[i]);

    // RGB wins over Y; unrelated channels (even UINT ones) are ignored.
    std::vector<test::ExrChannel> channels = test::rgbChannels(halfExactRgb(width, height), test::ExrType::Float);
    channels.push_back({"Y", test::ExrType::Float, y});
    channels.push_back({"Z", test::ExrType::Float, depth});
    channels.push_back({"id", test::ExrType::Uint, depth});
    const Environment env = loadBytes(dir, makeExr(width, height, channels), "rgbyz.exr");
    EXPECT_EQ(env.rgb, halfExactRgb(width, height));
}

TEST(ExrSanitize, NanInfAndNegativeTexelsAreReplacedAndCounted) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const uint32_t width = 8, height = 4;
    std::vector<float> rgb(width * height * 3, 0.5f);
    auto set = [&](uint32_t texel, float r, float g, float b) { rgb[texel * 3] = r, rgb[texel * 3 + 1] = g, rgb[texel * 3 + 2] = b; };
    set(0, nan, 0.5f, 0.5f);
    set(1, inf, 0.5f, 0.5f);
    set(2, -inf, 0.5f, 0.5f);
    set(3, -1.0f, -2.0f, 0.5f);   // two bad channels, one texel
    set(4, nan, inf, -3.0f);      // three kinds in one texel
    set(5, -0.0f, 0.5f, 0.5f);    // −0 is not negative: not counted, becomes +0
    set(6, 100000.0f, 0.5f, 0.5f);  // the brightest finite value (above the half maximum)
    EnvTempDir dir;
    const Environment env = loadBytes(dir, test::makeExr(width, height, test::rgbChannels(rgb, test::ExrType::Float)));
    EXPECT_EQ(env.replacedTexels, 5u);
    auto texel = [&](uint32_t i) { return std::array<float, 3>{env.rgb[i * 3], env.rgb[i * 3 + 1], env.rgb[i * 3 + 2]}; };
    EXPECT_EQ(texel(0), (std::array<float, 3>{0.0f, 0.5f, 0.5f}));
    EXPECT_EQ(texel(1), (std::array<float, 3>{100000.0f, 0.5f, 0.5f})) << "+Inf → the brightest finite value";
    EXPECT_EQ(texel(2), (std::array<float, 3>{0.0f, 0.5f, 0.5f}));
    EXPECT_EQ(texel(3), (std::array<float, 3>{0.0f, 0.0f, 0.5f}));
    EXPECT_EQ(texel(4), (std::array<float, 3>{0.0f, 100000.0f, 0.0f}));
    EXPECT_FALSE(std::signbit(texel(5)[0]));
    EXPECT_EQ(texel(6)[0], 100000.0f);
    for (float v : env.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
    ASSERT_EQ(env.report.warnings.size(), 1u);
    const std::string& warning = env.report.warnings[0];
    EXPECT_EQ(warning, (dir / "map.exr").string() +
                           ": replaced 5 texels holding NaN, Inf or negative values (2 NaN and 4 negative values set "
                           "to 0, 2 +Inf set to 100000)");
}

TEST(ExrSanitize, OverflowedHalfBecomesTheHalfMaximum) {
    // 1e6 does not fit in a half: OpenEXR stores +Inf. With nothing brighter, it becomes 65504.
    const uint32_t width = 4, height = 2;
    std::vector<float> rgb(width * height * 3, 1.0f);
    rgb[3] = 1e6f;
    EnvTempDir dir;
    const Environment env = loadBytes(dir, test::makeExr(width, height, test::rgbChannels(rgb, test::ExrType::Half)));
    EXPECT_EQ(env.replacedTexels, 1u);
    EXPECT_EQ(env.rgb[3], 65504.0f);
    ASSERT_FALSE(env.report.warnings.empty());
    EXPECT_NE(env.report.warnings.back().find("replaced 1 texel holding"), std::string::npos) << env.report.warnings.back();
}

}  // namespace
}  // namespace candela::assets::test
