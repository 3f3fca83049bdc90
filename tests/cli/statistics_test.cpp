// The measuring commands' statistics (app/statistics.h): medians, quantiles and the spreads the
// reports and bench print.

#include "statistics.h"

#include <gtest/gtest.h>

namespace candela::app {
namespace {

TEST(Statistics, QuantilesAreNearestRanksThatBracketTheMedian) {
    const std::vector<double> values{9, 1, 5, 3, 7};  // sorted: 1 3 5 7 9
    EXPECT_DOUBLE_EQ(quantile(values, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(quantile(values, 0.25), 3.0);
    EXPECT_DOUBLE_EQ(quantile(values, 0.5), 5.0);
    EXPECT_DOUBLE_EQ(quantile(values, 0.75), 7.0);
    EXPECT_DOUBLE_EQ(quantile(values, 1.0), 9.0);
    // An even count: median() is the upper middle (3), the quartiles 1 and 3.
    EXPECT_DOUBLE_EQ(quantile({1, 2, 3, 4}, 0.25), 1.0);
    EXPECT_DOUBLE_EQ(quantile({1, 2, 3, 4}, 0.75), 3.0);
    EXPECT_DOUBLE_EQ(median({1, 2, 3, 4}), 3.0);
    EXPECT_DOUBLE_EQ(quantile({1, 2}, 0.75), median({1, 2}));
    EXPECT_DOUBLE_EQ(quantile({4}, 0.75), 4.0);
    EXPECT_DOUBLE_EQ(quantile({}, 0.5), -1.0);
}

TEST(Statistics, SpreadsAreTheRangeOfRepeatsAndTheQuartilesOfFrames) {
    const Spread repeats = spreadOfRepeats({4.27, 5.6, 3.9});
    EXPECT_DOUBLE_EQ(repeats.median, 4.27);
    EXPECT_DOUBLE_EQ(repeats.low, 3.9);
    EXPECT_DOUBLE_EQ(repeats.high, 5.6);
    const Spread frames = spreadOfFrames({10, 11, 12, 13, 100});  // one slow frame moves the quartiles little
    EXPECT_DOUBLE_EQ(frames.median, 12.0);
    EXPECT_DOUBLE_EQ(frames.low, 11.0);
    EXPECT_DOUBLE_EQ(frames.high, 13.0);
    EXPECT_DOUBLE_EQ(spreadOfRepeats({}).median, -1.0);
}

}  // namespace
}  // namespace candela::app
