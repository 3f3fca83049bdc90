#pragma once
// The magma colour map (van der Walt and Smith's, from matplotlib; the ꟻLIP papers show error maps
// in it): 256 colours from near black (no error) through purple and orange to pale yellow
// (largest error), perceptually uniform and readable in grey.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace candela::reports {

// The colour of `value` in [0, 1] (clamped; NaN reads as 0), as 8-bit sRGB: entry
// ⌊255·value + 0.5⌋ of the 256, as the ꟻLIP tool writes its error maps.
std::array<uint8_t, 3> magma(float value);

// An error map (values in [0, 1]) as an RGBA8 image for writePng, alpha 255.
std::vector<uint8_t> magmaImage(std::span<const float> values);

}  // namespace candela::reports
