#pragma once
// Internal to loadEnvironment: the Radiance RGBE (.hdr, .pic) decoder, written by hand (stb_image
// reads RGBE too, but accepts fewer headers, reads no old-style RLE and reports failures without
// the detail our one-line errors give).
//
// Accepted: a first line "#?" + anything (#?RADIANCE, #?RGBE, ...); then any header lines up to a
// blank line — comments ('#', including repeated "#?RADIANCE" lines), GAMMA=, PRIMARIES=, VIEW=,
// SOFTWARE=, command lines — all ignored except FORMAT=32-bit_rle_rgbe (required; xyze and others
// are rejected) and EXPOSURE= (ignored with a warning, as other viewers ignore it); then the
// resolution line "±Y H ±X W" (-Y H +X W is the usual top-to-bottom, left-to-right; +Y and -X are
// flipped on load; the transposed "±X W ±Y H" forms are rejected). Scanlines may be new-style RLE
// (per-channel runs), flat, or old-style RLE (repeat markers (1,1,1,n)), each decided per scanline
// as Radiance does. Texels decode as m · 2^(e − 136) (e = 0 → black), as stb_image and three.js do.

#include "assets/environment.h"

#include <cstdint>
#include <span>
#include <string>

namespace candela::assets {

// True when `bytes` starts with the Radiance magic "#?".
bool looksLikeHdr(std::span<const uint8_t> bytes);

// Decodes a whole Radiance file held in `bytes`; `source` (the path) prefixes every error and
// warning. The result is not sanitized (RGBE cannot encode NaN, Inf or negatives anyway).
// Throws UserError "SOURCE: problem" for anything malformed; never reads outside `bytes`.
Environment decodeHdr(std::span<const uint8_t> bytes, const std::string& source, const EnvironmentLoadOptions& options);

}  // namespace candela::assets
