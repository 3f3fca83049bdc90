// `candela diff` end to end: two files and two folders, the exit codes (0 every pair passes, 1 a
// pair over a threshold, missing or of another size, 2 bad usage or an unreadable image), the
// lines it prints, the JSON it writes and the error maps. Inputs: the committed ꟻLIP test pairs
// (tests/data/flip) and small images written here.
#include "run_candela.h"
#include "test_paths.h"
#include "temp_dir.h"

#include "assets/image_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb_image.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using candela::test::Result;
using candela::test::run;

const fs::path kData = ::candela::test::testData() / "flip";

// A fresh scratch folder for one test, removed after it.
class DiffCli : public ::testing::Test {
protected:
    candela::test::TempDir dir{"candela_diff_cli"};

    std::string path(const std::string& name) const { return (dir / name).string(); }

    // Folders ref/ and test/ with the committed pairs, the test side's PNG and EXR renamed to the
    // reference's names so that they match.
    void folders(bool changed) {
        for (const char* side : {"ref", "test"}) fs::create_directories(dir / side / "sub");
        for (const char* ext : {".png", ".exr"}) {
            fs::copy_file(kData / (std::string("helmet_reference") + ext), dir / "ref" / "sub" / (std::string("helmet") + ext));
            fs::copy_file(kData / ((changed ? "helmet_test" : "helmet_reference") + std::string(ext)),
                          dir / "test" / "sub" / (std::string("helmet") + ext));
        }
    }

    void png(const std::string& name, uint32_t w, uint32_t h, uint8_t value) {
        std::vector<uint8_t> rgba(size_t(w) * h * 4, value);
        fs::create_directories((dir / name).parent_path());
        candela::assets::writePng(dir / name, w, h, rgba);
    }

    nlohmann::json json(const std::string& name) const {
        std::ifstream in(dir / name);
        return nlohmann::json::parse(in);
    }
};

// Exactly one line on stderr, containing `fragment`.
void expectOneErrorLine(const Result& r, const std::string& fragment) {
    EXPECT_EQ(r.exitCode, 2) << r.stderrText;
    EXPECT_NE(r.stderrText.find(fragment), std::string::npos) << r.stderrText;
    EXPECT_EQ(std::count(r.stderrText.begin(), r.stderrText.end(), '\n'), 1) << r.stderrText;
}

TEST_F(DiffCli, IdenticalFoldersPass) {
    folders(false);
    const Result r = run("diff " + path("ref") + " " + path("test") + " --max-flip 0 --max-fraction 0 --report " + path("d.json"));
    EXPECT_EQ(r.exitCode, 0) << r.stdoutText << r.stderrText;
    EXPECT_EQ(r.stderrText, "");
    EXPECT_NE(r.stdoutText.find("ok             sub/helmet.exr: 128x128 HDR, FLIP mean 0.000000"), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("ok             sub/helmet.png: 128x128, FLIP mean 0.000000"), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("2 pairs: 2 ok, 0 over threshold, 0 missing, 0 size mismatch, 0 unreadable"), std::string::npos);
    const nlohmann::json j = json("d.json");
    EXPECT_TRUE(j["totals"]["passed"]);
    for (const auto& pair : j["pairs"]) {
        EXPECT_EQ(pair["flip"]["mean"], 0.0);
        EXPECT_TRUE(pair["psnr"].is_null());  // identical: infinite
        EXPECT_EQ(pair["maxChannelDifference"], 0.0);
    }
}

TEST_F(DiffCli, ChangedImageFailsMaxFlip) {
    const std::string pngs = (kData / "helmet_reference.png").string() + " " + (kData / "helmet_test.png").string();
    // Mean ꟻLIP 0.085286 (flip_reference_test.cpp): over 0.05, under 0.1.
    const Result over = run("diff " + pngs + " --max-flip 0.05");
    EXPECT_EQ(over.exitCode, 1) << over.stdoutText << over.stderrText;
    EXPECT_NE(over.stdoutText.find("over threshold helmet_test.png: 128x128, FLIP mean 0.085286"), std::string::npos) << over.stdoutText;
    EXPECT_NE(over.stdoutText.find("mean FLIP 0.085286 > --max-flip 0.05"), std::string::npos) << over.stdoutText;
    EXPECT_EQ(over.stderrText, "");
    EXPECT_EQ(run("diff " + pngs + " --max-flip 0.1").exitCode, 0);
    // Without thresholds the numbers are reported and the pair passes.
    EXPECT_EQ(run("diff " + pngs).exitCode, 0);
    // Filament's gate: far more than 0.1% of the pixels differ by more than 5 levels.
    const Result fraction = run("diff " + pngs + " --threshold 5 --max-fraction 0.001");
    EXPECT_EQ(fraction.exitCode, 1);
    EXPECT_NE(fraction.stdoutText.find("levels > --max-fraction 0.001"), std::string::npos) << fraction.stdoutText;
}

