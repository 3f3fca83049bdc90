#pragma once
// `candela soak`'s options and flags.

#include "common_options.h"
#include "flag_spec.h"

#include <string>
#include <vector>

namespace candela::app {

struct SoakOptions {
    CommonOptions common;
    uint32_t frames = 0;       // --frames N
    uint32_t switchEvery = 0;  // --switch-every K: frames per environment
    uint32_t sampleEvery = 0;  // --sample-every K
    uint32_t width = 0;        // --width, --height
    uint32_t height = 0;
    std::string out;           // --out FILE.csv (optional)
    bool operator==(const SoakOptions&) const = default;
};

// Every flag soak takes.
std::vector<FlagSpec<SoakOptions>> soakFlags();

}  // namespace candela::app
