#pragma once
// WebP images (EXT_texture_webp) decoded to RGBA8 through Debian's libwebp: lossy, lossless, with
// or without alpha; an animated WebP gives its first frame (composited as libwebpdemux's animation
// decoder does), with a note. Errors are candela::UserError with one line starting "WebP: ".

#include "textures/decoded_texture.h"

#include <cstdint>
#include <span>
#include <utility>

namespace candela::textures {

// True when `bytes` starts with a RIFF header whose form type is "WEBP".
bool isWebp(std::span<const uint8_t> bytes);

// The size the bitstream declares (no pixel decoded); fails for a header libwebp cannot read or a
// side above `maxDimension`. Returns (width, height). Throws UserError("WebP: …").
std::pair<uint32_t, uint32_t> webpSize(std::span<const uint8_t> bytes, uint32_t maxDimension);

// webpSize, then the pixels: one level (WebP has no mips). Throws UserError("WebP: …").
DecodedTexture decodeWebp(std::span<const uint8_t> bytes, uint32_t maxDimension);

}  // namespace candela::textures
