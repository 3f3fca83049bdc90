#pragma once
// `candela bench --cold N`: the time to image of a single render. N fresh `candela render`
// processes of the scene and flags bench was given, each timed from its start to its exit (its
// image written), against the calibration pass run in this process between them. The first finds
// the caches (pipelines, the environment's maps) as they are; the others find them warm.

#include "bench_cli.h"

namespace candela::app {

// Runs the cold measurement of the bench command line `arguments` (after "bench") and prints it (as
// JSON with --json). Returns the exit code. Precondition: options.cold > 0.
int runColdBench(const BenchOptions& options, const std::vector<std::string>& arguments);

}  // namespace candela::app
