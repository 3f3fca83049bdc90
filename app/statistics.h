#pragma once
// Small statistics shared by the measuring subcommands (bench, ibl-report, quality-report).

#include <algorithm>
#include <cmath>
#include <vector>

namespace candela::app {

// The median of `values` (the upper middle for an even count); -1 when empty.
inline double median(std::vector<double> values) {
    if (values.empty()) return -1.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

// The q-quantile of `values` (0 ≤ q ≤ 1) by nearest rank: the smallest value with at least a
// fraction q of the values at or below it (q 0.25: the lower quartile). Quartiles so taken always
// bracket median() (the upper middle of an even count). -1 when empty.
inline double quantile(std::vector<double> values, double q) {
    if (values.empty()) return -1.0;
    std::sort(values.begin(), values.end());
    const double rank = std::ceil(std::clamp(q, 0.0, 1.0) * double(values.size()));
    return values[size_t(std::max(rank, 1.0)) - 1];
}

// A measured figure: the median of repeated measurements (frames, rounds of a report) and their
// spread, the lower and upper quartile by nearest rank (for 3 values the lowest and highest, for 5
// the second and fourth: one outlier on either side moves it little). All -1 when empty.
struct Spread {
    double median = -1.0;
    double low = -1.0;
    double high = -1.0;
};

inline Spread spreadOf(const std::vector<double>& values) {
    return {median(values), quantile(values, 0.25), quantile(values, 0.75)};
}

}  // namespace candela::app
