#pragma once
// The mip chain of a tangent-space normal map for specular anti-aliasing (Toksvig's idea): what a
// mip averages away is kept, so that the shader can widen the roughness by it. See docs/shading.md.

#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace candela::geometry {

// Mips 0 … ⌊log2 max(width, height)⌋ of `image` (RGBA8, a normal map: RGB = n · 0.5 + 0.5), sizes
// halved as Vulkan's (⌊size / 2⌋, at least 1). Mip 0 keeps the image's RGB; each further mip
// holds, per texel, the mean of the unit normals of mip 0 it covers (2 × 2 box filters in turn,
// clamped at odd edges): RGB its direction, A its length (1 where they agree, less where they
// diverge — the lost length the shader turns into roughness). Mip 0's A is 1 (255). Rows are
// computed on every core (core/parallel_for.h); the result does not depend on how many. Precondition:
// image.rgba8 holds width × height × 4 bytes.
std::vector<std::vector<uint8_t>> normalMapMipChain(const scene::Image& image);

}  // namespace candela::geometry
