#pragma once
// `candela scale-report`'s options and flags.

#include "common_options.h"
#include "flag_spec.h"

#include <string>
#include <vector>

namespace candela::app {

struct ScaleReportOptions {
    CommonOptions common;
    std::string out;               // --out DIR (created)
    std::vector<uint32_t> sizes;   // --sizes N,N,...: grid sides
    uint32_t frames = 0;           // --frames N per setting
    float lodErrorPixels = 0.0f;   // --lod-error PIXELS: the "on" setting
    uint32_t width = 0;            // --width, --height
    uint32_t height = 0;
    bool operator==(const ScaleReportOptions&) const = default;
};

// Every flag scale-report takes.
std::vector<FlagSpec<ScaleReportOptions>> scaleReportFlags();

}  // namespace candela::app
