#pragma once
// `candela render`'s options and flags.

#include "flag_spec.h"
#include "options/pixel_output.h"
#include "scene_batch.h"
#include "scene_render_options.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace candela::app {

struct RenderOptions : SceneRenderOptions {
    // SCENE... — glTF files, folders and @lists (scene_batch.h), after --scene's file.
    std::vector<std::string> inputs;
    std::string out;          // --out FILE (.png, .exr, .pfm), a pattern with {name}, {path}, {variant}, {frame}
    std::string report;       // --report FILE (JSON: per scene times, sizes, warnings, outputs)
    std::string html;         // --html FILE (a page of the run)
    bool inlineImages = false;  // --inline-images (the page holds its images)
    Shard shard;              // --shard I/N
    bool resume = false;      // --resume: skip scenes whose outputs are all complete
    std::string graphDot;     // --graph-dot FILE
    std::string graphJson;    // --graph-json FILE
    bool explain = false;     // --explain
    bool dither = false;      // --dither
    // --outputs LIST: what each image gives per pixel (options/pixel_output.h); --outputs-format: how
    // the outputs besides colour are stored beside a .png or .pfm.
    options::PixelOutputs outputs{options::PixelOutput::Color};
    options::OutputFiles outputsFormat = options::OutputFiles::Npy;
    // An image sequence of --frames N frames at --fps F, written to the --out pattern (one %d, e.g.
    // frame_%04d.png); frame i shows --time + i / F, and with --turntable DEGREES the orbit camera
    // turns that far over the sequence.
    uint32_t frames = 0;
    double fps = 0.0;
    float turntableDegrees = 0.0f;
    // --views N: N images of one pose from directions spread evenly on a sphere (a Fibonacci
    // lattice) or, with --view-ring ELEVATION, on a ring that far above the horizon, all at one
    // framing distance; written as a sequence, with transforms.json.
    uint32_t views = 0;
    std::optional<float> viewRing;
    // --light-seed S: each frame's or view's environment turned further by a jitter drawn from S.
    std::optional<uint64_t> lightSeed;
    // The images of one scene's sequence or views (1 for a still).
    uint32_t frameCount() const { return views > 0 ? views : std::max(frames, 1u); }
    bool sequence() const { return frames > 1 || views > 0; }
    bool operator==(const RenderOptions&) const = default;
};

// Every flag render takes.
std::vector<FlagSpec<RenderOptions>> renderFlags();
// A SCENE argument: appended to the inputs.
void takeRenderArgument(RenderOptions& options, const std::string& argument);
// The checks that involve more than one flag; a UserError naming them.
void checkRenderOptions(const RenderOptions& options);

}  // namespace candela::app
