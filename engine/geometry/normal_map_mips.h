#pragma once
// The mip chain of a tangent-space normal map for specular anti-aliasing (Toksvig's idea): what a
// mip averages away is kept, so that the shader can widen the roughness by it. See docs/shading.md.

#include "geometry/image_mips.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace candela::geometry {

// Writes mips 0 … mipLevelCount − 1 of `image` (RGBA8, a normal map: RGB = n · 0.5 + 0.5) into
// levels[0 …]. Mip 0 keeps the image's RGB; each further mip holds, per texel, the mean of the unit
// normals of mip 0 it covers (2 × 2 box filters in turn, clamped at odd edges): RGB its direction,
// A its length (1 where they agree, less where they diverge — the lost length the shader turns into
// roughness). Mip 0's A is 1 (255). Rows are computed on every core (core/parallel_for.h); the
// result does not depend on how many. Preconditions: image.rgba8 holds width × height × 4 bytes;
// levels holds mipLevelCount views of the levels' sizes (else std::invalid_argument).
void writeNormalMapMipChain(const scene::Image& image, std::span<const TexelLevel> levels);

// The same chain in vectors of tightly packed texels (mips 0 …).
std::vector<std::vector<uint8_t>> normalMapMipChain(const scene::Image& image);

}  // namespace candela::geometry
