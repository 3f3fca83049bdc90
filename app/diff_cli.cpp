// `candela diff`'s flags.

#include "diff_cli.h"

#include "flag_groups.h"

#include <charconv>

namespace candela::app {
namespace {

// A finite number > 0; `unit` names it in the error.
float positiveNumber(Str flag, Str v, const char* unit) {
    const float value = parseNumber(flag, v);
    if (!(value > 0.0f)) throw UserError(flag + ": expected " + unit + " > 0, got '" + v + "'");
    return value;
}

// A number from 0 to 1.
double unitFraction(Str flag, Str v) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), value);
    if (error != std::errc() || end != v.data() + v.size() || !(value >= 0.0 && value <= 1.0))
        throw UserError(flag + ": expected a number from 0 to 1, got '" + v + "'");
    return value;
}

// A setter of a positive number of `unit`.
Setter<DiffOptions> positive(float DiffOptions::*member, const char* unit) {
    return [member, unit](DiffOptions& o, Str flag, Str v) { o.*member = positiveNumber(flag, v, unit); };
}

}  // namespace

std::vector<FlagSpec<DiffOptions>> diffFlags() {
    using O = DiffOptions;
    return {
        {"--report", "FILE", "write the viewing parameters, every pair's numbers, status and error map, and the totals as JSON", "",
         parsed(&O::report, parsePath)},
        {"--html", "FILE",
         "write an HTML page of the comparison: a row per pair with reference, test and FLIP map, the "
         "numbers, failures first, sortable (self-contained: no network; images beside it)",
         "", parsed(&O::html, parsePath)},
        inlineImagesFlag(&O::inlineImages),
        {"--ppd", "PPD",
         "pixels per degree of visual angle the images are seen at; overrides the monitor flags [from "
         "them: about 67]",
         "", [](O& o, Str flag, Str v) { o.ppd = positiveNumber(flag, v, "pixels per degree"); }},
        {"--monitor-distance", "M", "distance from the viewer to the monitor in metres", "0.7", positive(&O::monitorDistance, "metres")},
        {"--monitor-width", "M", "width of the monitor's picture in metres", "0.7", positive(&O::monitorWidth, "metres")},
        {"--monitor-resolution", "PX", "the monitor's horizontal resolution in pixels", "3840",
         positive(&O::monitorResolution, "pixels")},
        {"--threshold", "LEVELS",
         "a pixel is over the threshold when one of its channels differs by more than LEVELS levels of "
         "255 (EXR: LEVELS/255 in linear units)",
         "5",
         [](O& o, Str flag, Str v) {
             o.threshold = parseNumber(flag, v);
             if (o.threshold < 0.0) throw UserError(flag + ": expected levels >= 0, got '" + v + "'");
         }},
        {"--max-flip", "X", "fail a pair whose mean FLIP is above X (0 to 1) [not checked]", "", parsed(&O::maxFlip, unitFraction)},
        {"--max-fraction", "F",
         "fail a pair whose fraction of pixels over --threshold is above F (0 to 1; Filament's renderdiff "
         "gate is --threshold 5 --max-fraction 0.001) [not checked]",
         "", parsed(&O::maxFraction, unitFraction)},
        {"--error-maps", "DIR",
         "write each compared pair's FLIP error map as a magma-coloured PNG under DIR, at the pair's relative "
         "path (an EXR pair's with .png added)",
         "", parsed(&O::errorMaps, parsePath)},
    };
}

void takeDiffArgument(DiffOptions& options, const std::string& argument) {
    if (!options.test.empty())
        throw UserError("unexpected argument '" + argument + "': diff compares two images or folders, A and B");
    (options.reference.empty() ? options.reference : options.test) = argument;
}

}  // namespace candela::app
