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

TEST(Statistics, SpreadsAreQuartilesThatAnOutlierMovesLittle) {
    const Spread three = spreadOf({4.27, 5.6, 3.9});  // three rounds: the lowest and highest
    EXPECT_DOUBLE_EQ(three.median, 4.27);
    EXPECT_DOUBLE_EQ(three.low, 3.9);
    EXPECT_DOUBLE_EQ(three.high, 5.6);
    const Spread five = spreadOf({2.51, 2.52, 4.00, 2.50, 2.53});  // one slow round
    EXPECT_DOUBLE_EQ(five.median, 2.52);
    EXPECT_DOUBLE_EQ(five.low, 2.51);
    EXPECT_DOUBLE_EQ(five.high, 2.53);
    EXPECT_DOUBLE_EQ(spreadOf({}).median, -1.0);
}

}  // namespace
}  // namespace candela::app
