// OpenEXR round trips through tinyexr (written here with its EXRHeader API) and the repair of NaN,
// Inf and negative texels. FLOAT channels read back bit for bit; HALF channels too, because every
// value written to them is exactly representable in half precision.
#include "environment_test_util.h"

#include <limits>

namespace candela::scene::test {
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

TEST(ExrRoundTrip, FloatRgbEveryCompression) {
    const uint32_t width = 34, height = 15;
    std::vector<float> rgb;
    for (uint32_t i = 0; i < width * height; ++i) rgb.insert(rgb.end(), {std::exp2(float(i % 50) - 25.0f), 1e-7f * float(i), 1234.5678f + float(i)});
    for (int compression : {TINYEXR_COMPRESSIONTYPE_NONE, TINYEXR_COMPRESSIONTYPE_RLE, TINYEXR_COMPRESSIONTYPE_ZIPS,
                            TINYEXR_COMPRESSIONTYPE_ZIP, TINYEXR_COMPRESSIONTYPE_PIZ}) {
        SCOPED_TRACE("compression " + std::to_string(compression));
        EnvTempDir dir;
        const Environment env = loadBytes(dir, makeExr(width, height, rgbChannels(rgb, TINYEXR_PIXELTYPE_FLOAT), compression));
        ASSERT_EQ(env.width, width);
        ASSERT_EQ(env.height, height);
        EXPECT_EQ(env.rgb, rgb);
        EXPECT_EQ(env.replacedTexels, 0u);
        EXPECT_EQ(env.warnings, std::vector<std::string>{(dir / "map.exr").string() + ": 34x15 is not 2:1; it is mapped as equirectangular anyway"});
    }
}

TEST(ExrRoundTrip, HalfRgbaIgnoresAlpha) {
    const uint32_t width = 64, height = 32;
    const std::vector<float> rgb = halfExactRgb(width, height);
    EnvTempDir dir;
    const Environment env = loadBytes(dir, makeExr(width, height, rgbChannels(rgb, TINYEXR_PIXELTYPE_HALF, /*alpha=*/true)));
    EXPECT_EQ(env.rgb, rgb);
    EXPECT_TRUE(env.warnings.empty());
}

TEST(ExrRoundTrip, SaveExrRgbHalfAndFloat) {
    // tinyexr's simple SaveEXR (what engine/io writes) as well.
    const uint32_t width = 16, height = 8;
    const std::vector<float> rgb = halfExactRgb(width, height);
    for (int fp16 : {0, 1}) {
        EnvTempDir dir;
        const char* error = nullptr;
        ASSERT_EQ(SaveEXR(rgb.data(), int(width), int(height), 3, fp16, (dir / "s.exr").c_str(), &error), TINYEXR_SUCCESS);
        const Environment env = loadEnvironment(dir / "s.exr");
        EXPECT_EQ(env.rgb, rgb) << "fp16 " << fp16;
    }
}

TEST(ExrRoundTrip, GreyYChannelAndExtraChannels) {
    const uint32_t width = 8, height = 4;
    std::vector<float> y(width * height), depth(width * height, 7.0f);
    for (size_t i = 0; i < y.size(); ++i) y[i] = float(i) * 0.5f;
    EnvTempDir dir;
    const Environment grey = loadBytes(dir, makeExr(width, height, {{"Y", TINYEXR_PIXELTYPE_HALF, y}}), "y.exr");
    for (size_t i = 0; i < y.size(); ++i)
        for (size_t c = 0; c < 3; ++c) ASSERT_EQ(grey.rgb[i * 3 + c], y[i]);

    // RGB wins over Y; unrelated channels (even UINT ones) are ignored.
    std::vector<ExrChannel> channels = rgbChannels(halfExactRgb(width, height), TINYEXR_PIXELTYPE_FLOAT);
    channels.push_back({"Y", TINYEXR_PIXELTYPE_FLOAT, y});
    channels.push_back({"Z", TINYEXR_PIXELTYPE_FLOAT, depth});
    channels.push_back({"id", TINYEXR_PIXELTYPE_UINT, depth});
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
    const Environment env = loadBytes(dir, makeExr(width, height, rgbChannels(rgb, TINYEXR_PIXELTYPE_FLOAT)));
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
    ASSERT_EQ(env.warnings.size(), 1u);
    const std::string& warning = env.warnings[0];
    EXPECT_EQ(warning, (dir / "map.exr").string() +
                           ": replaced 5 texels holding NaN, Inf or negative values (2 NaN and 4 negative values set "
                           "to 0, 2 +Inf set to 100000)");
}

TEST(ExrSanitize, OverflowedHalfBecomesTheHalfMaximum) {
    // 1e6 does not fit in a half: tinyexr stores +Inf. With nothing brighter, it becomes 65504.
    const uint32_t width = 4, height = 2;
    std::vector<float> rgb(width * height * 3, 1.0f);
    rgb[3] = 1e6f;
    EnvTempDir dir;
    const Environment env = loadBytes(dir, makeExr(width, height, rgbChannels(rgb, TINYEXR_PIXELTYPE_HALF)));
    EXPECT_EQ(env.replacedTexels, 1u);
    EXPECT_EQ(env.rgb[3], 65504.0f);
    ASSERT_FALSE(env.warnings.empty());
    EXPECT_NE(env.warnings.back().find("replaced 1 texel holding"), std::string::npos) << env.warnings.back();
}

}  // namespace
}  // namespace candela::scene::test
