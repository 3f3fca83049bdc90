#pragma once
// When the forward pass's pipeline variants are compiled (--precompile), and the names of the
// choices, the one table the command line and the docs read. Names only: no Vulkan.

#include "core/name_table.h"

#include <cstdint>
#include <utility>

namespace candela::options {

enum class Precompile : uint8_t {
    Off,         // each variant at its first draw, on the thread recording the frame
    Frame,       // every variant the scene's materials need in the frame, on worker threads (and the
                 // recording thread) before its draws are recorded
    DebugViews,  // Frame, and every debug view's variants of those in the background, from the next
                 // frame of the same bits on (not slowing the one that compiles), so that switching
                 // the view does not wait for a compiler (the viewer)
};

inline constexpr std::pair<Precompile, const char*> kPrecompileNames[] = {
    {Precompile::Off, "off"}, {Precompile::Frame, "frame"}, {Precompile::DebugViews, "debug-views"}};

constexpr const char* precompileName(Precompile value) { return nameOf(kPrecompileNames, value); }

}  // namespace candela::options
