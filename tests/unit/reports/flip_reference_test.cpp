// ꟻLIP against the authors' implementation (NVlabs/flip v1.5, its C++ tool's CPU path) on the
// committed pairs of tests/data/flip (tools/make-flip-test-images.sh: DamagedHelmet renders,
// 128 × 128, PNG and EXR). The expected numbers are what that tool printed for these files — mean,
// weighted median and quartiles, min and max to 6 decimals, HDR exposures to 4 — at its default 67
// pixels per degree and at --pixels-per-degree 40: docs/pipelines.md#how-the-tests-expected-values-
// were-obtained says how. The tool sums the mean in float; Candela in double, which rounds to the
// same 6 decimals here (the per-pixel maps were identical, bit for bit).

#include "reports/image_diff.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace candela::reports {
namespace {

const std::filesystem::path kData = ::candela::test::testData() / "flip";

// Half a unit in the 6th decimal the tool prints, and a little for the float sum it prints.
constexpr double kPrinted = 1e-6;

struct Published {
    double mean, weightedMedian, weightedQuartile1, weightedQuartile3, min, max;
};

void expectStatistics(const FlipStatistics& s, const Published& p) {
    EXPECT_NEAR(s.mean, p.mean, kPrinted);
    EXPECT_NEAR(s.weightedMedian, p.weightedMedian, kPrinted);
    EXPECT_NEAR(s.weightedQuartile1, p.weightedQuartile1, kPrinted);
    EXPECT_NEAR(s.weightedQuartile3, p.weightedQuartile3, kPrinted);
    EXPECT_NEAR(s.min, p.min, kPrinted);
    EXPECT_NEAR(s.max, p.max, kPrinted);
}

DiffSettings defaults(float ppd = pixelsPerDegree({})) {
    DiffSettings settings;
    settings.pixelsPerDegree = ppd;
    return settings;
}

TEST(FlipReference, LdrFlipOfThePngPair) {
    // flip --reference helmet_reference.png --test helmet_test.png
    const DiffPair pair = diffImages(kData / "helmet_reference.png", kData / "helmet_test.png", "helmet", defaults());
    ASSERT_EQ(pair.status, DiffStatus::Ok) << pair.message;
    EXPECT_FALSE(pair.hdr);
    EXPECT_EQ(pair.width, 128u);
    EXPECT_EQ(pair.height, 128u);
    expectStatistics(pair.flip, {0.085286, 0.159646, 0.091368, 0.251488, 0.001351, 0.779828});
}

TEST(FlipReference, LdrFlipAtFortyPixelsPerDegree) {
    // flip --reference helmet_reference.png --test helmet_test.png --pixels-per-degree 40
    const DiffPair pair = diffImages(kData / "helmet_reference.png", kData / "helmet_test.png", "helmet", defaults(40.0f));
    ASSERT_EQ(pair.status, DiffStatus::Ok) << pair.message;
    expectStatistics(pair.flip, {0.100324, 0.195548, 0.106157, 0.311217, 0.000388, 0.918448});
}

TEST(FlipReference, HdrFlipOfTheExrPair) {
    // flip --reference helmet_reference.exr --test helmet_test.exr --no-exposure-map
    //   Start exposure: 0.5827, Stop exposure: 3.6498, Number of exposures: 4
    const DiffPair pair = diffImages(kData / "helmet_reference.exr", kData / "helmet_test.exr", "helmet", defaults());
    ASSERT_EQ(pair.status, DiffStatus::Ok) << pair.message;
    EXPECT_TRUE(pair.hdr);
    ASSERT_TRUE(pair.exposures);
    EXPECT_NEAR(pair.exposures->start, 0.5827, 0.5e-4);
    EXPECT_NEAR(pair.exposures->stop, 3.6498, 0.5e-4);
    EXPECT_EQ(pair.exposures->count, 4u);
    expectStatistics(pair.flip, {0.120401, 0.240321, 0.145252, 0.425600, 0.000952, 0.975299});
}

TEST(FlipReference, ErrorMapIsTheReturnedStatistics) {
    std::vector<float> map;
    const DiffPair pair = diffImages(kData / "helmet_reference.png", kData / "helmet_test.png", "helmet", defaults(), &map);
    ASSERT_EQ(map.size(), 128u * 128u);
    const FlipStatistics again = flipStatistics(map);
    EXPECT_EQ(again.mean, pair.flip.mean);
    EXPECT_EQ(again.max, pair.flip.max);
}

}  // namespace
}  // namespace candela::reports
