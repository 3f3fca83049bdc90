#pragma once
// The mip chain of a colour or data texture computed on the CPU, on every core: what linear blits
// make (each level the 2 × 2 box average of the one above, colour in linear light), for devices
// whose blits run in software (a CPU driver: lavapipe spends some 120 ms on a 2048² texture's
// chain, this some 15 ms on 2 cores). See docs/textures.md.

#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace candela::geometry {

// Mips 1 … ⌊log2 max(width, height)⌋ of `image` (RGBA8), sizes halved as Vulkan's (⌊size / 2⌋, at
// least 1), each from the one above as a linear blit makes it: each texel the bilinear sample of
// the level above at its centre (between two texels at weight ½ each way for an even size: the
// 2 × 2 box average; elsewhere for an odd one, clamped at the edges), RGB filtered in linear light
// when image.srgb (as a blit of an sRGB format does) and rounded to the nearest code (ties to even,
// so that the chain has no bias: lavapipe's blits are half a code high a level), A as it is.
// Precondition: image.rgba8 holds width × height × 4 bytes.
std::vector<std::vector<uint8_t>> boxMipChain(const scene::Image& image);

}  // namespace candela::geometry
