// The rest of `candela diff` without the executable: PSNR, the largest channel difference and the
// fraction of pixels over a threshold on hand-computed cases; reading PNG and EXR files and every
// way that fails (one line naming the file); a pair's status (ok, over a threshold, size mismatch,
// unreadable); and matching two folders by relative path.

#include "assets/image_file.h"
#include "bad_input_expect.h"
#include "core/errors.h"
#include "reports/compared_image.h"
#include "reports/image_diff.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

namespace candela::reports {
namespace {

namespace fs = std::filesystem;

TEST(PixelDifference, HandComputedEightBit) {
    // Two pixels: (10, 20, 30) against (10, 26, 30) and (0, 0, 0) against (3, 0, 0).
    const std::vector<uint8_t> a = {10, 20, 30, 0, 0, 0}, b = {10, 26, 30, 3, 0, 0};
    const PixelDifference d = pixelDifference(a, b, 5.0);
    EXPECT_EQ(d.maxChannelDifference, 6.0);
    EXPECT_EQ(d.pixelsOverThreshold, 1u);  // 6 > 5; 3 is not
    EXPECT_EQ(d.fractionOverThreshold, 0.5);
    // MSE over the 6 values: (36 + 9) / 6 = 7.5.
    EXPECT_NEAR(d.psnr, 10.0 * std::log10(255.0 * 255.0 / 7.5), 1e-12);
    // Strictly greater, as Filament's maxAbsDiff: a difference equal to the threshold passes.
    EXPECT_EQ(pixelDifference(a, b, 6.0).pixelsOverThreshold, 0u);
    const PixelDifference same = pixelDifference(a, a, 0.0);
    EXPECT_TRUE(std::isinf(same.psnr));
    EXPECT_EQ(same.maxChannelDifference, 0.0);
    EXPECT_EQ(same.pixelsOverThreshold, 0u);
    EXPECT_THROW(pixelDifference(a, std::vector<uint8_t>{1, 2, 3}, 5.0), std::invalid_argument);
    EXPECT_EQ(pixelDifference(std::vector<uint8_t>{}, std::vector<uint8_t>{}, 5.0).fractionOverThreshold, 0.0);
}

TEST(PixelDifference, HandComputedFloat) {
    // Peak: the reference's largest value (4) when above 1.
    const std::vector<float> a = {4.0f, 0.0f, 0.0f, 0.5f, 0.5f, 0.5f}, b = {3.0f, 0.0f, 0.0f, 0.5f, 0.5f, 0.51f};
    const PixelDifference d = pixelDifference(a, b, 5.0 / 255.0);
    EXPECT_NEAR(d.maxChannelDifference, 1.0, 1e-7);
    EXPECT_EQ(d.pixelsOverThreshold, 1u);  // 0.01 < 5/255
    const double mse = (1.0 + 0.01 * 0.01) / 6.0;
    EXPECT_NEAR(d.psnr, 10.0 * std::log10(16.0 / mse), 1e-4);
    // Peak 1 for a reference within [0, 1]; a NaN counts as 0.
    const std::vector<float> c = {0.5f, 0.5f, 0.5f}, e = {0.5f, 0.5f, NAN};
    EXPECT_NEAR(pixelDifference(c, e, 0.0).psnr, 10.0 * std::log10(1.0 / (0.25 / 3.0)), 1e-9);
}

class DiffFiles : public ::testing::Test {
protected:
    candela::test::TempDir dir{"candela_diff"};

