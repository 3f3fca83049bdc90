#pragma once
// The mip chain of a colour or data texture computed on the CPU, on every core: what linear blits
// make (each level the 2 × 2 box average of the one above, colour in linear light), for devices
// whose blits run in software (a CPU driver: lavapipe spends some 120 ms on a 2048² texture's
// chain, this some 15 ms on 2 cores). See docs/textures.md.

#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace candela::geometry {

// One level of an RGBA8 image in memory the caller owns: `height` rows of `width` texels (4 bytes
// each), row y starting at data + y × rowPitch (rowPitch ≥ width × 4). The chains below write their
// levels into such views (a linearly tiled texture's mapped memory, or vectors) and read each level
// back from there to make the next.
struct TexelLevel {
    uint8_t* data = nullptr;
    size_t rowPitch = 0;
    uint32_t width = 0, height = 0;
    uint8_t* row(uint32_t y) const { return data + size_t(y) * rowPitch; }
};

// The mip levels of a width × height image, as Vulkan sizes them: ⌊log2 max(width, height)⌋ + 1
// (1 for an empty image, which no loader makes).
uint32_t mipLevelCount(uint32_t width, uint32_t height);

// The sizes of levels [first, mipLevelCount) of a width × height image, tightly packed, backed by
// the vectors in `storage` (resized here): the views the chains write for a caller without memory of
// its own.
std::vector<TexelLevel> packedLevels(uint32_t width, uint32_t height, uint32_t first, std::vector<std::vector<uint8_t>>& storage);

// Throws std::invalid_argument naming `what` unless `levels` are views of exactly levels [first,
// mipLevelCount) of a width × height image, each of its level's size.
void checkMipLevels(uint32_t width, uint32_t height, uint32_t first, std::span<const TexelLevel> levels, const char* what);

// Writes mips 1 … mipLevelCount − 1 of `image` (RGBA8) into mips[0 …] (mips[i] is level i + 1),
// each from the one above as a linear blit makes it: each texel the bilinear sample of the level
// above at its centre (between two texels at weight ½ each way for an even size: the 2 × 2 box
// average; elsewhere for an odd one, clamped at the edges), RGB filtered in linear light when
// image.srgb (as a blit of an sRGB format does) and rounded to the nearest code (ties to even, so
// that the chain has no bias: lavapipe's blits are half a code high a level), A as it is. Rows are
// computed on every core (core/parallel_for.h). Preconditions: image.rgba8 holds width × height × 4
// bytes; mips holds mipLevelCount − 1 views of the levels' sizes (else std::invalid_argument).
void writeBoxMipChain(const scene::Image& image, std::span<const TexelLevel> mips);

// The same chain in vectors of tightly packed texels (mips 1 …).
std::vector<std::vector<uint8_t>> boxMipChain(const scene::Image& image);

}  // namespace candela::geometry
