// `candela info`'s flags.

#include "info_cli.h"

#include "flag_groups.h"

namespace candela::app {

std::vector<FlagSpec<InfoOptions>> infoFlags() { return bindTo<InfoOptions>(&InfoOptions::common, deviceFlags(false)); }

}  // namespace candela::app