    // A w × h RGBA image of one colour, with pixel 0 changed to `first`.
    fs::path png(const std::string& name, uint32_t w, uint32_t h, uint8_t value, uint8_t first) {
        std::vector<uint8_t> rgba(size_t(w) * h * 4, value);
        for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
        rgba[0] = rgba[1] = rgba[2] = first;
        fs::create_directories((dir / name).parent_path());
        assets::writePng(dir / name, w, h, rgba);
        return dir / name;
    }
    fs::path exr(const std::string& name, uint32_t w, uint32_t h, float value) {
        std::vector<float> rgba(size_t(w) * h * 4, value);
        assets::writeExr(dir / name, w, h, rgba);
        return dir / name;
    }
    fs::path file(const std::string& name, const std::string& bytes) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
        return dir / name;
    }
    static DiffSettings settings() {
        DiffSettings s;
        s.pixelsPerDegree = pixelsPerDegree({});
        return s;
    }
};

TEST_F(DiffFiles, ReadsPngAsStoredAndDecoded) {
    const ComparedImage image = readComparedImage(png("a.png", 3, 2, 128, 255));
    EXPECT_EQ(image.format, ComparedFormat::Png);
    EXPECT_EQ(image.width, 3u);
    EXPECT_EQ(image.height, 2u);
    ASSERT_EQ(image.rgb8.size(), 18u);
    EXPECT_EQ(image.rgb8[0], 255);
    EXPECT_EQ(image.rgb8[3], 128);
    EXPECT_FLOAT_EQ(image.linear.rgb[0], 1.0f);
    EXPECT_FLOAT_EQ(image.linear.rgb[3], srgbToLinear(128));
}

TEST_F(DiffFiles, ReadsExrAsLinear) {
    const ComparedImage image = readComparedImage(exr("a.exr", 4, 4, 2.5f));
    EXPECT_EQ(image.format, ComparedFormat::Exr);
    EXPECT_TRUE(image.rgb8.empty());
    ASSERT_EQ(image.linear.rgb.size(), 48u);
    EXPECT_EQ(image.linear.rgb[5], 2.5f);
    EXPECT_TRUE(image.report.warnings.empty());  // not 2:1, but that is an environment's concern
    std::vector<float> rgba(16 * 4, 1.0f);
    rgba[0] = NAN;
    rgba[5] = -2.0f;
    assets::writeExr(dir / "nan.exr", 4, 4, rgba);
    const ComparedImage repaired = readComparedImage(dir / "nan.exr");
    EXPECT_EQ(repaired.linear.rgb[0], 0.0f);
    EXPECT_EQ(repaired.linear.rgb[4], 0.0f);
    ASSERT_EQ(repaired.report.warnings.size(), 1u);
    EXPECT_NE(repaired.report.warnings[0].find("2 pixels held NaN"), std::string::npos) << repaired.report.warnings[0];
}

TEST_F(DiffFiles, BadFilesAreOneLineErrorsNamingTheFile) {
    fs::create_directories(dir / "folder.png");
    const std::string pngSignature = "\x89PNG\r\n\x1a\n";
    const std::string header = pngSignature + std::string("\0\0\0\x0dIHDR", 8);
    const auto be32 = [](uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
    const struct {
        fs::path path;
        std::string fragment;
    } rows[] = {
        {dir / "missing.png", "cannot open"},
        {dir / "folder.png", "is a directory"},
        {file("text.png", "hello, world"), "not a PNG file"},
        {file("short.png", pngSignature), "truncated PNG"},
        {file("no_ihdr.png", pngSignature + std::string("\0\0\0\x0dIDAT", 8) + std::string(16, '\0')), "no IHDR"},
        {file("huge.png", header + be32(100000) + be32(100000) + std::string(64, '\0')), "exceeds the limit"},
        {file("zero.png", header + be32(0) + be32(16) + std::string(64, '\0')), "zero image size"},
        {file("cut.png", header + be32(16) + be32(16) + std::string("\x08\x02\0\0\0", 5)), "cannot decode PNG"},
        // A chunk that declares a gigabyte in a file of 57 bytes: refused before stb_image grows its
        // buffer to it (the compared-image fuzzer's finding).
        {file("idat.png", header + be32(2) + be32(2) + std::string("\x08\x06\0\0\0", 5) + be32(0) + be32(0x40000000) + "IDAT" +
                              std::string(16, '\0')),
         "chunk IDAT at byte 33 declares 1073741824 bytes, past the end of the file (57 bytes)"},
        {file("text.exr", "not an exr at all"), "not an OpenEXR file"},
        {file("cut.exr", std::string("\x76\x2f\x31\x01\x02\0\0\0", 8)), ""},
        {file("image.jpg", "jpeg"), "not a .png or .exr file"},
    };
    for (const auto& row : rows) {
        SCOPED_TRACE(row.path.string());
        std::string message;
        try {
            readComparedImage(row.path);
        } catch (const UserError& e) {
            message = e.what();
        }
        candela::test::expectOneLineErrorNamingFile(row.path, message, row.fragment);
    }
}

// Every input the compared-image fuzzer (tests/fuzz/fuzz_compared_image.cpp) failed on — a format
// byte, then the file — reads or fails with a UserError.
TEST_F(DiffFiles, FuzzRegressionsReadOrFailCleanly) {
    size_t inputs = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(CANDELA_FUZZ_REGRESSIONS) / "compared_image")) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        if (bytes.empty()) continue;
        const fs::path path = file(std::string("input") + ((bytes[0] & 1) ? ".exr" : ".png"), bytes.substr(1));
        try {
            readComparedImage(path);
        } catch (const UserError&) {
        }
        ++inputs;
    }
    EXPECT_GE(inputs, 1u);
}

