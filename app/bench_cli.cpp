// `candela bench`'s flags: what it measures and prints, then what it shares with render and view.

#include "bench_cli.h"

#include "flag_groups.h"

namespace candela::app {

std::vector<FlagSpec<BenchOptions>> benchFlags() {
    using O = BenchOptions;
    std::vector<FlagSpec<O>> flags = {
        {"--frames", "N", "frames measured after warm-up", "20", parsed(&O::frames, parseCount)},
        {"--explain", "",
         "print the camera used (as the flags that reproduce it) and which passes and shader variants the "
         "measured frames left out, and why (with --json: as \"explain\")",
         "", setsTo(&O::explain, true)},
        ditherFlag(&O::dither),
        outputsFlag(&O::outputs),
        {"--json", "", "machine-readable output", "", setsTo(&O::json, true)},
        {"--in-flight", "",
         "also run the frames as the viewer does, into an offscreen image with frames in "
         "flight: frame time and how far recording overlaps the GPU",
         "", setsTo(&O::inFlight, true)},
    };
    append(flags, bindTo<O>(frameSizeFlags(&O::width, &O::height)));
    append(flags, bindTo<O>(sceneRenderFlags(false)));
    return flags;
}

void checkBenchOptions(const BenchOptions& options) {
    checkSceneFlags(options, false, false);
    checkLightingFlags(options);
}

}  // namespace candela::app
