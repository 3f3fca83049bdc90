// `candela render`'s flags: its outputs and image sequences, then what it shares with view and bench.

#include "render_cli.h"

#include "cli_values.h"
#include "flag_groups.h"

namespace candela::app {

std::vector<FlagSpec<RenderOptions>> renderFlags() {
    using O = RenderOptions;
    std::vector<FlagSpec<O>> flags = {
        {"--out", "FILE",
         "the output image: .png (8-bit sRGB), .exr (linear half float) or .pfm (linear float); a pattern "
         "with {name}, {path}, {variant} and {frame} names each scene's images (folders are created); with "
         "--frames N and no {frame}, one %d or %04d holds the frame number",
         "candela.png", parsed(&O::out, parsePath)},
        {"--frames", "N", "an image sequence of N frames (--out then holds a %04d-style frame number)", "1",
         parsed(&O::frames, parseCount)},
        {"--fps", "F", "frames per second of an image sequence; frame i shows --time + i/F", "30",
         [](O& o, Str flag, Str v) {
             o.fps = parseSeconds(flag, v);
             if (!(o.fps > 0.0)) throw UserError(flag + ": expected frames per second > 0, got '" + v + "'");
         }},
        {"--turntable", "DEGREES",
         "turn the orbit camera by DEGREES over an image sequence (360: once round), framed at one "
         "distance",
         "0", parsed(&O::turntableDegrees, parseNumber)},
        {"--views", "N",
         "N images of one pose from directions spread evenly on a sphere (Fibonacci), all at one framing "
         "distance, written as a sequence (--out holds a %04d-style number) with their cameras in "
         "transforms.json beside them",
         "", parsed(&O::views, parseCount)},
        {"--view-ring", "ELEVATION",
         "put --views on a ring ELEVATION degrees above the horizon instead of a sphere", "",
         [](O& o, Str flag, Str v) { o.viewRing = parseNumber(flag, v); }},
        {"--light-seed", "S",
         "jittered lighting: turn the environment of each frame or view by a further angle drawn from the "
         "number S (the same images for the same S)",
         "", [](O& o, Str flag, Str v) {
             if (v.empty() || v.size() > 19 || v.find_first_not_of("0123456789") != std::string::npos)
                 throw UserError(flag + ": expected a whole number, got '" + v + "'");
             o.lightSeed = std::stoull(v);
         }},
        {"--report", "FILE",
         "write a JSON report of the run: per scene the load, upload and frame times, triangles, draws, "
         "textures and their bytes, extensions, warnings and the files written",
         "", parsed(&O::report, parsePath)},
        {"--html", "FILE",
         "write an HTML page of the run: a row per scene with its images, times, sizes, warnings and "
         "failure, sortable (self-contained: no network; images beside it)",
         "", parsed(&O::html, parsePath)},
        inlineImagesFlag(&O::inlineImages),
        {"--shard", "I/N|auto[/N]",
         "render only share I of N of the scenes (every N-th, from the I-th): one machine's part of a "
         "library spread over N machines; auto reads I and N from a Slurm array, a Kubernetes indexed "
         "job (give N) or GitLab's parallel jobs",
         "", parsed(&O::shard, [](Str flag, Str value) { return parseShard(flag, value); })},
        {"--resume", "",
         "skip the scenes whose output files are all there and complete (a killed or preempted run "
         "goes on where it stopped; what it left half-written is removed)",
         "", setsTo(&O::resume, true)},
        {"--graph-dot", "FILE", "write the compiled render graph as Graphviz dot", "", parsed(&O::graphDot, parsePath)},
        {"--graph-json", "FILE", "write the compiled render graph as JSON (passes, resources, barriers, timings)", "",
         parsed(&O::graphJson, parsePath)},
        {"--explain", "",
         "print the camera used (as the flags that reproduce it) and which passes and shader variants were "
         "left out, and why",
         "", setsTo(&O::explain, true)},
        ditherFlag(&O::dither),
        outputsFlag(&O::outputs),
        {"--outputs-format", "npy|exr|png",
         "how --outputs besides colour are stored beside a .png or .pfm --out: a NumPy array, an EXR "
         "file (32-bit float or uint channels) or a PNG picture to look at, each FILE-STEM.OUTPUT.EXT",
         "npy", parsed(&O::outputsFormat, [](Str flag, Str v) { return parseChoice(flag, options::kOutputFilesNames, v); })},
    };
    append(flags, bindTo<O>(frameSizeFlags(&O::width, &O::height)));
    append(flags, bindTo<O>(sceneRenderFlags(false)));
    append(flags, bindTo<O>(&O::common, std::vector{quietFlag()}));
    return flags;
}

void takeRenderArgument(RenderOptions& options, const std::string& argument) { options.inputs.push_back(argument); }

void checkRenderOptions(const RenderOptions& options) {
    checkSceneFlags(options, !options.inputs.empty(), true);
    checkLightingFlags(options);
    if (options.views > 0 && (options.frames > 1 || options.turntableDegrees != 0.0f))
        throw UserError("--views: views are of one pose; not with --frames or --turntable");
    if (options.viewRing && options.views == 0) throw UserError("--view-ring: puts --views on a ring; give --views N");
    if (options.lightSeed && !options.sequence()) throw UserError("--light-seed: jitters the lighting of --views or --frames; give one");
}

}  // namespace candela::app
