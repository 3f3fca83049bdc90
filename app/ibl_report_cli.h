#pragma once
// `candela ibl-report`'s options and flags.

#include "common_options.h"
#include "flag_spec.h"

#include <string>
#include <vector>

namespace candela::app {

struct IblReportOptions {
    CommonOptions common;
    EnvironmentChoice env;          // --env FILE|sky (never None)
    std::string out;                // --out DIR (created)
    uint32_t repeats = 0;           // --repeats N: rounds of precompute runs over every setting (median, spread)
    bool quick = false;             // --quick: a reduced sweep (tests, smoke runs)
    uint32_t width = 0;             // --width, --height: end-to-end image size
    uint32_t height = 0;
    uint32_t referenceSamples = 0;  // --reference-samples N: per pixel of the ground-truth render
    bool operator==(const IblReportOptions&) const = default;
};

// Every flag ibl-report takes.
std::vector<FlagSpec<IblReportOptions>> iblReportFlags();

}  // namespace candela::app