TEST_F(DiffCli, MissingAndMismatchedPairsFail) {
    folders(true);
    fs::remove(dir / "test" / "sub" / "helmet.exr");
    png("ref/small.png", 16, 16, 10);
    png("test/small.png", 16, 8, 10);
    png("test/extra.png", 4, 4, 10);
    const Result r = run("diff " + path("ref") + " " + path("test") + " --report " + path("d.json"));
    EXPECT_EQ(r.exitCode, 1) << r.stdoutText << r.stderrText;
    EXPECT_NE(r.stdoutText.find("missing        extra.png: no reference image in " + path("ref")), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("size mismatch  small.png: reference 16x16, test 16x8"), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("missing        sub/helmet.exr: no test image in " + path("test")), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("ok             sub/helmet.png"), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("4 pairs: 1 ok, 0 over threshold, 2 missing, 1 size mismatch, 0 unreadable"), std::string::npos);
    const nlohmann::json j = json("d.json");
    EXPECT_FALSE(j["totals"]["passed"]);
    EXPECT_EQ(j["totals"]["missing"], 2);
    EXPECT_EQ(j["totals"]["sizeMismatch"], 1);
    ASSERT_EQ(j["pairs"].size(), 4u);
    EXPECT_EQ(j["pairs"][0]["name"], "extra.png");
    EXPECT_EQ(j["pairs"][0]["status"], "missing");
    EXPECT_EQ(j["pairs"][0]["reference"], "");
    EXPECT_FALSE(j["pairs"][0].contains("flip"));  // nothing was compared
}

TEST_F(DiffCli, JsonHoldsEveryNumber) {
    folders(true);
    const Result r = run("diff " + path("ref") + " " + path("test") + " --monitor-distance 1.4 --error-maps " + path("maps") +
                         " --report " + path("d.json"));
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    const nlohmann::json j = json("d.json");
    EXPECT_NEAR(j["viewing"]["pixelsPerDegree"].get<double>(), 2 * 67.0206, 1e-3);  // twice as far
    EXPECT_EQ(j["viewing"]["from"], "monitor");
    EXPECT_NEAR(j["viewing"]["monitorDistance"].get<double>(), 1.4, 1e-6);
    EXPECT_EQ(j["viewing"]["monitorResolution"], 3840);
    EXPECT_EQ(j["thresholds"]["thresholdLevels"], 5.0);
    EXPECT_TRUE(j["thresholds"]["maxFlip"].is_null());
    ASSERT_EQ(j["pairs"].size(), 2u);
    for (const auto& pair : j["pairs"]) {
        SCOPED_TRACE(pair.dump());
        for (const char* key : {"name", "reference", "test", "status", "passed", "message", "format", "width", "height", "errorMap",
                                "flip", "psnr", "maxChannelDifference", "pixelsOverThreshold", "fractionOverThreshold"})
            EXPECT_TRUE(pair.contains(key)) << key;
        EXPECT_EQ(pair["status"], "ok");
        EXPECT_EQ(pair["width"], 128);
        const double mean = pair["flip"]["mean"];
        EXPECT_GT(mean, 0.0);
        EXPECT_LT(mean, pair["flip"]["max"].get<double>());
        EXPECT_LE(pair["flip"]["max"].get<double>(), 1.0);
        EXPECT_LE(pair["flip"]["weightedQuartile1"].get<double>(), pair["flip"]["weightedMedian"].get<double>());
        EXPECT_LE(pair["flip"]["weightedMedian"].get<double>(), pair["flip"]["weightedQuartile3"].get<double>());
        uint64_t pixels = 0;
        for (uint64_t n : pair["flip"]["histogram"]) pixels += n;
        EXPECT_EQ(pixels, 128u * 128u);
        EXPECT_GT(pair["psnr"].get<double>(), 10.0);
        EXPECT_GT(pair["fractionOverThreshold"].get<double>(), 0.0);
        EXPECT_LT(pair["fractionOverThreshold"].get<double>(), 1.0);
    }
    const auto& exr = j["pairs"][0];
    EXPECT_EQ(exr["name"], "sub/helmet.exr");
    EXPECT_EQ(exr["format"], "exr");
    EXPECT_EQ(exr["exposures"]["count"], 4);
    EXPECT_LT(exr["maxChannelDifference"].get<double>(), 100.0);  // linear radiance, not levels
    EXPECT_EQ(exr["errorMap"], path("maps") + "/sub/helmet.exr.png");
    const auto& png = j["pairs"][1];
    EXPECT_EQ(png["format"], "png");
    EXPECT_FALSE(png.contains("exposures"));
    EXPECT_EQ(png["errorMap"], path("maps") + "/sub/helmet.png");
    EXPECT_EQ(png["maxChannelDifference"].get<double>(), std::round(png["maxChannelDifference"].get<double>()));  // levels
    EXPECT_TRUE(j["totals"]["passed"]);
}

