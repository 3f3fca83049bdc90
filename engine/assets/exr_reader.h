#pragma once
// Internal to loadEnvironment: OpenEXR equirectangular maps through the reference implementation
// (Debian's libopenexr-dev 3.1). Its C library, OpenEXRCore, parses and strictly validates the
// headers first: every attribute against its type and the file's size, the data window against our
// limits (per call, no global state), before any table or pixel buffer is sized from them. Its C++
// library then decodes the pixels (OpenEXRCore 3.1 has no DWAA/DWAB decoder, the C++ library has
// every one), on its thread pool, after checking that it read the same windows.
//
// Accepted: scanline and tiled parts (the full-resolution level of a mipmapped or ripmapped file),
// every compression OpenEXR has (none, RLE, ZIPS, ZIP, PIZ, PXR24, B44, B44A, DWAA, DWAB), HALF
// and FLOAT channels: R, G, B (an A channel and any others are ignored) or a single Y channel
// (grey). The picture is the display window: data outside it is cropped, display pixels without
// data are black (the format's convention), with a note. Multi-part files: the first non-deep part
// with R, G, B (or Y) is used, with a note naming it. Refused with a one-line error: deep images,
// UINT or sub-sampled colour channels, luminance/chroma files (Y with RY, BY), files without R, G,
// B or Y, and display or data windows beyond the load options' limits.

#include "assets/environment.h"

#include <cstdint>
#include <span>
#include <string>

namespace candela::assets {

// True when `bytes` starts with the OpenEXR magic number 76 2f 31 01.
bool looksLikeExr(std::span<const uint8_t> bytes);

// Decodes a whole OpenEXR file held in `bytes`; `source` (the path) prefixes every error and
// note. The result is not sanitized (half and float channels may hold NaN, Inf and negatives).
// Throws UserError "SOURCE: problem" for anything malformed or unsupported.
Environment decodeExr(std::span<const uint8_t> bytes, const std::string& source, const EnvironmentLoadOptions& options);

}  // namespace candela::assets
