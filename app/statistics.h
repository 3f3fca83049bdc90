#pragma once
// Small statistics shared by the measuring subcommands (bench, ibl-report).

#include <algorithm>
#include <vector>

namespace candela::app {

// The median of `values` (the upper middle for an even count); -1 when empty.
inline double median(std::vector<double> values) {
    if (values.empty()) return -1.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

}  // namespace candela::app
