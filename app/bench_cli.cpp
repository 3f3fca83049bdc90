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
        {"--cold", "N",
         "time to image instead: N fresh `candela render` processes of the same scene and flags, each timed from its "
         "start to its image written, as ratios to the calibration pass run between them (the first finds the "
         "pipeline and IBL caches as they are, the others warm)",
         "", parsed(&O::cold, parseCount)},
    };
    append(flags, bindTo<O>(frameSizeFlags(&O::width, &O::height)));
    append(flags, bindTo<O>(sceneRenderFlags(false)));
    return flags;
}

void checkBenchOptions(const BenchOptions& options) {
    checkSceneFlags(options, false, false);
    checkLightingFlags(options);
}

std::vector<std::string> coldRenderArguments(const std::vector<std::string>& benchArguments) {
    // Bench's own flags, and whether each takes a value.
    const std::vector<std::pair<std::string, bool>> own = {
        {"--cold", true}, {"--frames", true}, {"--json", false}, {"--explain", false}, {"--in-flight", false}};
    std::vector<std::string> out;
    for (size_t i = 0; i < benchArguments.size(); ++i) {
        const std::string& word = benchArguments[i];
        const std::string name = word.substr(0, word.find('='));
        bool dropped = false;
        for (const auto& [flag, takesValue] : own)
            if (name == flag) {
                dropped = true;
                if (takesValue && name == word) ++i;  // "--flag VALUE": the value too
            }
        if (!dropped) out.push_back(word);
    }
    return out;
}

}  // namespace candela::app
