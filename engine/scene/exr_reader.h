#pragma once
// Internal to loadEnvironment: OpenEXR equirectangular maps through tinyexr's EXRHeader API.
//
// Accepted: single-part scanline images with R, G, B channels (an A channel and any others are
// ignored) or a single Y channel (grey), each HALF or FLOAT, any compression tinyexr reads (none,
// RLE, ZIPS, ZIP, PIZ). Rejected with a clear message: multi-part, deep and tiled files, UINT or
// sub-sampled channels, files without R, G, B (or Y). The data window's top row (min y) becomes row
// 0; its size is checked against the load options before tinyexr allocates any pixels.

#include "scene/environment.h"

#include <cstdint>
#include <span>
#include <string>

namespace candela::scene {

// True when `bytes` starts with the OpenEXR magic number 76 2f 31 01.
bool looksLikeExr(std::span<const uint8_t> bytes);

// Decodes a whole OpenEXR file held in `bytes`; `source` (the path) prefixes every error. The
// result is not sanitized (half and float channels may hold NaN, Inf and negatives). Throws
// UserError "SOURCE: problem" for anything malformed or unsupported.
Environment decodeExr(std::span<const uint8_t> bytes, const std::string& source, const EnvironmentLoadOptions& options);

}  // namespace candela::scene
