#pragma once
// `candela bench`'s options and flags.

#include "flag_spec.h"
#include "options/pixel_output.h"
#include "scene_render_options.h"

#include <string>
#include <vector>

namespace candela::app {

struct BenchOptions : SceneRenderOptions {
    uint32_t frames = 0;    // --frames N: frames measured
    bool explain = false;   // --explain
    bool dither = false;    // --dither
    bool json = false;      // --json
    bool inFlight = false;  // --in-flight (also frames as the viewer runs them, offscreen)
    uint32_t cold = 0;      // --cold N: N fresh render processes instead (bench_cold.h)
    // --outputs LIST: the per-pixel outputs each measured frame makes (the aov pass's cost).
    options::PixelOutputs outputs{options::PixelOutput::Color};
    bool operator==(const BenchOptions&) const = default;
};

// Every flag bench takes.
std::vector<FlagSpec<BenchOptions>> benchFlags();
// The checks that involve more than one flag; a UserError naming them.
void checkBenchOptions(const BenchOptions& options);
// The arguments of `candela render` that bench's `arguments` (its command line after "bench")
// stand for, for --cold: bench's own flags dropped (--cold, --frames, --json, --explain,
// --in-flight, with their values), the rest kept in order. Pure.
std::vector<std::string> coldRenderArguments(const std::vector<std::string>& benchArguments);

}  // namespace candela::app
