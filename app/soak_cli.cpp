// `candela soak`'s flags.

#include "soak_cli.h"

#include "flag_groups.h"

namespace candela::app {

std::vector<FlagSpec<SoakOptions>> soakFlags() {
    using O = SoakOptions;
    std::vector<FlagSpec<O>> flags = {
        {"--out", "FILE", "also write the samples as CSV", "", parsed(&O::out, parsePath)},
        {"--frames", "N", "frames to render", "10000", parsed(&O::frames, parseCount)},
        {"--switch-every", "K", "frames per environment (4 procedural skies, cycled; each switch reruns the IBL precompute)", "100",
         parsed(&O::switchEvery, parseCount)},
        {"--sample-every", "K", "frames between memory samples", "100", parsed(&O::sampleEvery, parseCount)},
    };
    append(flags, sizeFlags(&O::width, &O::height, "frame {}", 320, 180));
    append(flags, bindTo<O>(&O::common, deviceFlags(true)));
    append(flags, bindTo<O>(&O::common, std::vector{quietFlag()}));
    return flags;
}

}  // namespace candela::app