TEST_F(DiffCli, ErrorMapsAreMagmaPngsAtTheRelativePaths) {
    folders(true);
    const Result r = run("diff " + path("ref") + " " + path("test") + " --error-maps " + path("maps"));
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    for (const char* name : {"maps/sub/helmet.png", "maps/sub/helmet.exr.png"}) {
        SCOPED_TRACE(name);
        int w = 0, h = 0, channels = 0;
        stbi_uc* pixels = stbi_load(path(name).c_str(), &w, &h, &channels, 3);
        ASSERT_NE(pixels, nullptr);
        EXPECT_EQ(w, 128);
        EXPECT_EQ(h, 128);
        // Magma's dark end dominates (most pixels have a small error) and nothing is grey.
        size_t dark = 0, grey = 0;
        for (int i = 0; i < w * h; ++i) {
            const stbi_uc* p = pixels + 3 * i;
            dark += p[0] < 128 && p[1] < 64;
            grey += p[0] == p[1] && p[1] == p[2];
        }
        EXPECT_GT(dark, size_t(w * h / 2));
        EXPECT_EQ(grey, 0u);
        stbi_image_free(pixels);
    }
}

TEST_F(DiffCli, BadUsageAndUnreadableImagesExitTwo) {
    const std::string ref = (kData / "helmet_reference.png").string();
    expectOneErrorLine(run("diff " + ref), "diff: expected two images or two folders (candela diff A B)");
    expectOneErrorLine(run("diff " + ref + " " + ref + " " + ref), "unexpected argument");
    expectOneErrorLine(run("diff " + ref + " " + ref + " --ppd 0"), "--ppd: expected pixels per degree > 0, got '0'");
    expectOneErrorLine(run("diff " + ref + " " + ref + " --ppd 2000"), "diff: 2000 pixels per degree is more than 1000 (--ppd)");
    expectOneErrorLine(run("diff " + ref + " " + ref + " --monitor-distance 20"), "is more than 1000 (from the --monitor flags)");
    expectOneErrorLine(run("diff " + ref + " " + ref + " --max-flip 2"), "--max-flip: expected a number from 0 to 1, got '2'");
    expectOneErrorLine(run("diff " + ref + " " + ref + " --device 0"), "diff does not take --device");
    expectOneErrorLine(run("diff " + ref + " " + path("nothing.png")), path("nothing.png") + ": no such file or folder");
    expectOneErrorLine(run("diff " + ref + " " + (kData / "helmet_test.exr").string()), "compare PNG with PNG and EXR with EXR");
    expectOneErrorLine(run("diff " + ref + " " + kData.string()), "compare two images or two folders");
    std::ofstream(dir / "broken.png") << "not a png";
    const Result unreadable = run("diff " + ref + " " + path("broken.png"));
    expectOneErrorLine(unreadable, path("broken.png") + ": not a PNG file");
    EXPECT_NE(unreadable.stdoutText.find("unreadable     broken.png: " + path("broken.png") + ": not a PNG file"), std::string::npos)
        << unreadable.stdoutText;
    fs::create_directories(dir / "empty_a");
    fs::create_directories(dir / "empty_b");
    expectOneErrorLine(run("diff " + path("empty_a") + " " + path("empty_b")), "no .png or .exr images in either folder");
}

}  // namespace
