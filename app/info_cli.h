#pragma once
// `candela info`'s options and flags: the device flags only.

#include "common_options.h"
#include "flag_spec.h"

#include <vector>

namespace candela::app {

struct InfoOptions {
    CommonOptions common;
    bool operator==(const InfoOptions&) const = default;
};

// Every flag info takes.
std::vector<FlagSpec<InfoOptions>> infoFlags();

}  // namespace candela::app
