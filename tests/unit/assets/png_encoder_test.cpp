// The PNG encoder (assets/png_encoder.h): what it writes decodes (stb_image, an independent
// reader) to exactly the pixels given, for sizes down to 1 × 1 and odd widths, alpha included, in
// one deflated piece or several; its chunks' CRCs hold and its image data is one zlib stream whose
// Adler-32 holds (zlib's inflate checks both); and it is smaller than storing the pixels on a
// rendered-looking image (gradients and flat areas).
#include "assets/png_encoder.h"

#include <gtest/gtest.h>
#include <stb_image.h>
#include <zlib.h>

#include <cmath>
#include <string>
#include <vector>

namespace candela::assets {
namespace {

std::vector<uint8_t> decode(const std::vector<uint8_t>& png, int& width, int& height) {
    int channels = 0;
    uint8_t* pixels = stbi_load_from_memory(png.data(), int(png.size()), &width, &height, &channels, 4);
    if (!pixels) return {};
    std::vector<uint8_t> out(pixels, pixels + size_t(width) * size_t(height) * 4);
    stbi_image_free(pixels);
    EXPECT_EQ(channels, 4);
    return out;
}

TEST(PngEncoder, DecodesToThePixelsGiven) {
    // 33 × 130 and 40 × 200: pieces of 64 rows and a shorter last one (png_encoder.cpp).
    for (const auto& [w, h] : {std::pair{1u, 1u}, {3u, 2u}, {7u, 5u}, {64u, 33u}, {257u, 3u}, {33u, 130u}, {40u, 200u}}) {
        SCOPED_TRACE(testing::Message() << w << "x" << h);
        std::vector<uint8_t> rgba(size_t(w) * h * 4);
        uint32_t state = 12345;  // noise (no predictor helps), alpha anything
        for (uint8_t& byte : rgba) byte = uint8_t((state = state * 1664525u + 1013904223u) >> 24);
        int width = 0, height = 0;
        EXPECT_EQ(decode(encodePng(w, h, rgba), width, height), rgba);
        EXPECT_EQ(uint32_t(width), w);
        EXPECT_EQ(uint32_t(height), h);
    }
    EXPECT_ANY_THROW(encodePng(2, 2, std::vector<uint8_t>(15)));
}

uint32_t bigEndian(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

TEST(PngEncoder, ChunksHoldTheirCrcsAndTheImageDataIsOneZlibStream) {
    for (const auto& [w, h] : {std::pair{5u, 3u}, {33u, 130u}, {321u, 257u}}) {
        SCOPED_TRACE(testing::Message() << w << "x" << h);
        std::vector<uint8_t> rgba(size_t(w) * h * 4);
        for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = uint8_t((i / 4 % w) * 3 + (i / 4 / w) * 5 + i % 4 * 60);
        const std::vector<uint8_t> png = encodePng(w, h, rgba);
        std::vector<uint8_t> idat;
        std::vector<std::string> types;
        for (size_t at = 8; at + 12 <= png.size();) {
            const uint32_t length = bigEndian(&png[at]);
            ASSERT_LE(at + 12 + length, png.size());
            types.emplace_back(reinterpret_cast<const char*>(&png[at + 4]), 4);
            EXPECT_EQ(bigEndian(&png[at + 8 + length]), uint32_t(crc32(0, &png[at + 4], uInt(4 + length)))) << types.back();
            if (types.back() == "IDAT") idat.insert(idat.end(), png.begin() + long(at) + 8, png.begin() + long(at + 8 + length));
            at += 12 + length;
        }
        EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
        // Each row: its filter byte and its bytes. uncompress fails on a wrong Adler-32.
        std::vector<uint8_t> rows(size_t(h) * (size_t(w) * 4 + 1) + 1);
        uLongf size = uLongf(rows.size());
        ASSERT_EQ(uncompress(rows.data(), &size, idat.data(), uLong(idat.size())), Z_OK);
        EXPECT_EQ(size, rows.size() - 1);
    }
}

TEST(PngEncoder, ARenderedLookingImageTakesAFractionOfItsPixels) {
    const uint32_t w = 320, h = 180;
    std::vector<uint8_t> rgba(size_t(w) * h * 4);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            uint8_t* p = &rgba[(size_t(y) * w + x) * 4];
            const bool disc = std::hypot(float(x) - 160.0f, float(y) - 90.0f) < 60.0f;
            p[0] = disc ? uint8_t(200 - y / 2) : uint8_t(x * 255 / w);
            p[1] = disc ? 40 : uint8_t(y * 255 / h);
            p[2] = 128;
            p[3] = 255;
        }
    const std::vector<uint8_t> png = encodePng(w, h, rgba);
    int width = 0, height = 0;
    EXPECT_EQ(decode(png, width, height), rgba);
    EXPECT_LT(png.size() * 20, rgba.size()) << png.size() << " bytes";
}

}  // namespace
}  // namespace candela::assets
