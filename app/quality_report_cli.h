#pragma once
// `candela quality-report`'s options and flags.

#include "common_options.h"
#include "flag_spec.h"

#include <string>
#include <vector>

namespace candela::app {

struct QualityReportOptions {
    CommonOptions common;
    std::string out;                  // --out DIR (created)
    std::vector<std::string> scenes;  // --scenes default,FILE,...: the built-in grid or glTF files
    EnvironmentChoice env;            // --env FILE|sky: the glTF scenes' environment (the grid: the sky)
    std::vector<uint32_t> msaa;       // --msaa N,N,...
    std::vector<float> lodErrors;     // --lod-errors PX,PX,...
    uint32_t frames = 0;              // --frames N: timed frames per setting
    uint32_t orbitFrames = 0;         // --orbit-frames N: frames of the 1°-per-frame orbit
    uint32_t repeats = 0;             // --repeats N: rounds of timing over every setting
    uint32_t width = 0;               // --width, --height
    uint32_t height = 0;
    bool operator==(const QualityReportOptions&) const = default;
};

// Every flag quality-report takes.
std::vector<FlagSpec<QualityReportOptions>> qualityReportFlags();

}  // namespace candela::app
