#pragma once
// Encoding RGBA8 pixels as a PNG file's bytes, chosen by measurement (docs/outputs.md#png-encoding):
// every row with the Paeth filter, deflated by zlib with its run-length strategy (Z_RLE), both on
// every core (pieces of rows deflated apart and joined into one zlib stream). On rendered images
// that is 8× faster than stb_image_write's per-row filter search with its own deflate on one core,
// and its files are a quarter smaller.

#include <cstdint>
#include <span>
#include <vector>

namespace candela::assets {

// The PNG file (8-bit RGBA, non-interlaced) of the `width` × `height` pixels `rgba`, rows top first;
// the same bytes whatever the machine's core count (for the same zlib).
// Preconditions: width, height ≥ 1; rgba.size() == width × height × 4.
std::vector<uint8_t> encodePng(uint32_t width, uint32_t height, std::span<const uint8_t> rgba);

}  // namespace candela::assets
