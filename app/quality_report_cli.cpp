// `candela quality-report`'s flags.

#include "quality_report_cli.h"

#include "flag_groups.h"

#include <algorithm>

namespace candela::app {

std::vector<FlagSpec<QualityReportOptions>> qualityReportFlags() {
    using O = QualityReportOptions;
    std::vector<FlagSpec<O>> flags = {
        {"--out", "DIR", "where report.csv, report.md and the plots go (created)", "quality-report", parsed(&O::out, parsePath)},
        {"--frames", "N", "timed frames per setting", "5", parsed(&O::frames, parseCount)},
    };
    append(flags, sizeFlags(&O::width, &O::height, "frame {} (the reference renders 4x as many pixels a side)", 640, 360));
    append(flags, {
        {"--msaa", "N,N,...", "sample counts, each {choices} (those the device lacks are clamped, noted)", "1,2,4,8",
         [](O& o, Str flag, Str v) {
             o.msaa.clear();
             for (const std::string& item : commaSeparated(v)) o.msaa.push_back(parseChoice(flag, kSampleCounts, item));
         },
         namesOf(kSampleCounts)},
        {"--repeats", "N",
         "rounds of --frames timed frames over every setting; the median ratio and its quartiles are "
         "reported",
         "5", parsed(&O::repeats, parseCount)},
        requiredEnvFlag(&O::env, "the glTF scenes' environment: an .hdr/.exr file or sky (the grid: the sky)", "quality-report"),
        {"--scenes", "A,B,...", "default (the built-in grid under the sky) and/or glTF files", "default",
         [](O& o, Str flag, Str v) {
             o.scenes = commaSeparated(v);
             if (std::find(o.scenes.begin(), o.scenes.end(), "") != o.scenes.end())
                 throw UserError(flag + ": expected default or glTF files, comma-separated, got '" + v + "'");
         }},
        {"--lod-errors", "PX,PX,...", "level-of-detail errors in pixels", "0,0.5,1,2,4",
         [](O& o, Str flag, Str v) {
             o.lodErrors.clear();
             for (const std::string& item : commaSeparated(v)) {
                 const float pixels = parseNumber(flag, item);
                 if (!(pixels >= 0.0f)) throw UserError(flag + ": expected pixels ≥ 0, got '" + v + "'");
                 o.lodErrors.push_back(pixels);
             }
         }},
        {"--orbit-frames", "N", "frames of the 1-degree-per-frame orbit (error and temporal difference)", "6",
         parsed(&O::orbitFrames, parseCount)},
    });
    append(flags, bindTo<O>(&O::common, deviceFlags(true)));
    append(flags, bindTo<O>(&O::common, std::vector{verboseFlag(false), quietFlag()}));
    return flags;
}

}  // namespace candela::app