TEST_F(DiffFiles, PairStatuses) {
    const fs::path a = png("a.png", 16, 16, 100, 100), b = png("b.png", 16, 16, 100, 200), small = png("s.png", 8, 16, 100, 100);
    DiffSettings s = settings();
    const DiffPair same = diffImages(a, a, "a.png", s);
    EXPECT_EQ(same.status, DiffStatus::Ok);
    EXPECT_EQ(same.flip.mean, 0.0);
    EXPECT_TRUE(same.message.empty());

    const DiffPair changed = diffImages(a, b, "b.png", s);
    EXPECT_EQ(changed.status, DiffStatus::Ok);  // no threshold given: reported, not failed
    EXPECT_GT(changed.flip.mean, 0.0);
    EXPECT_EQ(changed.pixels.maxChannelDifference, 100.0);
    EXPECT_EQ(changed.pixels.pixelsOverThreshold, 1u);

    s.maxFlip = changed.flip.mean / 2;
    const DiffPair overFlip = diffImages(a, b, "b.png", s);
    EXPECT_EQ(overFlip.status, DiffStatus::OverThreshold);
    EXPECT_NE(overFlip.message.find("--max-flip"), std::string::npos) << overFlip.message;
    s.maxFlip.reset();
    s.maxFraction = 0.001;  // 1 of 256 pixels is over 5 levels
    EXPECT_EQ(diffImages(a, b, "b.png", s).status, DiffStatus::OverThreshold);
    s.maxFraction = 0.01;
    EXPECT_EQ(diffImages(a, b, "b.png", s).status, DiffStatus::Ok);

    const DiffPair mismatch = diffImages(a, small, "s.png", s);
    EXPECT_EQ(mismatch.status, DiffStatus::SizeMismatch);
    EXPECT_EQ(mismatch.message, "reference 16x16, test 8x16");

    std::vector<float> map = {1.0f};
    const DiffPair unreadable = diffImages(a, file("bad.png", "nope"), "bad.png", s, &map);
    EXPECT_EQ(unreadable.status, DiffStatus::Unreadable);
    EXPECT_EQ(unreadable.message, (dir / "bad.png").string() + ": not a PNG file");
    EXPECT_TRUE(map.empty());

    EXPECT_THROW(diffImages(a, exr("e.exr", 16, 16, 1.0f), "e", s), UserError);  // PNG against EXR
    EXPECT_THROW(diffImages(a, file("x.tga", "tga"), "x", s), UserError);
}

TEST_F(DiffFiles, ExrPairIsHdrFlipWithThresholdInLinearUnits) {
    const fs::path a = exr("a.exr", 16, 16, 2.0f), b = exr("b.exr", 16, 16, 2.015625f);  // exact in half
    std::vector<float> map;
    const DiffPair pair = diffImages(a, b, "b.exr", settings(), &map);
    EXPECT_EQ(pair.status, DiffStatus::Ok);
    EXPECT_TRUE(pair.hdr);
    ASSERT_TRUE(pair.exposures);
    EXPECT_EQ(map.size(), 256u);
    EXPECT_NEAR(pair.pixels.maxChannelDifference, 0.015625, 1e-7);
    EXPECT_EQ(pair.pixels.pixelsOverThreshold, 0u);  // 0.0156 < 5/255 = 0.0196
}

TEST_F(DiffFiles, FoldersMatchByRelativePath) {
    png("ref/a.png", 4, 4, 0, 0);
    png("ref/sub/b.png", 4, 4, 0, 0);
    png("ref/only_reference.png", 4, 4, 0, 0);
    file("ref/notes.txt", "ignored");
    png("test/a.png", 4, 4, 0, 0);
    png("test/sub/b.png", 4, 4, 0, 0);
    png("test/only_test.png", 4, 4, 0, 0);
    exr("test/c.EXR", 4, 4, 1.0f);
    const std::vector<MatchedFile> files = matchFolders(dir / "ref", dir / "test");
    ASSERT_EQ(files.size(), 5u);
    EXPECT_EQ(files[0].name, "a.png");
    EXPECT_TRUE(files[0].reference && files[0].test);
    EXPECT_EQ(files[1].name, "c.EXR");
    EXPECT_FALSE(files[1].reference);
    EXPECT_EQ(files[2].name, "only_reference.png");
    EXPECT_FALSE(files[2].test);
    EXPECT_EQ(files[3].name, "only_test.png");
    EXPECT_EQ(files[4].name, "sub/b.png");
    EXPECT_EQ(*files[4].test, dir / "test" / "sub" / "b.png");
    EXPECT_THROW(matchFolders(dir / "ref", dir / "nowhere"), UserError);
}

}  // namespace
}  // namespace candela::reports
