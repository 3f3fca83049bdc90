// `candela ibl-report`'s flags.

#include "ibl_report_cli.h"

#include "flag_groups.h"

namespace candela::app {

std::vector<FlagSpec<IblReportOptions>> iblReportFlags() {
    using O = IblReportOptions;
    std::vector<FlagSpec<O>> flags = {
        {"--out", "DIR", "where report.csv, report.md and the plots go (created)", "ibl-report", parsed(&O::out, parsePath)},
    };
    append(flags, sizeFlags(&O::width, &O::height, "{} of the end-to-end images", 320, 180));
    append(flags, {
        {"--repeats", "N",
         "rounds of precompute runs over every setting, a calibration run before each; the median time and "
         "its quartiles are reported, over the median calibration",
         "3", parsed(&O::repeats, parseCount)},
        {"--quick", "", "a reduced sweep (smoke tests)", "", setsTo(&O::quick, true)},
        {"--reference-samples", "N", "samples per pixel of the ground-truth render (at least 16)", "4096",
         [](O& o, const std::string& flag, const std::string& v) {
             o.referenceSamples = parseDimension(flag, v);
             if (o.referenceSamples < 16) throw UserError(flag + ": need at least 16");
         }},
        requiredEnvFlag(&O::env, "the environment measured: an .hdr/.exr file or sky", "ibl-report"),
    });
    append(flags, bindTo<O>(&O::common, deviceFlags(true)));
    append(flags, bindTo<O>(&O::common, std::vector{verboseFlag(false), quietFlag()}));
    return flags;
}

}  // namespace candela::app
