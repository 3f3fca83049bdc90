// `candela scale-report`'s flags.

#include "scale_report_cli.h"

#include "flag_groups.h"
#include "options/draw_selection.h"

namespace candela::app {

std::vector<FlagSpec<ScaleReportOptions>> scaleReportFlags() {
    using O = ScaleReportOptions;
    std::vector<FlagSpec<O>> flags = {
        {"--out", "DIR", "where report.csv, report.md and frame_vs_triangles.png go (created)", "scale-report",
         parsed(&O::out, parsePath)},
        {"--frames", "N", "frames measured per setting", "5", parsed(&O::frames, parseCount)},
    };
    append(flags, frameSizeFlags(&O::width, &O::height));
    append(flags, {
        {"--lod-error", "PIXELS", "the level-of-detail error of the \"on\" runs", valueText(options::DrawSelection{}.lodErrorPixels),
         [](O& o, Str flag, Str v) { o.lodErrorPixels = parsePixels(flag, v, false); }},
        {"--sizes", "N,N,...", "grid sides", "1,2,5,10,20,50,100",
         [](O& o, Str flag, Str v) {
             o.sizes.clear();
             for (const std::string& item : commaSeparated(v)) {
                 const uint32_t side = parseDimension(flag, item);
                 if (side == 0 || side > 1000) throw UserError(flag + ": expected grid sides from 1 to 1000, got '" + v + "'");
                 o.sizes.push_back(side);
             }
         }},
    });
    append(flags, bindTo<O>(&O::common, deviceFlags(true)));
    append(flags, bindTo<O>(&O::common, std::vector{quietFlag()}));
    return flags;
}

}  // namespace candela::app
