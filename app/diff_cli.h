#pragma once
// `candela diff A B`'s options and flags: two PNG or EXR files, or two folders of them.

#include "common_options.h"
#include "flag_spec.h"

#include <optional>
#include <string>
#include <vector>

namespace candela::app {

struct DiffOptions {
    CommonOptions common;              // (diff takes none of the common flags)
    std::string reference;             // A
    std::string test;                  // B
    std::optional<float> ppd;          // --ppd PPD (unset: from the monitor flags)
    float monitorDistance = 0.0f;      // --monitor-distance M
    float monitorWidth = 0.0f;         // --monitor-width M
    float monitorResolution = 0.0f;    // --monitor-resolution PX
    double threshold = 0.0;            // --threshold LEVELS
    std::optional<double> maxFlip;     // --max-flip X
    std::optional<double> maxFraction; // --max-fraction F
    std::string errorMaps;             // --error-maps DIR
    std::string report;                // --report FILE (JSON)
    std::string html;                  // --html FILE (a page of the comparison)
    bool inlineImages = false;         // --inline-images
    bool operator==(const DiffOptions&) const = default;
};

// Every flag diff takes.
std::vector<FlagSpec<DiffOptions>> diffFlags();
// A, then B; a UserError for a third argument.
void takeDiffArgument(DiffOptions& options, const std::string& argument);

}  // namespace candela::app
